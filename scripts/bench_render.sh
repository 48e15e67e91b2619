#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Moved: the rendering benchmark lives in bench/render/bench_render.sh.
exec "$(cd "$(dirname "$0")/.." && pwd)/bench/render/bench_render.sh" "$@"
