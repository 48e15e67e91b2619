#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# INTRACY against TRAY and Embree 3 (paper section 8, Table 2; issue 10).
# Renders the teapot scene and the paper's scenes 1, 2, 2a, 3 (data/scenes)
# with INTRACY, TRAY and (when built) bench_render_embree, one after the
# other, median of REPS runs (default 3) with THREADS threads (default 2), at
# 640x480 x 16 and 1280x1024 x 256 levels, plus 320x240 and 1280x1024 at 16
# levels for the scaling exponent; writes docs/results/render.md and the
# 640x480 scene images to docs/results/images/. Builds nothing: expects a
# Release build. Usage:
#   bench/render/bench_render.sh [BUILD_DIR] [OUT_MD]
# (defaults: build, docs/results/render.md). SCENES="teapot scene1 ..." and
# CONFIGS="640x480:16 1280x1024:256 ..." restrict a run; the table is written
# from every run found in out/bench-render/, so a restricted run adds to (and
# replaces the same runs of) the earlier ones.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
out_md=${2:-$here/docs/results/render.md}
threads=${THREADS:-2}
reps=${REPS:-3}
seamless=$build/bin/seamless
embree=$build/bin/bench_render_embree
work=$here/out/bench-render
images=$here/docs/results/images
[ -x "$seamless" ] || { echo "bench_render: no binary at $seamless (build Release first)" >&2; exit 2; }
[ -x "$embree" ] || embree=
mkdir -p "$work" "$images"

read -r -a scenes <<<"${SCENES:-teapot scene1 scene2 scene2a scene3}"
read -r -a configs <<<"${CONFIGS:-640x480:16 1280x1024:256 320x240:16 1280x1024:16}"
configs=("${configs[@]/:/ }")
for sc in "${scenes[@]}"; do
  for cfg in "${configs[@]}"; do
    read -r size levels <<<"$cfg"
    methods=(intracy tray)
    if [ -n "$embree" ] && { [ "$cfg" = "640x480 16" ] || [ "$cfg" = "1280x1024 256" ]; }; then
      methods+=(embree)
    fi
    for method in "${methods[@]}"; do
      rm -f "$work/$sc-$method-$size-$levels"-*.json
      for rep in $(seq 1 "$reps"); do
        tag="$sc-$method-$size-$levels-$rep"
        echo "bench_render: $tag" >&2
        png=$work/$sc-$method-$size-$levels.png
        if [ "$method" = embree ]; then
          "$embree" "$here/data/scenes/$sc.json" --size "$size" --levels "$levels" \
            --threads "$threads" -o "$png" >"$work/$tag.json"
        else
          "$seamless" render "$here/data/scenes/$sc.json" -o "$png" --method "$method" \
            --size "$size" --levels "$levels" --threads "$threads" --stats "$work/$tag.json" \
            >/dev/null 2>"$work/$tag.log"
        fi
      done
      if [ "$sc" != teapot ] && [ "$size" = 640x480 ] && [ "$method" != embree ]; then
        cp "$png" "$images/$sc-$method.png"
      fi
    done
  done
done

model=$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)
python3 "$here/bench/render/render_table.py" "$work" "$out_md" "$model" "$(nproc)" \
  "$(date -u +%Y-%m-%d)" "$threads" "$reps" "${embree:+yes}"
