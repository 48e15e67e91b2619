#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job on the bundled default: describe the teapot model, tessellate it
# crack-free to glTF, and verify the mesh. Outputs land in out/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
seamless="$here/build/bin/seamless"
model="$here/data/models/teapot.json"
mkdir -p "$here/out"
"$seamless" info "$model"
if "$seamless" tessellate --help >/dev/null 2>&1; then
  "$seamless" tessellate "$model" -o "$here/out/teapot.glb" --stats "$here/out/teapot-tessellation.json"
fi
if "$seamless" check --help >/dev/null 2>&1 && [ -f "$here/out/teapot.glb" ]; then
  "$seamless" check "$here/out/teapot.glb"
fi
