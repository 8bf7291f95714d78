#!/usr/bin/env bash
# Renders the stored high-sample references the tests compare against. Run from the repository
# root after building; the outputs go to tests/data/renderer/. Slow (minutes): not part of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/caustica
$bin render scenes/cornell-box.pbrt --integrator pt --spp 4096 --seed 1000 --quiet \
  -o tests/data/renderer/cornell-box.pt-4096spp.exr

# The transport-agreement scenes (tests/integrators/transport_agreement_test.cpp): the path
# tracer renders every path these scenes have, without bias, and with a "variance" layer (the
# per-pixel variance of each pixel's mean) that the test uses as the reference's own noise.
for scene in pool-air pool-underwater glass-block rough-glass-slab prism fog-block medium-glass-block fluorescent-stage; do
  $bin render scenes/transport/$scene.pbrt --integrator pt --spp 8192 --seed 2000 --variance --quiet \
    -o tests/data/renderer/transport/$scene.pt-8192spp.exr
done
