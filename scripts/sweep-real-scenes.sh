#!/usr/bin/env bash
# Loads and renders many real pbrt-v4 scenes with both Caustica and pbrt-v4 at a small size, to
# find the files Caustica refuses or renders differently (a sweep, not a benchmark: it reports
# exit statuses, Caustica's warnings and both images' means, not times). For each SCENE.pbrt a
# copy with the Film's larger side reduced to --size pixels is written beside it (so that its
# relative paths still resolve), rendered by pbrt-v4 and by Caustica with the same sample count
# and the scene's own integrator, and one line per scene is printed:
#   SCENE  pbrt-v4 exit status and mean R G B  |  Caustica exit status and mean R G B  |  Caustica's
#   first error or warning
# Means that differ by more than the noise (rerun with more --spp to tell) point at a feature to
# check; pbrt-v4's "path" ignores participating media where Caustica renders them. Not part of CI:
# it needs pbrt-v4 (PBRT, default ../shared/tools/pbrt-v4/pbrt), oiiotool, python3 and a built
# caustica (CAUSTICA, default build/caustica).
#
# Usage: scripts/sweep-real-scenes.sh [--spp N] [--size PIXELS] SCENE.pbrt ...
set -euo pipefail
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
PBRT=$(realpath "${PBRT:-$root/../shared/tools/pbrt-v4/pbrt}")
CAUSTICA=$(realpath "${CAUSTICA:-$root/build/caustica}")
spp=16
size=128
scenes=()
while (($#)); do
    case $1 in
    --spp) spp=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    *) scenes+=("$(realpath "$1")"); shift ;;
    esac
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

means() { oiiotool "$1" --printstats 2>/dev/null | awk '/Stats Avg/ {printf "%.4f %.4f %.4f", $3, $4, $5; exit}'; }

for scene in "${scenes[@]}"; do
    dir=$(dirname "$scene")
    small="$dir/$(basename "$scene" .pbrt).sweep-small.pbrt"
    python3 - "$scene" "$small" "$size" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
size = int(sys.argv[3])
pattern = {axis: re.compile(r'"integer %sresolution"\s*\[?\s*(\d+)' % axis) for axis in "xy"}
found = {axis: pattern[axis].search(text) for axis in "xy"}
x = int(found["x"].group(1)) if found["x"] else 1280
y = int(found["y"].group(1)) if found["y"] else 720
k = max(x, y) / size
for axis, value in (("x", x), ("y", y)):
    m = pattern[axis].search(text)
    if m:
        text = text[:m.start(1)] + str(max(1, round(value / k))) + text[m.end(1):]
open(sys.argv[2], "w").write(text)
EOF
    pbrt_status=0 caustica_status=0
    (cd "$dir" && timeout 600 "$PBRT" --quiet --nthreads 2 --spp "$spp" --outfile "$tmp/pbrt.exr" "$small") \
        > "$tmp/pbrt.log" 2>&1 || pbrt_status=$?
    (cd "$dir" && timeout 600 "$CAUSTICA" render "$small" --spp "$spp" --threads 2 --quiet -o "$tmp/caustica.exr") \
        > "$tmp/caustica.log" 2>&1 || caustica_status=$?
    message=$(grep -m1 -E "error|warning" "$tmp/caustica.log" || true)
    echo "$(basename "$scene")  pbrt-v4 $pbrt_status [$( ((pbrt_status == 0)) && means "$tmp/pbrt.exr")]" \
         " | Caustica $caustica_status [$( ((caustica_status == 0)) && means "$tmp/caustica.exr")]  $message"
    rm -f "$small" "$tmp/pbrt.exr" "$tmp/caustica.exr"
done
