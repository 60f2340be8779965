"""sinew.sweep on a LocalCluster of 2 worker processes returns, in case order, the Results that
the same cases give in this process (bit for bit: the workers load the model file themselves)."""
import numpy as np

import sinew
from conftest import CHRONO, RESOURCES
from sinew.sweep import run_case


def test_sweep_on_two_processes_equals_local_runs():
    cases = [{"duration": 0.2, "coordinates": {"r1_z": 0.1 * i}, "speeds": {"r2_x": -0.2 * i}}
             for i in range(4)]
    cases.append({"duration": 0.1, "integrator": "euler", "step": 1e-3})
    results = sinew.sweep(RESOURCES / "DoublePendulum3D.osim", cases)
    assert len(results) == len(cases)
    for case, result in zip(cases, results):
        local = run_case(str(RESOURCES / "DoublePendulum3D.osim"), case)
        assert np.array_equal(result.time, local.time)
        assert np.array_equal(result.q, local.q)
        assert np.array_equal(result.u, local.u)
    assert results[2].q[0, 0] == 0.2


def test_sweep_ships_excitations():
    cases = [{"duration": 0.2, "excitations": {"grav": sinew.Ramp(0.0, slope)}}
             for slope in (0.5, 1.0)]
    results = sinew.sweep(CHRONO / "torque-actuator.osim", cases)
    local = run_case(str(CHRONO / "torque-actuator.osim"), cases[1])
    assert np.array_equal(results[1].q, local.q)
    assert not np.array_equal(results[0].q, results[1].q)
