#!/usr/bin/env bash
# Error against time, Caustica against pbrt-v4, on a witness scene with a stored pbrt-v4 reference
# (tests/data/pbrt-v4/SCENE.exr, made by scripts/make-pbrt-references.sh): each renderer renders
# the scene at the sample counts given, taking turns, and the table reports the wall time of the
# whole process, the relative MSE against the reference (`caustica diff`) and their product,
# relMSE x seconds (lower is better: it does not depend on the sample count for an unbiased
# renderer, so renderers are compared at whatever counts suit them). Not part of CI: it needs
# pbrt-v4 (PBRT, default ../shared/tools/pbrt-v4/pbrt) and a built caustica (CAUSTICA, default
# build/caustica).
#
# Usage: scripts/bench-relmse-vs-pbrt.sh SCENE PBRT_SPP [INTEGRATOR:SPP ...]
#   e.g. scripts/bench-relmse-vs-pbrt.sh media/plume-spot 256 pt:256 vcm:64
# SCENE is scenes/SCENE.pbrt; pbrt-v4 renders it with the integrator the file names, at
# PBRT_SPP samples per pixel; Caustica with each INTEGRATOR at SPP. Every render uses 2 threads
# and runs REPETITIONS times (default 3) with different seeds; the table gives medians. pbrt-v4's
# seeds start at 100: the references are pbrt-v4's renders with seeds 1 and 2 (and 11, 12, 21,
# 22 after a crash; make-pbrt-references.sh), and a render with one of those seeds repeats the
# reference's first samples, so part of its error would cancel against the reference.
set -euo pipefail
export LC_ALL=C
cd "$(dirname "$0")/.."
PBRT=${PBRT:-../shared/tools/pbrt-v4/pbrt}
CAUSTICA=${CAUSTICA:-build/caustica}
REPETITIONS=${REPETITIONS:-3}
scene=$1
pbrt_spp=$2
shift 2
reference=tests/data/pbrt-v4/$scene.exr
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Runs one render (the command after the label), then prints: label seconds relMSE.
measure() {
    local label=$1 out=$2
    shift 2
    local start end
    start=$(date +%s.%N)
    "$@" > /dev/null 2>&1
    end=$(date +%s.%N)
    local relmse
    relmse=$("$CAUSTICA" diff "$out" "$reference" | awk '$1 == "relmse" {print $2}')
    echo "$label $(echo "$end - $start" | bc -l) $relmse"
}

for ((r = 1; r <= REPETITIONS; ++r)); do
    measure "pbrt-v4" "$tmp/pbrt.exr" "$PBRT" --quiet --nthreads 2 --spp "$pbrt_spp" --seed "$((100 + r))" \
        --outfile "$tmp/pbrt.exr" "scenes/$scene.pbrt"
    for entry in "$@"; do
        integrator=${entry%%:*}
        spp=${entry##*:}
        measure "caustica-$integrator" "$tmp/$integrator.exr" "$CAUSTICA" render "scenes/$scene.pbrt" \
            --integrator "$integrator" --spp "$spp" --seed "$r" --threads 2 --quiet -o "$tmp/$integrator.exr"
    done
done > "$tmp/runs.txt"

echo "| renderer | seconds | relMSE | relMSE x seconds |"
echo "| --- | --- | --- | --- |"
for label in $(awk '{print $1}' "$tmp/runs.txt" | awk '!seen[$0]++'); do
    awk -v l="$label" '$1 == l {print $2, $3, $2 * $3}' "$tmp/runs.txt" | sort -k3 -g |
        awk -v l="$label" '{s[NR] = $1; e[NR] = $2; p[NR] = $3} END {m = int((NR + 1) / 2);
            printf "| %s | %.2f | %.4g | %.4g |\n", l, s[m], e[m], p[m]}'
done
