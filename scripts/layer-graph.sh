#!/usr/bin/env bash
# Writes docs/layers.dot: the CMake target graph of the library layers, the CLI and the outside
# libraries they link (cmake --graphviz; configure only, nothing is built). Draw it with
# `dot -Tsvg docs/layers.dot -o layers.svg` (Debian package graphviz).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/CMakeGraphVizOptions.cmake" <<'OPTS'
set(GRAPHVIZ_GRAPH_NAME "sinew")
set(GRAPHVIZ_GENERATE_PER_TARGET FALSE)
set(GRAPHVIZ_GENERATE_DEPENDERS FALSE)
set(GRAPHVIZ_IGNORE_TARGETS "^sinew$")
OPTS
cmake -S "$root" -B "$work" -G Ninja -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCHMARKS=OFF \
  -DSINEW_BUILD_EXAMPLES=OFF --graphviz="$work/layers.dot" >/dev/null
cp "$work/layers.dot" "$root/docs/layers.dot"
echo "wrote docs/layers.dot"
