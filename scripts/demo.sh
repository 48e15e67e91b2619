#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job on the bundled default: describe the teapot model, tessellate it
# crack-free to glTF, verify the mesh, and render the default scene with
# INTRACY. Outputs land in out/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
seamless="$here/build/bin/seamless"
model="$here/data/models/teapot.json"
mkdir -p "$here/out"
"$seamless" info "$model"
echo
"$seamless" tessellate "$model" -o "$here/out/teapot.glb" --stats "$here/out/teapot-tessellation.json"
echo
# The teapot is open by design (the lid does not meet the rim, the spout is
# open), so check judges it without --closed: exit 0 means no cracks,
# T-junctions, non-manifold or degenerate elements, flips or self-intersections.
"$seamless" check "$here/out/teapot.glb"
echo
"$seamless" render "$here/data/scenes/teapot.json" -o "$here/out/teapot.png" --stats "$here/out/teapot-render.json"
echo "outputs: $here/out/teapot.glb, $here/out/teapot.png (and their --stats JSON)"
