#!/usr/bin/env bash
# Renders the pbrt-v4 references of the hard-transport scenes (scenes/hard; see
# tests/data/pbrt-v4/hard/README.md) into tests/data/pbrt-v4/hard/. Not part of CI and
# not needed by any test: it needs a pbrt-v4 binary (PBRT, default ../shared/tools/pbrt-v4/pbrt)
# and oiiotool, and takes about half an hour on 2 cores.
#
# Each scene is rendered twice by pbrt-v4 with the integrator its file names (volpath in media,
# bdpt or path on surfaces; never lightpath, which ignores participating media), with different
# seeds. The
# stored EXR holds their mean as R, G, B and half their difference as difference.R/G/B: the test
# can estimate the reference's own variance from it exactly as it does its renders' (per pixel,
# and per block for the correlation that splatting brings).
#
# Usage: scripts/make-pbrt-references.sh [SCENE...]   (default: every scene in the table)
set -euo pipefail
cd "$(dirname "$0")/.."
PBRT=${PBRT:-../shared/tools/pbrt-v4/pbrt}
out=tests/data/pbrt-v4/hard
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# scene  samples per run
table="fog-point 16384
fog-spot 4096
fog-small-area 4096
fog-large-area 4096
fog-caustic 32768
chromatic-fog 4096
fog-box-spot 4096
milky-glass 32768
light-in-glass 4096
underwater-point 4096
narrow-line 4096
near-specular-glass 4096
skin-lens 32768
coated-low-roughness 4096"

want=("$@")
while read -r scene spp; do
  if [ ${#want[@]} -gt 0 ] && [[ ! " ${want[*]} " == *" $scene "* ]]; then continue; fi
  seeds=()
  for seed in 1 2; do
    # This pbrt-v4 build has crashed now and then (a segmentation fault in one of several runs
    # of fog-small-area); a crashed run is rendered again with the next seed.
    for attempt in 0 1 2; do
      "$PBRT" --quiet --nthreads 2 --spp "$spp" --seed "$((seed + 10 * attempt))" \
        --outfile "$tmp/$scene.$seed.exr" "scenes/hard/$scene.pbrt" && { seeds+=("$((seed + 10 * attempt))"); break; }
      [ "$attempt" -lt 2 ] || exit 1
    done
  done
  oiiotool "$tmp/$scene.1.exr" --ch R,G,B "$tmp/$scene.2.exr" --ch R,G,B --add --mulc 0.5 -o "$tmp/mean.exr"
  oiiotool "$tmp/$scene.1.exr" --ch R,G,B "$tmp/$scene.2.exr" --ch R,G,B --sub --mulc 0.5 \
    --chnames difference.R,difference.G,difference.B -o "$tmp/difference.exr"
  oiiotool "$tmp/mean.exr" "$tmp/difference.exr" --chappend -d float --compression zip \
    --attrib "pbrt-v4:command" "pbrt --nthreads 2 --spp $spp --seed $(IFS=,; echo "${seeds[*]}") scenes/hard/$scene.pbrt" \
    -o "$out/$scene.exr"
  echo "$scene: $spp spp x 2, $(oiiotool "$out/$scene.exr" --ch R,G,B --printstats | grep Avg)"
done <<< "$table"
