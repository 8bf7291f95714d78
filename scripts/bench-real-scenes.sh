#!/usr/bin/env bash
# Caustica against pbrt-v4 at equal wall time on real scenes, each with a pbrt-v4 reference image
# beside it (NAME.pbrt with NAME.pbrt-v4.exr, as in ../shared/real-scenes). Per scene:
#   1. pbrt-v4 renders it at PBRT_SPP samples per pixel on 2 threads with a seed other than the
#      reference's; its wall time T, loading included, is the budget. (With the reference's own
#      seed, pbrt-v4's samples are the reference's first ones, and its error looks smaller than
#      it is: on killeroo-gold at 16 spp, relMSE 0.120 with the same seed, 0.195 with others.)
#   2. Caustica loads the scene once with --spp 1 to measure its loading time L (wall time less
#      the render seconds of --stats-json), then renders with --time T - L on 2 threads.
#   3. Both images are scored against the reference with `caustica diff`, and Caustica's image
#      mean is compared per channel with the reference's.
# Not part of CI: it needs pbrt-v4 (PBRT, default ../shared/tools/pbrt-v4/pbrt), oiiotool and a
# built caustica (CAUSTICA, default build/caustica). Extra arguments after -- go to Caustica.
#
# Usage: scripts/bench-real-scenes.sh [--pbrt-spp N] [--seed S] SCENE.pbrt ... [-- CAUSTICA_ARGS]
set -euo pipefail
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
PBRT=$(realpath "${PBRT:-$root/../shared/tools/pbrt-v4/pbrt}")
CAUSTICA=$(realpath "${CAUSTICA:-$root/build/caustica}")
pbrt_spp=16
seed=7
scenes=()
extra=()
while (($#)); do
    case $1 in
    --pbrt-spp) pbrt_spp=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) scenes+=("$(realpath "$1")"); shift ;;
    esac
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
relmse() { "$CAUSTICA" diff "$1" "$2" | awk '$1 == "relmse" {print $2}'; }
means() { oiiotool "$1" --printstats | awk '/Stats Avg/ {print $3, $4, $5}'; }

echo "| scene | pbrt-v4: wall s, relMSE | Caustica: wall s, relMSE | Caustica's mean against the reference, per channel |"
echo "| --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
    dir=$(dirname "$scene")
    name=$(basename "$scene" .pbrt)
    reference=$dir/$name.pbrt-v4.exr
    cd "$dir"
    start=$(now)
    "$PBRT" --quiet --nthreads 2 --spp "$pbrt_spp" --seed "$seed" --outfile "$tmp/pbrt.exr" "$name.pbrt" > /dev/null 2>&1
    budget=$(echo "$(now) - $start" | bc -l)

    start=$(now)
    "$CAUSTICA" render "$name.pbrt" --spp 1 --threads 2 --quiet --stats-json "$tmp/load.json" -o "$tmp/load.exr" \
        "${extra[@]}" > /dev/null 2>&1
    wall=$(echo "$(now) - $start" | bc -l)
    rendering=$(grep -o '"wall_seconds": *[0-9.e+-]*' "$tmp/load.json" | head -1 | awk '{print $2}')
    loading=$(echo "$wall - $rendering" | bc -l)
    render_budget=$(echo "$budget - $loading" | bc -l)
    if (($(echo "$render_budget < 0.05" | bc -l))); then render_budget=0.05; fi

    start=$(now)
    "$CAUSTICA" render "$name.pbrt" --time "$render_budget" --seed "$seed" --threads 2 --quiet -o "$tmp/caustica.exr" \
        "${extra[@]}" > /dev/null 2>&1
    wall=$(echo "$(now) - $start" | bc -l)

    read -r r g b <<< "$(means "$tmp/caustica.exr")"
    read -r rr rg rb <<< "$(means "$reference")"
    printf "| %s | %.2f, %.4f | %.2f, %.4f | %+.2f%%, %+.2f%%, %+.2f%% |\n" "$name" "$budget" \
        "$(relmse "$tmp/pbrt.exr" "$reference")" "$wall" "$(relmse "$tmp/caustica.exr" "$reference")" \
        "$(echo "100 * ($r / $rr - 1)" | bc -l)" "$(echo "100 * ($g / $rg - 1)" | bc -l)" \
        "$(echo "100 * ($b / $rb - 1)" | bc -l)"
done
