"""A control loop in Python: a PID controller, one call to Simulator.step per millisecond,
holds chrono's actuated double pendulum at a target pose against gravity.

    PYTHONPATH=build/release/python python3 examples/python/control_loop.py
"""
import sys

import numpy as np

import sinew
from models import ACTUATED_DOUBLE_PENDULUM

model = sinew.load(ACTUATED_DOUBLE_PENDULUM)
print(model, "actuators:", model.actuators)  # CoordinateActuators on q1 and q2, 1 N m each
h = 1e-3
simulator = model.simulator(h, integrator="euler")
n = len(model.coordinates)
target = np.array([0.6, -0.4])  # rad
kp, ki, kd = 400.0, 800.0, 40.0  # N m/rad, N m/(rad s), N m s/rad
integral = np.zeros(n)
observation = simulator.reset()
for _ in range(int(4.0 / h)):
    q, u = observation[:n], observation[n:]
    error = target - q
    integral += error * h
    observation = simulator.step(kp * error + ki * integral - kd * u)
final_error = np.max(np.abs(simulator.q - target))
print(f"t = {simulator.t:.3f} s: q = {simulator.q} rad, |q - target| = {final_error:.2e} rad")
if final_error > 1e-4:
    sys.exit("FAIL: the controller did not reach the target pose")
