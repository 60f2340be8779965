"""Simulate OpenSim's 3-D double pendulum from its initial states for 3 s, compare with the
states OpenSim stored for the same run, write states.sto, and plot the angles when matplotlib
is installed.

    PYTHONPATH=build/release/python python3 examples/python/simulate_and_plot.py [OUT_DIR]
"""
import pathlib
import sys

import numpy as np

import sinew
from models import DOUBLE_PENDULUM_3D, OPENSIM_RESOURCES

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python")
out.mkdir(parents=True, exist_ok=True)
model = sinew.load(DOUBLE_PENDULUM_3D)
print(model, "coordinates:", model.coordinates)
result = model.simulate(3.0, accuracy=1e-10,
                        initial_states=OPENSIM_RESOURCES / "DoublePendulum3D_InitialStates.sto")
print(f"{len(result)} states, {result.statistics['steps']} steps; "
      f"q(3 s) = {result.q[-1]} rad")
result.to_sto(out / "double_pendulum_states.sto")

# OpenSim's stored run of the same model: its rows are at the same report times.
lines = (OPENSIM_RESOURCES / "DoublePendulum3D_states.sto").read_text().splitlines()
start = lines.index("endheader") + 1
labels = lines[start].split("\t")
rows = np.array([[float(x) for x in line.split()] for line in lines[start + 1:] if line.strip()])
rows_at = np.rint(rows[:, 0] / 0.01).astype(int)
worst = max(np.max(np.abs(result.q[rows_at, c] - rows[:, labels.index(name)]))
            for c, name in enumerate(result.coordinates))
print(f"largest difference from OpenSim's stored states: {worst:.2e} rad")
if worst > 3e-7:  # docs/engine.md: 1.05e-7 rad measured
    sys.exit("FAIL: the run differs from OpenSim's by more than 3e-7 rad")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot")
else:
    figure, axes = plt.subplots()
    for c, name in enumerate(result.coordinates):
        axes.plot(result.time, result.q[:, c], label=f"{name} (Sinew)")
        axes.plot(rows[:, 0], rows[:, labels.index(name)], "k:", label=f"{name} (OpenSim)")
    axes.set_xlabel("time (s)")
    axes.set_ylabel("angle (rad)")
    axes.legend()
    figure.savefig(out / "double_pendulum.png", dpi=100)
    print("wrote", out / "double_pendulum.png")
