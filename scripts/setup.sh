#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what seamless needs on Debian 12 (only what is missing), then
# configures and builds into build/ (Release). Idempotent: a second run only
# rebuilds what changed. Usage: scripts/setup.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}

# OpenCASCADE reads STEP/IGES (lib/model) and is the tessellation benchmark's
# baseline; Embree is the render benchmark's baseline (bench/, optional
# targets); clang with libFuzzer and the sanitizer runtimes builds the fuzz
# targets (tests/fuzz) that the test script runs. pybind11 with Debian's
# python3 headers, numpy and pytest: the Python module (python/) and its tests;
# Dask distributed: `seamless batch --scheduler` (docs/batch.md).
packages=(build-essential cmake pkg-config libopenmesh-dev libcgal-dev libtinygltf-dev catch2
          nlohmann-json3-dev libstb-dev libpng-dev libcli11-dev libtbb-dev libboost-dev python3
          python3-dev pybind11-dev python3-numpy python3-pytest python3-distributed
          libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
          libocct-foundation-dev libembree-dev clang-14 libclang-rt-14-dev libfuzzer-14-dev)
# node and npm run the Khronos glTF validator (tests/mesh/io/mesh_io_test.cpp);
# by command, since a node from elsewhere (nodesource) brings its own npm.
command -v node >/dev/null 2>&1 || packages+=(nodejs)
command -v npm >/dev/null 2>&1 || packages+=(npm)
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
# One dpkg-query for all (a query per package took 1.5 s of every run).
installed=$(dpkg-query -W -f='${Package} ${Status}\n' "${packages[@]}" 2>/dev/null |
  awk '/ install ok installed$/ {print $1}' || true)
missing=()
for p in "${packages[@]}"; do
  grep -qx -- "$p" <<<"$installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The Khronos glTF validator (npm) for the .glb export test. Without it the
# test warns that it checked nothing, and fails under CI=true.
if ! npm ls -g gltf-validator >/dev/null 2>&1; then
  $sudo_cmd npm install -g --silent --no-audit --no-fund gltf-validator >/dev/null 2>&1 ||
    echo "setup: gltf-validator not installed (npm failed); its test fails under CI" >&2
fi

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)"

# `import seamless` in Debian's python3 with no other step (docs/python.md):
# a .pth file in its site folder names BUILD_DIR/python, where the build puts
# the module. One per machine: the last set-up's build is the one imported.
python=/usr/bin/python3
site_dir=$("$python" -c 'import site; print(site.getsitepackages()[0])')
module_dir="$(cd "$build" && pwd)/python"
if [ "$(cat "$site_dir/seamless.pth" 2>/dev/null)" != "$module_dir" ]; then
  $sudo_cmd mkdir -p "$site_dir"
  echo "$module_dir" | $sudo_cmd tee "$site_dir/seamless.pth" >/dev/null
fi
