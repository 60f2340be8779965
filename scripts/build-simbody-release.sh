#!/usr/bin/env bash
# Builds Simbody 3.7 in Release (Simbody's own flags: -O2 -DNDEBUG) for the Simbody comparison
# benchmark, then that benchmark against it. Debian's libsimbody-dev (scripts/setup.sh), which
# the tests use, is built with its assertions on and runs about 1.55x slower, so issue #15's
# "faster than Simbody" figures need this build (docs/benchmarks.md).
#
# The source is Debian's own package of the same version (simbody_3.7+dfsg, from the Debian
# mirror apt uses, its SHA-256 checked), so nothing but Debian is downloaded. Takes about
# 9 minutes on 2 cores; not part of CI. Builds into build/simbody/ (source, build, install)
# and build/simbody-bench/ (Sinew's Release build with bench_simbody_hung linked to it).
# Usage: scripts/build-simbody-release.sh, then
#   build/simbody-bench/benchmarks/bench_simbody_hung --benchmark_filter=merson_sweep
# DEBIAN_MIRROR overrides the mirror (default http://deb.debian.org/debian).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
tarball=simbody_3.7+dfsg.orig.tar.xz
sha256=c2e2a3e7def05ba4fda4b216d04d41bdc6477c0cfcec20bfce98c1005532dfb6
work=$root/build/simbody
bash "$root/scripts/setup.sh"  # CMake, Ninja, LAPACK (through libsimbody-dev), Sinew's own
install=$work/install
mkdir -p "$work"

if [ ! -f "$install/lib/cmake/simbody/SimbodyConfig.cmake" ] &&
   [ ! -f "$install/lib/x86_64-linux-gnu/cmake/simbody/SimbodyConfig.cmake" ]; then
  if ! echo "$sha256  $work/$tarball" | sha256sum -c --status 2>/dev/null; then
    echo "build-simbody-release: downloading $tarball from $mirror"
    if ! command -v curl >/dev/null; then
      sudo_cmd=""
      [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
      $sudo_cmd apt-get update -qq
      DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq curl
    fi
    curl -fsSL -o "$work/$tarball" "$mirror/pool/main/s/simbody/$tarball"
    echo "$sha256  $work/$tarball" | sha256sum -c --status ||
      { echo "build-simbody-release: $tarball has the wrong SHA-256" >&2; exit 1; }
  fi
  rm -rf "$work/src" "$work/build"
  mkdir -p "$work/src"
  tar -xJf "$work/$tarball" -C "$work/src" --strip-components=1
  cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$install" -DBUILD_EXAMPLES=OFF -DBUILD_VISUALIZER=OFF \
    -DBUILD_TESTING=OFF -DBUILD_STATIC_LIBRARIES=OFF -DINSTALL_DOCS=OFF >/dev/null
  cmake --build "$work/build" -j "$(nproc)"
  cmake --install "$work/build" >/dev/null
fi
config=$(dirname "$(find "$install" -name SimbodyConfig.cmake | head -n 1)")

# Sinew's Release build, its Simbody reference compiled with NDEBUG to match the library
# (reference/CMakeLists.txt), linked to this Simbody (the benchmark's run path points at it).
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$root")}"
cmake -S "$root" -B "$root/build/simbody-bench" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSimbody_DIR="$config" -DSINEW_SIMBODY_NDEBUG=ON -DSINEW_WERROR=ON -DSINEW_BUILD_TESTS=OFF \
  -DSINEW_BUILD_EXAMPLES=OFF -DSINEW_BUILD_PYTHON=OFF >/dev/null
cmake --build "$root/build/simbody-bench" -j "$(nproc)" --target bench_simbody_hung
echo "build-simbody-release: $root/build/simbody-bench/benchmarks/bench_simbody_hung"
