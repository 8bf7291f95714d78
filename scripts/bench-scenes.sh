#!/usr/bin/env bash
# End-to-end benchmark: renders a fixed list of shipped scenes at fixed sample counts with one or
# more caustica binaries and writes a results table, so that two builds (two commits) can be
# compared on the same machine in one run. The binaries take turns run by run (A B, then B A) and
# every run is repeated, so slow drift of the machine (other load, clock changes) falls on all of
# them alike; the table reports medians over the repetitions and each binary's ratio to the
# first. Speed is only meaningful as such a ratio measured in one run on one machine.
set -euo pipefail
export LC_ALL=C # decimal points in the numbers read and written

usage() {
    cat <<'EOF'
Usage: scripts/bench-scenes.sh [options] [--label NAME] CAUSTICA [[--label NAME] CAUSTICA ...]

Renders each benchmark scene with each CAUSTICA binary, interleaved run by run, and writes
  OUT/runs.csv      one row per render
  OUT/summary.csv   medians per scene and binary, ratios to the first binary
  OUT/summary.md    the same as a Markdown table (also printed)
Each run records wall seconds of the render (from --stats-json), seconds of the whole process
(parsing and scene building included), rays per second, peak memory, and the relative MSE
against the stored reference image where tests/data/renderer has one (from `caustica diff`).
Every render uses the same seed, so a binary's images are the same in every repetition.

Options:
  --label NAME        name of the binary that follows (default: A, B, C, ...)
  --threads N         render threads (default 2)
  --repetitions N     renders per scene and binary (default 3)
  --scenes ID,ID,...  only these benchmark scenes (default: all; see --list)
  --out DIR           output directory (default out/bench-YYYYmmdd-HHMMSS)
  --list              print the benchmark scenes and exit
  -h, --help          print this help and exit

Example: scripts/bench-scenes.sh --label before build-a/caustica --label after build-b/caustica
EOF
}

repo=$(cd "$(dirname "$0")/.." && pwd)

# id | scene file | integrator | samples per pixel | reference image (- for none).
# The sample counts make each render take one to three seconds on one core of a 2020s desktop:
# long enough that process start-up and timer noise stay small, short enough for a full run of
# two binaries with three repetitions to take a few minutes.
# The references are the path tracer's converged renders of the same scene at the same
# resolution (scripts/make-references.sh); every integrator converges to them.
scene_table() {
    cat <<'EOF'
cornell-pt|scenes/cornell-box.pbrt|pt|32|tests/data/renderer/cornell-box.pt-4096spp.exr
cornell-bdpt|scenes/cornell-box.pbrt|bdpt|8|tests/data/renderer/cornell-box.pt-4096spp.exr
glass-caustic-vcm|scenes/glass-sphere-caustic.pbrt|vcm|4|-
glass-caustic-bdpt|scenes/glass-sphere-caustic.pbrt|bdpt|4|-
prism-dispersion-pt|scenes/prism-dispersion.pbrt|pt|8|-
transport-prism-bdpt|scenes/transport/prism.pbrt|bdpt|64|tests/data/renderer/transport/prism.pt-8192spp.exr
fog-block-pt|scenes/transport/fog-block.pbrt|pt|128|tests/data/renderer/transport/fog-block.pt-8192spp.exr
fog-block-vcm|scenes/transport/fog-block.pbrt|vcm|64|tests/data/renderer/transport/fog-block.pt-8192spp.exr
EOF
}

die() { echo "bench-scenes.sh: $*" >&2; exit 2; }

