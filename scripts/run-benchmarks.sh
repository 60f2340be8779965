#!/usr/bin/env bash
# Runs every Google Benchmark program (bench_*) of a build, and benchmarks/python_step.py when
# the Python module was built. Usage:
#   scripts/run-benchmarks.sh BUILD_DIR [--quick] [extra benchmark flags...]
# With --quick each benchmark runs once with minimal time (--benchmark_min_time=0.001,
# --benchmark_repetitions=1; benchmarks with their own MinTime keep it), which proves in a few
# minutes that they still build, find their data and run to completion; the timings mean little.
# Build the programs first, e.g. `ninja -C build/release` (they are on by default,
# SINEW_BUILD_BENCHMARKS). Exit status is non-zero when a program is missing, crashes or exits
# non-zero, or when a benchmark reports an error (SkipWithError); each program's JSON results
# are kept in BUILD_DIR/benchmark-results/.
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [--quick] [benchmark flags...]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
shift
flags=()
quick=()
if [ "${1:-}" = "--quick" ]; then
  quick=(--quick)
  flags+=(--benchmark_min_time=0.001 --benchmark_repetitions=1)
  shift
fi
flags+=("$@")

root=$(cd "$(dirname "$0")/.." && pwd)
mapfile -t sources < <(find "$root/benchmarks" -maxdepth 1 -name '*.cc' | sort)
if [ ${#sources[@]} -eq 0 ]; then
  echo "run-benchmarks: no benchmarks/*.cc" >&2
  exit 1
fi
out="$build/benchmark-results"
mkdir -p "$out"
failed=()
for source in "${sources[@]}"; do
  name=bench_$(basename "$source" .cc)
  program="$build/benchmarks/$name"
  if [ ! -x "$program" ] && [[ $name == bench_simbody_* ]] &&
    ! grep -q '^SINEW_BENCHMARK_SIMBODY:INTERNAL=1' "$build/CMakeCache.txt"; then
    echo "== $name: skipped (Simbody not found at configure time; scripts/setup.sh installs it)"
    continue
  fi
  if [ ! -x "$program" ]; then
    echo "run-benchmarks: $name: not built ($program missing)" >&2
    failed+=("$name")
    continue
  fi
  echo "== $name"
  status=0
  "$program" "${flags[@]}" --benchmark_out="$out/$name.json" --benchmark_out_format=json ||
    status=$?
  if [ "$status" -ne 0 ]; then
    echo "run-benchmarks: $name exited with status $status" >&2
    failed+=("$name")
  elif grep -q '"error_occurred": true' "$out/$name.json"; then
    echo "run-benchmarks: $name: a benchmark reported an error:" >&2
    grep '"error_message"' "$out/$name.json" >&2 || true
    failed+=("$name")
  fi
done
# The Python module's benchmarks (benchmarks/python_step.py), when the module was built.
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
if grep -q '^SINEW_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "== python_step.py"
  PYTHONPATH="$build/python" "$python" "$root/benchmarks/python_step.py" "${quick[@]}" ||
    failed+=(python_step.py)
fi
if [ ${#failed[@]} -gt 0 ]; then
  echo "run-benchmarks: FAILED: ${failed[*]}" >&2
  exit 1
fi
echo "run-benchmarks: all ${#sources[@]} programs ran to completion"
