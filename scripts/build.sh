#!/usr/bin/env bash
# Configures and builds Sinew. Usage: scripts/build.sh [release|asan] [cmake --build options...]
# (default release; e.g. `--target test_engine` builds one program). Builds into build/<kind>.
# Warnings are errors in both kinds. The sanitizer build (asan) uses clang with ASan + UBSan and
# also builds the libFuzzer targets (scripts/fuzz.sh), so CI compiles the library once for the
# sanitizer tests and the fuzzing; it is optimized lightly (-O1, line tables only) because its
# compile time dominates CI and the sanitizers need no more to report precisely.
# SINEW_CORPUS_DIR (folder of real OpenSim files for the corpus sweeps; default
# ../shared/opensim-data when present) and SINEW_REQUIRE_CORPUS=ON (fail without it, as CI does)
# are passed to CMake.
set -euo pipefail
kind=${1:-release}
shift || true
root=$(cd "$(dirname "$0")/.." && pwd)
case "$kind" in
  release) flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  asan) flags=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG"
    -DSINEW_SANITIZE=ON -DSINEW_BUILD_FUZZERS=ON -DSINEW_BUILD_BENCHMARKS=OFF
    -DSINEW_BUILD_PYTHON=OFF) ;;
  *) echo "usage: $0 [release|asan]" >&2; exit 1 ;;
esac
flags+=(-DSINEW_CORPUS_DIR="${SINEW_CORPUS_DIR:-}" -DSINEW_REQUIRE_CORPUS="${SINEW_REQUIRE_CORPUS:-OFF}")
# Several checkouts (git worktrees) share ccache's objects when paths are taken relative to them.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$root")}"
cmake -S "$root" -B "$root/build/$kind" -G Ninja -DSINEW_WERROR=ON "${flags[@]}" >/dev/null
cmake --build "$root/build/$kind" -j "$(nproc)" "$@"
