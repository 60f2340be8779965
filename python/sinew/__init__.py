"""Sinew from Python: load OpenSim models (.osim), simulate them, step them in control loops and
in batches across threads, and sweep parameters on a Dask cluster.

    import sinew
    model = sinew.load("DoublePendulum3D.osim")
    result = model.simulate(3.0, accuracy=1e-8)
    result.q            # NumPy array, [times, coordinates]

See docs/python.md for the API, installation and Dask.
"""
from ._sinew import (Batch, Constant, Error, Function, Model, Ramp, Simulator, Sine, State,
                     forward, load, write_table)
from .result import Result
from .sweep import sweep

__all__ = ["Batch", "Constant", "Error", "Function", "Model", "Ramp", "Result", "Simulator",
           "Sine", "State", "forward", "load", "sweep", "write_table"]
