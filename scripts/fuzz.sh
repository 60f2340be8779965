#!/usr/bin/env bash
# Builds Sinew's libFuzzer targets in the sanitizer build (build/asan: clang + ASan + UBSan, the
# same build the sanitizer tests run in, so CI compiles the library once for both) and runs each
# of them in turn, the fuzzing time SECONDS (default 60) split evenly between them (at least 1 s
# each); the build does not count. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   targets: osim_reader storage_reader mesh_reader controls_reader simulate (default: all)
# Seeds: the small files of tests/data (.osim, .sto/.mot, .vtp, ControlSet .xml), the bad inputs
# in fuzz/seeds/<target>/, plus the generated ones fuzz_seeds writes; corpora grow across runs in build/asan/fuzz-corpus/<target>.
# Findings go to build/asan/fuzz-artifacts/, each run's log to build/asan/fuzz-logs/<target>.log.
# Exit status is non-zero when any target finds a crash, a leak, a timeout or an out-of-memory.
set -euo pipefail
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(osim_reader storage_reader mesh_reader controls_reader simulate)
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/asan"

build_targets=(fuzz_seeds)
for t in "${targets[@]}"; do build_targets+=("fuzz_$t"); done
bash "$root/scripts/build.sh" asan --target "${build_targets[@]}"

seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
# Copies the files under tests/data named *.EXT (case-insensitive) and smaller than 64 KB into
# DIR, each name prefixed by PREFIX and its content by the bytes PREFIX_BYTES.
copy_seeds() {
  local dir=$1 ext=$2 prefix=$3 bytes=$4
  mkdir -p "$dir"
  find "$root/tests/data" -iname "*.$ext" -size -64k -print0 |
    while IFS= read -r -d '' f; do
      { printf '%s' "$bytes"; cat "$f"; } >"$dir/$prefix$(basename "$f")"
    done
}
copy_seeds "$seeds/osim_reader" osim "" ""
copy_seeds "$seeds/storage_reader" sto "" ""
copy_seeds "$seeds/storage_reader" mot "" ""
copy_seeds "$seeds/mesh_reader" vtp "" "0"
# Hand-made bad inputs, one per check of issue #9 (fuzz/seeds/<target>/, see fuzz/CMakeLists.txt).
for dir in "$root"/fuzz/seeds/*/; do
  mkdir -p "$seeds/$(basename "$dir")"
  cp "$dir"* "$seeds/$(basename "$dir")/"
done
"$build/fuzz/fuzz_seeds" "$seeds/mesh_reader"
mkdir -p "$seeds/controls_reader"
grep -rlZ --include='*.xml' '<ControlSet' "$root/tests/data" | xargs -0 -I{} cp {} "$seeds/controls_reader/"
# The simulate target's first byte picks the integrator and actuator excitation: seed both
# euler without excitation ('0') and rk45 with every actuator excited ('3').
copy_seeds "$seeds/simulate" osim "euler_" "0"
copy_seeds "$seeds/simulate" osim "rk45_" "3"

dict_of() {
  case $1 in
    osim_reader | simulate) echo "$root/fuzz/osim.dict" ;;
    storage_reader) echo "$root/fuzz/storage.dict" ;;
    mesh_reader) echo "$root/fuzz/mesh.dict" ;;
    controls_reader) echo "$root/fuzz/controls.dict" ;;
  esac
}

share=$((seconds / ${#targets[@]}))
[ "$share" -ge 1 ] || share=1
mkdir -p "$build/fuzz-artifacts" "$build/fuzz-logs"
failed=()
for t in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$t"
  mkdir -p "$corpus"
  log="$build/fuzz-logs/$t.log"
  echo "fuzz: $t for $share s (log: $log)"
  status=0
  "$build/fuzz/fuzz_$t" "$corpus" "$seeds/$t" -dict="$(dict_of "$t")" \
    -max_total_time="$share" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$build/fuzz-artifacts/${t}-" -print_final_stats=1 >"$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  echo "fuzz: $t: ${runs:-?} runs, ${rate:-?} runs/s, $cov, exit $status"
  if [ "$status" -ne 0 ]; then
    failed+=("$t")
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written|uncaught' "$log" | head -20 || true
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (reproduce: build/asan/fuzz/fuzz_TARGET ARTIFACT)" >&2
  exit 1
fi
echo "fuzz: no findings"
