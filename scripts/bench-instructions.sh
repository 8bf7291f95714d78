#!/usr/bin/env bash
# Counts the instructions each caustica binary executes on bench-scenes.sh's scenes, under
# valgrind's callgrind, on one thread. Wall times of sub-second renders on a shared machine drift
# by 10-30% from run to run; an instruction count is the same in every run, so a change of 1% is
# visible. It does not see cache misses, branch mispredictions or lock waits, so it complements
# the timed runs of bench-scenes.sh and does not replace them.
set -euo pipefail
export LC_ALL=C

usage() {
    cat <<'EOF'
Usage: scripts/bench-instructions.sh [--scenes ID,ID,...] [--label NAME] CAUSTICA [[--label NAME] CAUSTICA ...]

Renders every bench-scenes.sh scene (see scripts/bench-scenes.sh --list) with each binary on one
thread at a quarter of its sample count (at least 1), under `valgrind --tool=callgrind`, and prints
a Markdown table of instructions executed and each binary's ratio to the first. The renders use
seed 1, so a binary's count is the same in every run. Needs valgrind (Debian package valgrind).
EOF
}

die() { echo "bench-instructions.sh: $*" >&2; exit 2; }
repo=$(cd "$(dirname "$0")/.." && pwd)
command -v valgrind >/dev/null || die "valgrind is not installed (apt-get install valgrind)"

only="" labels=() binaries=() next_label=""
while [[ $# -gt 0 ]]; do
    case $1 in
        -h|--help) usage; exit 0 ;;
        --label) [[ $# -ge 2 ]] || die "--label needs a name"; next_label=$2; shift 2 ;;
        --scenes) [[ $# -ge 2 ]] || die "--scenes needs a list"; only=$2; shift 2 ;;
        -*) die "unknown option $1 (see --help)" ;;
        *)
            [[ -x $1 && -f $1 ]] || die "$1 is not an executable file"
            binaries+=("$(cd "$(dirname "$1")" && pwd)/$(basename "$1")")
            labels+=("${next_label:-$(basename "$1")}")
            next_label=""
            shift ;;
    esac
done
[[ ${#binaries[@]} -ge 1 ]] || { usage >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
header="| scene | integrator | spp |" rule="|---|---|---:|"
for label in "${labels[@]}"; do header+=" $label |"; rule+="---:|"; done
for label in "${labels[@]:1}"; do header+=" $label / ${labels[0]} |"; rule+="---:|"; done
echo "$header"
echo "$rule"
while read -r id scene integrator spp _; do
    [[ -z $only || ,$only, == *,$id,* ]] || continue
    spp=$((spp / 4 > 0 ? spp / 4 : 1))
    counts=()
    for i in "${!binaries[@]}"; do
        count=$(cd "$repo" && valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
            "${binaries[$i]}" render "$scene" --integrator "$integrator" --spp "$spp" --threads 1 \
            --seed 1 --quiet -o "$work/image.exr" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p')
        [[ -n $count ]] || die "${labels[$i]} failed to render $id"
        counts+=("$count")
    done
    row="| $id | $integrator | $spp |"
    for c in "${counts[@]}"; do row+=" $(awk -v c="$c" 'BEGIN { printf "%.4g G", c / 1e9 }') |"; done
    for c in "${counts[@]:1}"; do row+=" $(awk -v a="$c" -v b="${counts[0]}" 'BEGIN { printf "%.3f", a / b }') |"; done
    echo "$row"
done < <("$repo/scripts/bench-scenes.sh" --list)
