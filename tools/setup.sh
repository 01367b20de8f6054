#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages only), then configures and
# builds particles in ./build. Safe to run again: it installs nothing twice
# and rebuilds only what changed.
#
#   bash tools/setup.sh            # Release build in ./build
#   BUILD_DIR=out bash tools/setup.sh
#   CI=true bash tools/setup.sh    # also -Werror
#   BUILD_DIR=build-asan BUILD_TYPE=Debug CMAKE_EXTRA_ARGS=-DPARTICLES_SANITIZE=ON \
#     bash tools/setup.sh          # ASan + UBSan at -O1 (what .ci/run does second)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$here/build}
build_type=${BUILD_TYPE:-Release}

packages=(
  build-essential cmake pkg-config
  libeigen3-dev nlohmann-json3-dev libcli11-dev libbox2d-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsfml-dev xvfb xauth fonts-dejavu-core  # particles view, and its screenshot tests headless
  gnuplot-nox  # the plots of the HTML reports (suite, bench, stress); without it they say so
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
# CMAKE_EXTRA_ARGS: more -D options, word-split (.ci/run's sanitizer build).
# shellcheck disable=SC2086
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" -DPARTICLES_WERROR="$werror" \
  ${CMAKE_EXTRA_ARGS:-} >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
