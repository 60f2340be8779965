"""sweep: many simulations of one model file on a Dask cluster (dask.distributed)."""
from __future__ import annotations

import os
from typing import Any, Dict, List, Mapping, Optional, Sequence

# What a case may hold besides the keyword arguments of Model.simulate.
_CASE_KEYS = ("coordinates", "speeds", "parameters")


def run_case(model_path: str, case: Mapping[str, Any]) -> Any:
    """Runs one case in this process: loads `model_path` and simulates it.

    A case is a dict: `duration` (s, required), `coordinates` and `speeds` ({name: value}, set
    on the default state), `parameters` ({"<component>/<property>": value}, model properties
    overridden before the model is built, as sinew.load's `parameters`), `load` (other keyword
    arguments of sinew.load), and any other keyword argument of Model.simulate (accuracy,
    integrator, step, report_interval, initial_states, excitations, controls,
    equilibrate_muscles). Returns the sinew.Result.
    """
    from . import load
    options = dict(case)
    load_options = dict(options.pop("load", {}))
    if "parameters" in options:
        if "parameters" in load_options:
            raise ValueError("a case gives parameters either at its top level or in 'load'")
        load_options["parameters"] = options.pop("parameters")
    model = load(model_path, **load_options)
    coordinates = options.pop("coordinates", {})
    speeds = options.pop("speeds", {})
    if coordinates or speeds:
        if options.get("initial_states") is not None:
            raise ValueError("a case gives either initial_states or coordinates/speeds")
        state = model.default_state()
        for name, value in coordinates.items():
            state.set_value(name, value)
        for name, value in speeds.items():
            state.set_speed(name, value)
        options["initial_states"] = state
    duration = options.pop("duration")
    return model.simulate(duration, **options)


def sweep(model_path: "os.PathLike[str] | str", cases: Sequence[Mapping[str, Any]],
          client: Optional[Any] = None) -> List[Any]:
    """Simulates `model_path` once per case on a Dask cluster; returns the Results in case order.

    Each worker loads the model file itself (the file is shipped by path, never a pickled
    System), so the path must be readable on every worker. `client` is a
    dask.distributed.Client of any cluster; None starts a LocalCluster of 2 worker processes
    for this call. See run_case for what a case holds.
    """
    from dask.distributed import Client, LocalCluster
    path = os.fspath(model_path)
    cases = [dict(case) for case in cases]
    own = client is None
    if own:
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        client = Client(cluster)
    try:
        futures = client.map(run_case, [path] * len(cases), cases, pure=False)
        return client.gather(futures)
    finally:
        if own:
            client.close()
            cluster.close()
