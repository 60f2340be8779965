#!/usr/bin/env bash
# Installs a built Sinew into a scratch prefix, checks that the install holds public headers only,
# and builds and runs a project outside the tree that finds it with find_package(sinew).
# Usage: scripts/check-install.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:?usage: $0 BUILD_DIR}" && pwd)
prefix="$build/install-check/prefix"
rm -rf "$build/install-check"
cmake --install "$build" --prefix "$prefix" >/dev/null

# Public headers only: no internal/ folder, no header that includes an implementation library.
include="$prefix/include"
private=$(find "$include" -path '*/internal/*' -o -name 'internal' | sort)
leaks=$(grep -rlE '^#include [<"](pugixml|zlib|nlohmann/|CLI/|muParser)' "$include" || true)
if [ -n "$private$leaks" ]; then
  echo "install check: private headers installed:" >&2
  printf '  %s\n' $private $leaks >&2
  exit 1
fi
# Every installed header compiles with only the install tree and Eigen on the include path.
headers=$(cd "$include" && find sinew -name '*.h' | sort)
{ for h in $headers; do echo "#include <$h>"; done; } > "$build/install-check/all_headers.cc"
"${CXX:-c++}" -std=c++20 -fsyntax-only -I"$include" -I/usr/include/eigen3 \
  "$build/install-check/all_headers.cc"
echo "install check: $(echo "$headers" | wc -l) public headers, none private, all compile against the install tree alone"

cmake -S "$root/examples/find_package_consumer" -B "$build/install-check/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build/install-check/consumer" >/dev/null
"$build/install-check/consumer/consumer" \
  "$root/tests/data/projectchrono/chrono/data/opensim/double_pendulum.osim" >/dev/null
echo "install check: find_package(sinew) consumer built and ran"

# The Python module, when built: installed into site-packages under the prefix, importable from
# there alone, and it simulates.
site=$(sed -n 's/^SINEW_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
if grep -q '^SINEW_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  (cd "$build/install-check" && PYTHONPATH="$prefix/$site" "$python" -c "
import sinew, sys
assert sinew.__file__.startswith('$prefix'), sinew.__file__
model = sinew.load(sys.argv[1])
assert len(model.simulate(0.1).time) == 11
" "$root/tests/data/projectchrono/chrono/data/opensim/double_pendulum.osim")
  echo "install check: the Python module imports from $prefix/$site and simulates"
fi
