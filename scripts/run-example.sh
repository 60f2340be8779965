#!/usr/bin/env bash
# Sets up, builds (Release) and runs Sinew's main jobs on models bundled in tests/data:
#   1. inspect Rajagopal2016 (what the file says and what the parser builds),
#   2. simulate OpenSim's 3-D double pendulum from its initial states, with a browser viewer,
#   3. export Rajagopal2016 playing the Hamner running motion as a browser viewer,
#   4. render a still picture of it,
#   5. the same double pendulum from Python (examples/python/simulate_and_plot.py).
# Everything is written to out/ (open out/*.html in a browser; they work offline).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" release
sinew="$root/build/release/apps/sinew/sinew"
data="$root/tests/data"
out="$root/out"
mkdir -p "$out"
rajagopal="$data/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim"
geometry="$data/opensim-org/opensim-models/Geometry"
running="$data/opensim-org/opensim-models/Pipelines/Hamner/outputReference/ResultsIK/subject02_running_ik.mot"
pendulum="$data/opensim-org/opensim-core/Applications/Analyze/tests/resources"

echo "== 1. sinew inspect Rajagopal2016.osim (first lines; all of it in $out/rajagopal_inspect.txt)"
"$sinew" inspect "$rajagopal" > "$out/rajagopal_inspect.txt"
head -n 6 "$out/rajagopal_inspect.txt"

echo "== 2. sinew simulate DoublePendulum3D.osim, 3 s from OpenSim's initial states"
"$sinew" simulate "$pendulum/DoublePendulum3D.osim" --duration 3 --accuracy 1e-8 \
  --initial-states "$pendulum/DoublePendulum3D_InitialStates.sto" \
  --out "$out/double_pendulum" --export "$out/double_pendulum.html" --vis primitives

echo "== 3. sinew export Rajagopal2016 running (Hamner IK motion)"
"$sinew" export "$rajagopal" --motion "$running" --vis mesh --geometry-dir "$geometry" \
  --out "$out/rajagopal_running.html"

echo "== 4. sinew render a frame of it"
"$sinew" render "$rajagopal" --motion "$running" --time 0.4 --vis mesh \
  --geometry-dir "$geometry" --out "$out/rajagopal_running.png"

echo "== 5. Python: sinew.load(...).simulate(...), compared with OpenSim's states, plotted"
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$root/build/release/CMakeCache.txt")
PYTHONPATH="$root/build/release/python" MPLBACKEND=Agg "${python:-python3}" \
  "$root/examples/python/simulate_and_plot.py" "$out/python"

echo "Done. Open $out/rajagopal_running.html or $out/double_pendulum.html in a browser."
