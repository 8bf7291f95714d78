#!/usr/bin/env bash
# Error against time for Caustica's integrators on one scene, against a given reference image:
# for each seed, every INTEGRATOR:SPP renders in turn (so that the machine's drift falls on all
# alike), and the table gives the medians of the whole process's wall seconds, of the relMSE
# against the reference (`caustica diff`), and of their product, relMSE x seconds (lower is
# better, and independent of the sample count for an unbiased renderer). Not part of CI.
#
# Usage: scripts/bench-equal-time.sh SCENE.pbrt REFERENCE.exr INTEGRATOR:SPP [INTEGRATOR:SPP ...]
#   e.g. scripts/bench-equal-time.sh scenes/hard/narrow-line.pbrt /tmp/ref.exr bdpt:32 vcm:64
# Make the reference with the same build at many samples, for example
#   build/caustica render scenes/hard/narrow-line.pbrt --integrator bdpt --spp 4096 --seed 77 -o /tmp/ref.exr
# REPETITIONS seeds (default 9, from 301), 2 threads; CAUSTICA defaults to build/caustica.
set -euo pipefail
export LC_ALL=C
cd "$(dirname "$0")/.."
CAUSTICA=${CAUSTICA:-build/caustica}
REPETITIONS=${REPETITIONS:-9}
scene=$1
reference=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for ((seed = 301; seed < 301 + REPETITIONS; ++seed)); do
    for spec in "$@"; do
        integrator=${spec%%:*}
        spp=${spec##*:}
        start=$(date +%s.%N)
        "$CAUSTICA" render "$scene" --integrator "$integrator" --spp "$spp" --seed "$seed" --threads 2 -q \
            -o "$tmp/render.exr" > /dev/null 2>&1
        end=$(date +%s.%N)
        relmse=$("$CAUSTICA" diff "$tmp/render.exr" "$reference" | awk '$1 == "relmse" { print $2 }')
        echo "$spec $(echo "$end - $start" | bc -l) $relmse" >> "$tmp/runs"
    done
done

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "| integrator:spp | seconds | relMSE | relMSE x seconds |"
echo "| --- | ---: | ---: | ---: |"
for spec in "$@"; do
    seconds=$(awk -v s="$spec" '$1 == s { print $2 }' "$tmp/runs" | median)
    relmse=$(awk -v s="$spec" '$1 == s { print $3 }' "$tmp/runs" | median)
    product=$(awk -v s="$spec" '$1 == s { print $2 * $3 }' "$tmp/runs" | median)
    printf '| %s | %.3f | %.3g | %.3g |\n' "$spec" "$seconds" "$relmse" "$product"
done
