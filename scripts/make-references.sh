#!/usr/bin/env bash
# Renders the stored high-sample references the tests compare against. Run from the repository
# root after building; the outputs go to tests/data/renderer/. Slow (minutes): not part of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/caustica
$bin render scenes/cornell-box.pbrt --integrator pt --spp 4096 --seed 1000 --quiet \
  -o tests/data/renderer/cornell-box.pt-4096spp.exr
