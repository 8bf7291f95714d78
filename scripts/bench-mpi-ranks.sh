#!/usr/bin/env bash
# Wall time of one render against the number of MPI ranks (docs/benchmarks.md, "MPI"), taking
# turns in every round: one process on 1 and on 2 threads, then `mpirun -np N` with one thread
# per rank for each N given. Prints "integrator configuration seconds" lines; take the medians.
set -euo pipefail
usage() {
    cat <<'USAGE'
Usage: scripts/bench-mpi-ranks.sh CAUSTICA [ROUNDS] [RANKS...]
  CAUSTICA  the binary (built with MPI); ROUNDS: 3 by default; RANKS: 2 4 by default.
Renders at 256x256: pt on scenes/cornell-box.pbrt (128 spp), vcm and sppm on
scenes/cornell-glass-sphere.pbrt (32 iterations). Ranks beyond the cores are oversubscribed.
USAGE
}
[[ $# -ge 1 && $1 != -h && $1 != --help ]] || { usage; exit 2; }
caustica=$(realpath "$1")
rounds=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
ranks=("$@")
[[ ${#ranks[@]} -gt 0 ]] || ranks=(2 4)
repo=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Open MPI refuses to run as root unless told (CI containers run as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

seconds() {
    local start end
    start=$(date +%s%N)
    "$@" > /dev/null 2>&1
    end=$(date +%s%N)
    local ms=$(( (end - start) / 1000000 ))
    printf '%d.%03d\n' $((ms / 1000)) $((ms % 1000))
}

for case in "pt cornell-box 128" "vcm cornell-glass-sphere 32" "sppm cornell-glass-sphere 32"; do
    read -r integrator scene spp <<< "$case"
    args=(render "$repo/scenes/$scene.pbrt" --integrator "$integrator" --spp "$spp" --resolution 256x256 -q
          -o "$out/image.exr")
    for ((round = 1; round <= rounds; ++round)); do
        echo "$integrator threads1 $(seconds "$caustica" "${args[@]}" --threads 1)"
        echo "$integrator threads2 $(seconds "$caustica" "${args[@]}" --threads 2)"
        for n in "${ranks[@]}"; do
            echo "$integrator np$n $(seconds mpirun --oversubscribe -np "$n" "$caustica" "${args[@]}" --threads 1)"
        done
    done
done
