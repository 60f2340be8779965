"""The sweep of batch_sweep.py with sinew.sweep on a Dask cluster: each case is one
Model.simulate on a worker process, which loads the model file itself.

    PYTHONPATH=build/release/python python3 examples/python/dask_sweep.py [SCHEDULER_ADDRESS]

Without an address it starts a LocalCluster of 2 worker processes; with one (e.g.
tcp://10.0.0.5:8786, see docs/python.md) it runs on that cluster, whose workers must import
sinew and read the model at the same path.
"""
import sys

import numpy as np

import sinew
from models import SINGLE_PIN
from pendulum_period import exact_period, half_period_crossing


def client_from_arguments():
    """A Client of the scheduler whose address is the first command-line argument, or None (then
    sinew.sweep starts a LocalCluster of 2 worker processes)."""
    if len(sys.argv) < 2:
        return None
    from dask.distributed import Client
    return Client(sys.argv[1])


def main():
    amplitudes = np.linspace(0.1, 3.0, 8)  # rad
    cases = [{"duration": 0.55 * exact_period(a), "coordinates": {"r1_z": a}, "accuracy": 1e-10,
              "report_interval": 1e-3} for a in amplitudes]
    results = sinew.sweep(SINGLE_PIN, cases, client=client_from_arguments())
    worst = 0.0
    print(" amplitude (rad)  period (s)  exact (s)  relative error")
    for amplitude, result in zip(amplitudes, results):
        period, exact = half_period_crossing(result.time, result.u[:, 0]), exact_period(amplitude)
        worst = max(worst, abs(period - exact) / exact)
        print(f"{amplitude:16.3f} {period:11.6f} {exact:10.6f} {abs(period - exact) / exact:15.1e}")
    print(f"largest relative error of the period: {worst:.1e}")
    if not worst < 1e-8:  # as in batch_sweep.py
        sys.exit("FAIL: a period differs from the closed form")


if __name__ == "__main__":  # Dask's worker processes import this file again: run only here
    main()
