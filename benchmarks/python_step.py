"""Benchmarks of the Python module: the overhead of one Simulator.step() call beyond the C++
step it runs, and Batch throughput on 1 and 2 threads (figures in docs/benchmarks.md).

    PYTHONPATH=build/release/python python3 benchmarks/python_step.py [--quick]

The C++ step time is measured with Simulator.step(controls, repeat=N), one Python call that
takes N steps; the overhead of a call is the time of one step() minus that per-step time. Times are the best of several
repeats (CPU time of this process, so other work on the machine counts less).
"""
import math
import pathlib
import sys
import time

import numpy as np

import sinew

QUICK = "--quick" in sys.argv
DATA = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data"
DOUBLE_PENDULUM = DATA / "opensim-org/opensim-core/Applications/Analyze/tests/resources/DoublePendulum3D.osim"
ACTUATED = DATA / "projectchrono/chrono/data/opensim/double_pendulum.osim"
SKELETON = DATA / "projectchrono/chrono/data/opensim/Rajagopal2015.osim"
H = 1e-3


def best_time(run, repeats):
    """The smallest process CPU time of `repeats` calls of run(), and the wall time of that one."""
    best = (math.inf, math.inf)
    for _ in range(repeats):
        cpu, wall = time.process_time(), time.perf_counter()
        run()
        best = min(best, (time.process_time() - cpu, time.perf_counter() - wall))
    return best


def tumbling_state(model):
    # As bench_engine_skeleton's Rajagopal2015 runs: every coordinate moving, speed sin(c + 1).
    state = model.default_state()
    state.u = np.sin(np.arange(len(model.coordinates)) + 1.0)
    return state


def step_overhead(model_file, steps):
    model = sinew.load(model_file)
    controls = np.full(len(model.actuators), 0.1) if model.actuators else None
    simulator = model.simulator(H)

    def one_call_per_step():
        simulator.reset()
        for _ in range(steps):
            simulator.step(controls)

    def one_call():
        simulator.reset()
        simulator.step(controls, repeat=steps)
    repeats = 3 if QUICK else 9
    return (best_time(one_call_per_step, repeats)[0] / steps,
            best_time(one_call, repeats)[0] / steps)


def throughput(model_file, n, steps, threads, state=None):
    model = sinew.load(model_file)
    batch = sinew.Batch(model, n, step=H, threads=threads)
    start = state(model) if state else model.default_state()
    controls = np.zeros((n, len(model.actuators))) if model.actuators else None

    def run():
        batch.reset(start)
        for _ in range(steps):
            batch.step(controls)
    _, wall = best_time(run, 2 if QUICK else 5)
    return n * steps / wall


print("Simulator.step() overhead (euler, h = 1 ms), CPU time per call:")
print("| model | step() per call | the C++ step (step(repeat=N) / N) | overhead per call |")
print("|---|---|---|---|")
for name, model_file in [("DoublePendulum3D, no controls", DOUBLE_PENDULUM),
                         ("chrono double_pendulum, 2 controls", ACTUATED)]:
    per_call, per_copy = step_overhead(model_file, 200 if QUICK else 2000)
    print(f"| {name} | {per_call * 1e6:.2f} us | {per_copy * 1e6:.2f} us | "
          f"{(per_call - per_copy) * 1e6:.2f} us |")

print("\nBatch throughput (euler, h = 1 ms), steps per second (wall time):")
print("| model | copies | 1 thread | 2 threads | speed-up |")
print("|---|---|---|---|---|")
for name, model_file, n, steps, state in [
        ("DoublePendulum3D", DOUBLE_PENDULUM, 256, 20 if QUICK else 400, None),
        ("Rajagopal2015 skeleton, tumbling", SKELETON, 16, 2 if QUICK else 25, tumbling_state)]:
    one, two = (throughput(model_file, n, steps, threads, state) for threads in (1, 2))
    print(f"| {name} | {n} | {one:,.0f} | {two:,.0f} | {two / one:.2f} |")
