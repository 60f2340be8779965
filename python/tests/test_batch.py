"""A Batch of 64 copies stepped on 2 threads gives the trajectories of 64 single Simulators bit
for bit (same integrator history per copy, one System shared read-only), with and without
actuators, and the same statistics; Simulator observations are [q, u]. (NSC statistics and
warnings: test_contact.py.)"""
import numpy as np

import sinew
from conftest import CHRONO, RESOURCES

STEPS = 200
H = 1e-3


def initial_states(model, n):
    # Copy i starts from the default pose turned by i / n rad about every coordinate.
    states = []
    for i in range(n):
        state = model.default_state()
        state.q = state.q + i / n
        state.u = state.u - 0.5 * i / n
        states.append(state)
    return states


def test_batch_equals_single_runs_without_actuators():
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    n = 64
    states = initial_states(model, n)
    batch = sinew.Batch(model, n, step=H, threads=2)
    assert batch.threads == 2
    batch.reset(states)
    for _ in range(STEPS):
        batch.step()
    q, u, t = batch.q, batch.u, batch.t
    assert q.shape == (n, 2) and t.shape == (n,)
    for i in range(n):
        simulator = model.simulator(H, initial_states=states[i])
        for _ in range(STEPS):
            observation = simulator.step()
        assert np.array_equal(observation, np.concatenate([q[i], u[i]]))
        assert simulator.t == t[i]
        assert {key: values[i] for key, values in batch.statistics.items()} == \
            simulator.statistics
    assert np.all(t == STEPS * H)
    assert np.ptp(q[:, 0]) > 0.5  # the copies did follow different trajectories


def test_batch_equals_single_runs_with_controls():
    model = sinew.load(CHRONO / "double_pendulum.osim")
    n, steps = 64, 50
    rng = np.random.default_rng(13)
    controls = rng.uniform(-1.0, 1.0, size=(steps, n, len(model.actuators)))
    batch = sinew.Batch(model, n, step=H, threads=2)
    for k in range(steps):
        batch.step(controls[k])
    for i in range(n):
        simulator = model.simulator(H)
        for k in range(steps):
            simulator.step(controls[k, i])
        assert np.array_equal(simulator.q, batch.q[i])
        assert np.array_equal(simulator.u, batch.u[i])
    # Different controls, different motions; a reset starts every copy again.
    assert np.ptp(batch.q[:, 0]) > 0
    batch.reset()
    assert np.array_equal(batch.q, np.tile(model.default_state().q, (n, 1)))
    assert np.all(batch.t == 0)


def test_one_thread_equals_two_threads():
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    states = initial_states(model, 8)
    results = []
    for threads in (1, 2):
        batch = sinew.Batch(model, 8, step=H, threads=threads)
        batch.reset(states)
        for _ in range(100):
            batch.step()
        results.append((batch.q, batch.u))
    assert np.array_equal(results[0][0], results[1][0])
    assert np.array_equal(results[0][1], results[1][1])


def test_step_repeat_equals_repeated_steps():
    model = sinew.load(CHRONO / "double_pendulum.osim")
    controls = np.array([0.3, -0.2])
    one_by_one, at_once = model.simulator(H), model.simulator(H)
    for _ in range(25):
        observation = one_by_one.step(controls)
    assert np.array_equal(at_once.step(controls, repeat=25), observation)
    assert at_once.t == one_by_one.t == 25 * H


def test_simulator_statistics_are_simulates_over_the_same_steps():
    # Simulator.statistics has Result.statistics' keys and meanings: a run of "euler" steps of
    # h = 1 ms over 0.2 s takes the steps simulate takes with report_interval = h (both end
    # step k at k h), so the counts are simulate's; reset() starts them again from zero.
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    expected = model.simulate(STEPS * H, integrator="euler", step=H,
                              report_interval=H).statistics
    assert expected["steps"] == STEPS
    simulator = model.simulator(H)
    for _ in range(STEPS):
        simulator.step()
    assert simulator.statistics == expected
    simulator.reset()
    assert simulator.statistics == {key: 0 for key in expected}
