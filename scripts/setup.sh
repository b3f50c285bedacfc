#!/usr/bin/env bash
# Installs the Debian packages the testbed needs (only those missing), then configures and
# builds it in Release. Idempotent: when everything is installed it runs no apt-get at all.
# Sourced by main.sh and test.sh; can also be run on its own.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(
  cmake ninja-build g++ ccache pkg-config
  clang libclang-rt-14-dev
  libeigen3-dev libtbb-dev libcli11-dev libsuitesparse-dev libopenblas0-serial
  libopenvdb-dev libboost-iostreams-dev libcgal-dev libgsl-dev libpng-dev libembree-dev libopenexr-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtomlplusplus-dev glmark2-data
  gnuplot-nox ffmpeg snakemake
)

# The test suite's also (test.sh sets this): a Slurm cluster and a browser for the workflow's
# tests, Blender for the point cache's round trip.
[ "${RICE_TEST_PACKAGES:-}" = "1" ] && packages+=(slurm-wlm munge chromium blender)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DRICE_WERROR="$werror" >/dev/null
cmake --build build -j "$(nproc)"
