#!/usr/bin/env bash
# Peak memory per stored light vertex: renders scenes/white-room.pbrt with sppm, bpm, vcm
# ("lightvertices" "retrace") and vcm ("store") at two path depths, and divides the difference in
# peak memory by the difference in light vertices kept (both from --stats-json). The two renders
# differ only in how many light vertices they keep, so everything else the process holds (film,
# splat buffers, scene, image output) cancels out. Also prints each render's peak over pt's, per
# vertex: an upper bound that charges per-pixel buffers to the vertices as well.
#
# Usage: scripts/bench-light-vertex-memory.sh [CAUSTICA] [--threads N]
set -euo pipefail
export LC_ALL=C

repo=$(cd "$(dirname "$0")/.." && pwd)
caustica=${1:-$repo/build/caustica}
threads=2
if [[ ${2:-} == --threads ]]; then threads=${3:?--threads needs a count}; fi
scene=$repo/scenes/white-room.pbrt
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Renders the scene with the Integrator line replaced; prints "vertices peak_mib".
render() {
    local integrator=$1 file=$work/scene.pbrt
    sed "s|^Integrator .*|Integrator $integrator|" "$scene" > "$file"
    "$caustica" render "$file" --quiet --spp 4 --seed 1 --threads "$threads" -o "$work/out.exr" \
        --stats-json "$work/stats.json" > /dev/null
    python3 - "$work/stats.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
print(stats["stored_light_vertices"], stats["peak_memory_mib"])
PY
}

read -r _ pt_mib < <(render '"path" "integer maxdepth" [ 12 ]')
printf '%-28s %12s %10s %16s %16s\n' integrator vertices peak_MiB bytes/vertex over_pt/vertex
for kind in '"sppm"' '"bpm"' '"vcm" "string lightvertices" "retrace"' '"vcm" "string lightvertices" "store"'; do
    read -r deep_n deep_mib < <(render "$kind \"integer maxdepth\" [ 12 ]")
    read -r shallow_n shallow_mib < <(render "$kind \"integer maxdepth\" [ 4 ]")
    python3 - "$kind" "$deep_n" "$deep_mib" "$shallow_n" "$shallow_mib" "$pt_mib" <<'PY'
import sys
kind, deep_n, deep_mib, shallow_n, shallow_mib, pt_mib = sys.argv[1], *map(float, sys.argv[2:])
slope = (deep_mib - shallow_mib) * 2**20 / (deep_n - shallow_n)
whole = (deep_mib - pt_mib) * 2**20 / deep_n
label = kind.replace('"string lightvertices" ', '').replace('"', '')
print(f"{label:<28} {int(deep_n):>12} {deep_mib:>10.1f} {slope:>16.1f} {whole:>16.1f}")
PY
done
