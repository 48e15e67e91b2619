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
# targets (tests/fuzz) that the test script runs.
packages=(build-essential cmake pkg-config libopenmesh-dev libcgal-dev libtinygltf-dev catch2
          nlohmann-json3-dev libstb-dev libcli11-dev libtbb-dev libboost-dev python3
          libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
          libocct-foundation-dev libembree-dev clang-14 libclang-rt-14-dev libfuzzer-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The Khronos glTF validator (npm) for the .glb export test, when npm is there.
# Without it the test warns that it checked nothing, and fails under CI=true.
if command -v npm >/dev/null 2>&1 && ! npm ls -g gltf-validator >/dev/null 2>&1; then
  npm install -g --silent --no-audit --no-fund gltf-validator >/dev/null 2>&1 ||
    echo "setup: gltf-validator not installed (npm failed); its test fails under CI" >&2
fi

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)"
