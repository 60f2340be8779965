"""Where the examples find their models: the repository's tests/data (credited in
tests/data/ATTRIBUTION.md), or the folder given in $SINEW_EXAMPLE_DATA."""
import os
import pathlib

DATA = pathlib.Path(os.environ.get(
    "SINEW_EXAMPLE_DATA", pathlib.Path(__file__).resolve().parents[2] / "tests" / "data"))
OPENSIM_RESOURCES = DATA / "opensim-org/opensim-core/Applications/Analyze/tests/resources"
SINGLE_PIN = OPENSIM_RESOURCES / "SinglePin.osim"
DOUBLE_PENDULUM_3D = OPENSIM_RESOURCES / "DoublePendulum3D.osim"
# chrono's planar double pendulum with a CoordinateActuator (optimal force 1 N m) on each pin.
ACTUATED_DOUBLE_PENDULUM = DATA / "projectchrono/chrono/data/opensim/double_pendulum.osim"
