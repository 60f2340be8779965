"""sinew.load's external_loads, disabled_forces and rename_force_classes: what `sinew simulate
--external-loads`, `--disable-force` and `--rename-force-class` do, bit for bit, and what the
physics says."""
import numpy as np
import pytest

import sinew
from conftest import DATA, read_sto

FORWARD = DATA / "opensim-org/opensim-core/Applications/Forward/tests/resources"
SPRINGS = DATA / "sinew/springs.osim"
ANGLE = "/jointset/GroundJoint/Pendulum_r1/value"


def test_external_load_replaces_gravity_as_the_cli_applies_it(cli, tmp_path):
    loads = FORWARD / "pendulum_external_load.xml"
    run = dict(duration=1.0, report_interval=0.1, accuracy=1e-10)
    pushed = sinew.load(FORWARD / "pendulum_no_gravity.osim",
                        external_loads=[loads]).simulate(**run)
    states = cli([FORWARD / "pendulum_no_gravity.osim", "--duration", 1, "--report-interval",
                  0.1, "--accuracy", 1e-10, "--external-loads", loads], tmp_path / "cli")
    labels, time, values = read_sto(states)
    assert labels == pushed.labels
    np.testing.assert_array_equal(values, pushed.states)
    # The ExternalForce is the pendulum's weight: it swings as the pendulum under gravity.
    falling = sinew.load(FORWARD / "pendulum.osim").simulate(**run)
    column = pushed.labels.index(ANGLE)
    assert np.ptp(falling.states[:, column]) > 0.1  # it does swing
    np.testing.assert_allclose(pushed.states[:, column], falling.states[:, column], atol=1e-6)
    # Without the loads the weightless pendulum stays where it starts.
    still = sinew.load(FORWARD / "pendulum_no_gravity.osim").simulate(**run)
    assert np.ptp(still.states[:, column]) < 1e-12  # rounding alone


def test_disabled_force_is_left_out_and_an_unknown_name_is_an_error():
    block = "/jointset/block_slide/block_x/value"
    run = sinew.load(SPRINGS, disabled_forces=["block_spring"]).simulate(0.1)
    np.testing.assert_array_equal(run.states[:, run.labels.index(block)], 0.4)
    moving = sinew.load(SPRINGS).simulate(0.1)
    assert np.ptp(moving.states[:, moving.labels.index(block)]) > 0.0
    with pytest.raises(sinew.Error, match=r"block_sprng: cannot disable: no force has this name "
                                          r"\(close names: block_spring\)"):
        sinew.load(SPRINGS, disabled_forces=["block_sprng"])


def test_renamed_force_class_builds_the_other_muscle_model():
    arm26 = DATA / "opensim-org/opensim-models/Models/Arm26/arm26.osim"
    renamed = sinew.load(arm26, rename_force_classes={
        "Thelen2003Muscle": "Thelen2003Muscle_Deprecated"})
    types = {force["type"] for force in renamed.report["forces"] if force["actuator"]}
    assert types == {"Thelen2003Muscle_Deprecated"}
    assert {f["type"] for f in sinew.load(arm26).report["forces"]} == {"Thelen2003Muscle"}
    # The deprecated class is another model of the muscle: the run differs.
    a = renamed.simulate(0.05, equilibrate_muscles=True).states
    b = sinew.load(arm26).simulate(0.05, equilibrate_muscles=True).states
    assert np.abs(a - b).max() > 1e-6
