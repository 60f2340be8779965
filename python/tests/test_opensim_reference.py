"""Through Python, SinglePin and DoublePendulum3D reproduce OpenSim's stored forward runs (the
bounds of docs/engine.md, as BuildSystemTest asserts them: OpenSim's own integration error),
and a torque actuator under a ramp excitation follows its closed form."""
import numpy as np
import pytest

import sinew
from conftest import CHRONO, RESOURCES, read_sto


@pytest.mark.parametrize("name, q_bound, u_bound", [
    ("SinglePin", 1e-7, 3e-7),
    ("DoublePendulum3D", 3e-7, 2e-6),
])
def test_reproduces_opensim_states(name, q_bound, u_bound):
    model = sinew.load(RESOURCES / f"{name}.osim")
    result = model.simulate(3.0, accuracy=1e-10,
                            initial_states=RESOURCES / f"{name}_InitialStates.sto")
    labels, time, values = read_sto(RESOURCES / f"{name}_states.sto")
    assert len(result.time) == 301  # 0 to 3 s every 0.01 s
    dq = du = 0.0
    for row, t in enumerate(time):
        # OpenSim's rows are the report times 0, 0.01, ... (plus a final duplicate row).
        i = int(round(t / 0.01))
        assert abs(result.time[i] - t) < 1e-12
        for c, coordinate in enumerate(result.coordinates):
            dq = max(dq, abs(result.q[i, c] - values[row, labels.index(coordinate)]))
            du = max(du, abs(result.u[i, c] - values[row, labels.index(coordinate + "_u")]))
    print(f"{name}: max |dq| = {dq:.3g} rad, max |du| = {du:.3g} rad/s")
    assert dq < q_bound
    assert du < u_bound


def test_torque_actuator_follows_closed_form():
    # chrono's torque-actuator.osim: rod1 (1 kg, 1 kg m^2 about its mass centre, pinned 0.5 m
    # from it, no gravity) under -9.8 e(t) N m with e(t) = t: q1(t) = q0 - 9.8 t^3 / (6 1.25).
    # rk45 keeps each step's local error below accuracy (unit floor); q1'' depends on t alone,
    # so the global error stays below 2 accuracy per step (as examples/listing1 bounds it).
    model = sinew.load(CHRONO / "torque-actuator.osim")
    accuracy = 1e-9
    result = model.simulate(1.0, accuracy=accuracy, excitations={"grav": sinew.Ramp(0.0, 1.0)})
    q0 = result.q[0, 0]
    expected = q0 - 9.8 * result.time**3 / (6 * 1.25)
    bound = 2 * accuracy * result.statistics["steps"]
    assert np.max(np.abs(result.q[:, 0] - expected)) < bound
    assert result.q[-1, 0] < q0 - 1.0  # it did move: 9.8 / 7.5 rad by t = 1 s
