#!/usr/bin/env bash
# Writes scenes/lights/portal-sky.exr, the environment of scenes/lights/portal-window.pbrt: a
# 32x32 equal-area map (pbrt-v4's layout) of a sky that runs from deep blue to a pale horizon
# tint across the map, with a small bright sun (3x3 texels) centred on the direction
# (0.15, 0.55, 1), which shines in through the window onto the floor.
set -euo pipefail
cd "$(dirname "$0")/../.."
oiiotool --pattern fill:topleft=0.25,0.35,0.7:topright=0.45,0.55,0.95:bottomleft=0.9,0.75,0.5:bottomright=0.35,0.35,0.4 32x32 3 \
  --fill:color=60,52,40 3x3+16+20 -d half --compression zip -o scenes/lights/portal-sky.exr
