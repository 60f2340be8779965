"""The period of OpenSim's SinglePin.osim pendulum released from rest at an angle, measured on a
simulated trajectory and in closed form, shared by the Batch and Dask sweep examples.

SinglePin: a 0.75 kg rod, inertia 0.025 kg m^2 about its mass centre, pinned 0.5 m from it,
g = 9.80665 m/s^2. Its exact period from amplitude a is T = 4 K(sin(a/2)) / w0 with
w0^2 = m g d / (I + m d^2) and K the complete elliptic integral of the first kind,
K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
"""
import math

import numpy as np

MASS, INERTIA, DISTANCE, GRAVITY = 0.75, 0.025, 0.5, 9.80665


def exact_period(amplitude, mass=MASS, distance=DISTANCE):
    """The period (s) of SinglePin released from rest at `amplitude` rad (< pi); `mass` (kg) and
    `distance` (m, from the pin to the mass centre) as overridden by parameter_sweep.py."""
    w0 = math.sqrt(mass * GRAVITY * distance / (INERTIA + mass * distance**2))
    a, b = 1.0, math.sqrt(1.0 - math.sin(amplitude / 2) ** 2)
    while abs(a - b) > 1e-15 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 4 * (math.pi / (2 * a)) / w0


def half_period_crossing(time, speed):
    """Twice the first time after the start at which `speed` changes sign (released from rest
    at a positive angle the speed goes negative, and turns positive after half a period); the
    crossing is interpolated linearly between samples. NaN when it never turns."""
    speed = np.asarray(speed)
    turns = np.nonzero((speed[:-1] < 0) & (speed[1:] >= 0))[0]
    if len(turns) == 0:
        return math.nan
    i = turns[0]
    t = time[i] + (time[i + 1] - time[i]) * (-speed[i]) / (speed[i + 1] - speed[i])
    return 2 * t
