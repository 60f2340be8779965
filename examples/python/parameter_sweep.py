"""A sweep of model parameters with sinew.sweep on a Dask cluster: SinglePin's rod with its mass
and the distance from the pin to its mass centre overridden per case (the file's rod is 0.75 kg,
0.5 m below the pin), released from rest at 1.5 rad; the period measured on each run against
the closed form.

    PYTHONPATH=build/release/python python3 examples/python/parameter_sweep.py [SCHEDULER_ADDRESS]

Each worker loads the model file and applies the case's "parameters" (as sinew.load's
`parameters`) before building it. Without an address it starts a LocalCluster of 2 worker
processes; with one it runs on that cluster (see docs/python.md).
"""
import itertools
import sys

import sinew
from dask_sweep import client_from_arguments
from models import SINGLE_PIN
from pendulum_period import exact_period, half_period_crossing

AMPLITUDE = 1.5  # rad
PIN_Y = 0.5  # the pin in the rod's body frame: (0, 0.5, 0)


def main():
    grid = list(itertools.product((0.5, 2.0), (0.1, 0.25, 0.4, 0.5)))  # (mass kg, distance m)
    cases = [{"duration": 0.55 * exact_period(AMPLITUDE, mass, distance),
              "coordinates": {"r1_z": AMPLITUDE}, "accuracy": 1e-10, "report_interval": 1e-3,
              "parameters": {"rod1/mass": mass, "rod1/mass_center": [0.0, PIN_Y - distance, 0.0]}}
             for mass, distance in grid]
    results = sinew.sweep(SINGLE_PIN, cases, client=client_from_arguments())
    worst = 0.0
    print(" mass (kg)  distance (m)  period (s)  exact (s)  relative error")
    for (mass, distance), result in zip(grid, results):
        period = half_period_crossing(result.time, result.u[:, 0])
        exact = exact_period(AMPLITUDE, mass, distance)
        worst = max(worst, abs(period - exact) / exact)
        print(f"{mass:10.2f} {distance:13.2f} {period:11.6f} {exact:10.6f} "
              f"{abs(period - exact) / exact:15.1e}")
    print(f"largest relative error of the period: {worst:.1e}")
    if not worst < 1e-8:  # as in batch_sweep.py: the crossing's interpolation error is ~h^3
        sys.exit("FAIL: a period differs from the closed form")


if __name__ == "__main__":  # Dask's worker processes import this file again: run only here
    main()
