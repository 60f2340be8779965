"""Muscle-tendon equilibrium from Python: Model.simulate(equilibrate_muscles=True) starts from
what `sinew simulate --equilibrate-muscles` starts from (bit for bit), Model.equilibrate_muscles
gives the same fibers, and a muscle left unbalanced is a UserWarning naming it."""
import warnings

import numpy as np
import pytest

import sinew
from conftest import DATA, read_sto

ARM26 = DATA / "opensim-org/opensim-models/Models/Arm26/arm26.osim"

SLACK_MODEL = DATA / "sinew" / "slack_deprecated_muscle.osim"


def test_simulate_from_equilibrium_equals_cli_bit_for_bit(cli, tmp_path):
    states = cli([ARM26, "--duration", 0.05, "--accuracy", 1e-7, "--equilibrate-muscles"],
                 tmp_path / "cli")
    result = sinew.load(ARM26).simulate(0.05, accuracy=1e-7, equilibrate_muscles=True)
    labels, time, values = read_sto(states)
    assert labels == result.labels
    assert np.array_equal(time, result.time)
    assert np.array_equal(values, result.states)


def test_equilibrate_muscles_moves_only_the_fibers_and_simulate_starts_there():
    model = sinew.load(ARM26)
    default = model.default_state()
    balanced = model.equilibrate_muscles(default)
    fibers = [i for i, name in enumerate(model.state_variables) if name.endswith("/fiber_length")]
    others = [i for i in range(len(model.state_variables)) if i not in fibers]
    assert len(fibers) == 6
    # The file's default fiber lengths are the optimal ones; equilibrium moves every one.
    assert np.all(balanced.z[fibers] != default.z[fibers])
    assert np.array_equal(balanced.z[others], default.z[others])
    assert np.array_equal(balanced.q, default.q) and np.array_equal(balanced.u, default.u)
    # The given state is not changed; equilibrium of an equilibrium is itself.
    assert np.array_equal(default.z, model.default_state().z)
    assert np.array_equal(model.equilibrate_muscles(balanced).z, balanced.z)
    result = model.simulate(0.0, equilibrate_muscles=True)
    start = [result.labels.index(f"/forceset/{name.split('/')[0]}/fiber_length")
             for name in np.array(model.state_variables)[fibers]]
    assert np.array_equal(result.states[0, start], balanced.z[fibers])


def test_unbalanced_muscle_is_a_warning_naming_it():
    model = sinew.load(SLACK_MODEL)
    with pytest.warns(UserWarning, match="/forceset/musc: OpenSim's equilibrium iteration ended "
                                         "with the tendon at its slack length"):
        state = model.equilibrate_muscles(model.default_state())
    # The tendon at slack, the fiber across the rest of the path at the muscle's width.
    assert state.z[1] == pytest.approx(np.hypot(0.03, 0.12 * np.sin(0.2)), abs=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sinew.load(ARM26).simulate(0.0, equilibrate_muscles=True)  # arm26 balances: no warning
