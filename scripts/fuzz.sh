#!/usr/bin/env bash
# Builds the libFuzzer target of the .osim reader with clang + ASan and runs it for a bounded
# time (default 60 s), seeded with the small test models. Usage: scripts/fuzz.sh [seconds].
# Exit status is non-zero only when the fuzzer finds a crash, a leak or a timeout.
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/fuzz"
CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSINEW_BUILD_FUZZERS=ON -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" --target fuzz_osim_reader -j "$(nproc)"
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
# Seeds: the test models under 60 KB (small inputs keep the run fast).
find "$root/tests/data" -name '*.osim' -size -60k -exec cp {} "$corpus/" \;
artifacts="$build/artifacts"
mkdir -p "$artifacts"
"$build/fuzz/fuzz_osim_reader" "$corpus" -dict="$root/fuzz/osim.dict" \
  -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$artifacts/" -print_final_stats=1
