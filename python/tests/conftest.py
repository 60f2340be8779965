"""Shared pieces of the Python tests: where the test data and the CLI are (ctest sets
SINEW_TEST_DATA_DIR and SINEW_CLI), a storage-file reader written here (independent of the
library's), and a runner for `sinew simulate`."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

DATA = pathlib.Path(os.environ.get(
    "SINEW_TEST_DATA_DIR", pathlib.Path(__file__).resolve().parents[2] / "tests" / "data"))
RESOURCES = DATA / "opensim-org/opensim-core/Applications/Analyze/tests/resources"
CHRONO = DATA / "projectchrono/chrono/data/opensim"


def read_sto(path):
    """(labels, time [n], values [n, labels]) of a .sto file: the header up to `endheader`, a
    tab-separated label line, then rows of numbers."""
    lines = pathlib.Path(path).read_text().splitlines()
    end = next(i for i, line in enumerate(lines) if line.strip() == "endheader")
    labels = lines[end + 1].split("\t")
    rows = np.array([[float(x) for x in line.split()] for line in lines[end + 2:] if line.strip()])
    return labels[1:], rows[:, 0], rows[:, 1:]


@pytest.fixture(scope="session")
def cli():
    """Runs `sinew simulate ARGS --quiet --out DIR` and returns DIR/states.sto."""
    program = os.environ.get("SINEW_CLI")
    if not program:
        pytest.skip("SINEW_CLI is not set (ctest sets it to the built sinew program)")

    def simulate(args, out):
        subprocess.run([program, "simulate", *map(str, args), "--quiet", "--out", str(out)],
                       check=True, capture_output=True)
        return pathlib.Path(out) / "states.sto"
    return simulate