threads=2 repetitions=3 only="" out="" labels=() binaries=() next_label=""
while [[ $# -gt 0 ]]; do
    case $1 in
        -h|--help) usage; exit 0 ;;
        --list) scene_table | column -t -s'|'; exit 0 ;;
        --label) [[ $# -ge 2 ]] || die "--label needs a name"; next_label=$2; shift 2 ;;
        --threads) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--threads needs a positive integer"; threads=$2; shift 2 ;;
        --repetitions) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--repetitions needs a positive integer"; repetitions=$2; shift 2 ;;
        --scenes) [[ $# -ge 2 ]] || die "--scenes needs a list"; only=$2; shift 2 ;;
        --out) [[ $# -ge 2 ]] || die "--out needs a directory"; out=$2; shift 2 ;;
        -*) die "unknown option $1 (see --help)" ;;
        *)
            [[ -x $1 && -f $1 ]] || die "$1 is not an executable file"
            binaries+=("$(cd "$(dirname "$1")" && pwd)/$(basename "$1")")
            default_labels=ABCDEFGHIJKLMNOPQRSTUVWXYZ
            labels+=("${next_label:-${default_labels:${#labels[@]}:1}}")
            next_label=""
            shift ;;
    esac
done
[[ -z $next_label ]] || die "--label $next_label names no binary"
[[ ${#binaries[@]} -ge 1 ]] || { usage >&2; exit 2; }
if [[ $(printf '%s\n' "${labels[@]}" | sort | uniq -d) ]]; then die "labels must differ"; fi
for label in "${labels[@]}"; do [[ $label =~ ^[A-Za-z0-9._-]+$ ]] || die "label \"$label\" may hold only letters, digits, '.', '_' and '-'"; done

mapfile -t scenes < <(scene_table)
if [[ -n $only ]]; then
    selected=()
    IFS=',' read -ra wanted <<<"$only"
    for id in "${wanted[@]}"; do
        match=$(printf '%s\n' "${scenes[@]}" | grep "^$id|" || true)
        [[ -n $match ]] || die "no benchmark scene \"$id\" (see --list)"
        selected+=("$match")
    done
    scenes=("${selected[@]}")
fi

out=${out:-out/bench-$(date +%Y%m%d-%H%M%S)}
mkdir -p "$out"
out=$(cd "$out" && pwd)
runs=$out/runs.csv
echo "label,scene,integrator,spp,repetition,wall_seconds,process_seconds,rays_per_second,peak_memory_mib,relmse" >"$runs"
{
    echo "date: $(date -Iseconds)"
    echo "host: $(uname -n), $(nproc) cores, threads $threads, repetitions $repetitions"
    for i in "${!binaries[@]}"; do echo "${labels[$i]}: ${binaries[$i]}"; done
} >"$out/setup.txt"

# One render; appends its row to runs.csv.
run_one() {
    local label=$1 binary=$2 id=$3 scene=$4 integrator=$5 spp=$6 reference=$7 rep=$8
    local image=$out/images/$label-$id.exr stats=$out/stats/$label-$id-$rep.json
    local start end relmse=""
    start=$(date +%s.%N)
    (cd "$repo" && "$binary" render "$scene" --integrator "$integrator" --spp "$spp" --threads "$threads" \
        --seed 1 --quiet -o "$image" --stats-json "$stats") ||
        die "$label failed to render $id (see its messages above)"
    end=$(date +%s.%N)
    if [[ $reference != - ]]; then
        relmse=$("$binary" diff "$image" "$repo/$reference" | awk '$1 == "relmse" { print $2 }')
    fi
    # --stats-json writes one "key": value pair per line.
    local wall rays memory
    wall=$(sed -n 's/.*"wall_seconds": \([^,]*\),*/\1/p' "$stats")
    rays=$(sed -n 's/.*"rays_per_second": \([^,]*\),*/\1/p' "$stats")
    memory=$(sed -n 's/.*"peak_memory_mib": \([^,]*\),*/\1/p' "$stats")
    echo "$label,$id,$integrator,$spp,$rep,$wall,$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'),$rays,$memory,$relmse" >>"$runs"
    printf '%-10s %-22s rep %d: %8.3f s\n' "$label" "$id" "$rep" "$wall" >&2
}

# Odd repetitions run the binaries in the given order, even ones in reverse (A B, B A, A B, ...),
# so that running first or second (a warmer cache, the other jobs' rhythm) favours none of them.
mkdir -p "$out/images" "$out/stats"
for ((rep = 1; rep <= repetitions; ++rep)); do
    order=("${!binaries[@]}")
    if ((rep % 2 == 0)); then mapfile -t order < <(printf '%s\n' "${order[@]}" | tac); fi
    for row in "${scenes[@]}"; do
        IFS='|' read -r id scene integrator spp reference <<<"$row"
        for i in "${order[@]}"; do
            run_one "${labels[$i]}" "${binaries[$i]}" "$id" "$scene" "$integrator" "$spp" "$reference" "$rep"
        done
    done
done

# Medians over the repetitions, and the ratio of each binary's median to the first binary's.
python3 - "$runs" "$out" "${labels[0]}" <<'EOF'
import csv, statistics, sys

runs_path, out, first = sys.argv[1:]
rows = list(csv.DictReader(open(runs_path)))
scenes, labels, groups = [], [], {}
for r in rows:
    if r["scene"] not in scenes: scenes.append(r["scene"])
    if r["label"] not in labels: labels.append(r["label"])
    groups.setdefault((r["scene"], r["label"]), []).append(r)

metrics = ["wall_seconds", "process_seconds", "rays_per_second", "peak_memory_mib", "relmse"]
summary = []
for scene in scenes:
    medians = {}
    for label in labels:
        group = groups[(scene, label)]
        medians[label] = {m: statistics.median(float(r[m]) for r in group) if group[0][m] else None
                          for m in metrics}
    for label in labels:
        m, base = medians[label], medians[first]
        summary.append({"scene": scene, "label": label,
                        "integrator": groups[(scene, label)][0]["integrator"],
                        "spp": groups[(scene, label)][0]["spp"], **m,
                        "wall_ratio": m["wall_seconds"] / base["wall_seconds"],
                        "rays_per_second_ratio": m["rays_per_second"] / base["rays_per_second"]})

fields = ["scene", "integrator", "spp", "label", *metrics, "wall_ratio", "rays_per_second_ratio"]
with open(f"{out}/summary.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    for s in summary:
        w.writerow({k: ("" if s[k] is None else s[k]) for k in fields})

def num(v, fmt):
    return "-" if v is None else format(v, fmt)

lines = [f"| scene | integrator | spp | binary | render s | process s | Mrays/s | peak MiB | relMSE "
         f"| render s / {first} | rays/s / {first} |",
         "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|"]
for s in summary:
    lines.append(f"| {s['scene']} | {s['integrator']} | {s['spp']} | {s['label']} "
                 f"| {num(s['wall_seconds'], '.3f')} | {num(s['process_seconds'], '.3f')} "
                 f"| {num(s['rays_per_second'] / 1e6, '.2f')} | {num(s['peak_memory_mib'], '.0f')} "
                 f"| {num(s['relmse'], '.4g')} | {s['wall_ratio']:.3f} | {s['rays_per_second_ratio']:.3f} |")
open(f"{out}/summary.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
echo "results in $out" >&2
