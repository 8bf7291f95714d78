#!/usr/bin/env bash
# Compares the rendering speed of two commits on this machine in one run: checks each out into a
# temporary git worktree, builds its caustica in Release, and runs scripts/bench-scenes.sh (of
# the current checkout, so both render the same scene files) with the two binaries interleaved.
# The worktrees are removed on exit, also after a failure.
set -euo pipefail

usage() {
    cat <<'EOF'
Usage: scripts/bench-commits.sh [--build-lock FILE] REV_A REV_B [bench-scenes.sh options]

Builds the caustica target of REV_A and REV_B (any git revision) in worktrees under /tmp and
benchmarks them with scripts/bench-scenes.sh, labelled with their short hashes; the ratios in the
table are REV_B over REV_A. Options after the revisions (--threads, --repetitions, --scenes,
--out) go to bench-scenes.sh. Two revisions naming the same commit are built once.

  --build-lock FILE   hold this flock(1) lock while building (to share a machine's cores)
  -h, --help          print this help and exit

Example: scripts/bench-commits.sh HEAD~1 HEAD --repetitions 5
EOF
}

lock=""
while [[ $# -gt 0 ]]; do
    case $1 in
        -h|--help) usage; exit 0 ;;
        --build-lock) [[ $# -ge 2 ]] || { echo "bench-commits.sh: --build-lock needs a file" >&2; exit 2; }
                      lock=$2; shift 2 ;;
        *) break ;;
    esac
done
[[ $# -ge 2 ]] || { usage >&2; exit 2; }
rev_a=$1 rev_b=$2
shift 2

repo=$(cd "$(dirname "$0")/.." && pwd)
commit_a=$(git -C "$repo" rev-parse --verify --short "$rev_a^{commit}")
commit_b=$(git -C "$repo" rev-parse --verify --short "$rev_b^{commit}")

worktrees=()
cleanup() {
    for dir in "${worktrees[@]}"; do
        git -C "$repo" worktree remove --force "$dir" 2>/dev/null || rm -rf "$dir"
    done
    git -C "$repo" worktree prune
}
trap cleanup EXIT

# Builds a commit's caustica and sets $built to its path. (Not run in a $(...) subshell, which
# would lose the worktree list that cleanup needs.)
build_commit() {
    local commit=$1 dir
    dir=$(mktemp -d "/tmp/caustica-bench-$commit-XXXXXX")
    worktrees+=("$dir")
    git -C "$repo" worktree add --detach --quiet "$dir" "$commit" >&2
    cmake -S "$dir" -B "$dir/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAUSTICA_BUILD_TESTS=OFF \
        -DCAUSTICA_BUILD_BENCHMARKS=OFF >"$dir/configure.log" ||
        { cat "$dir/configure.log" >&2; exit 1; }
    if [[ -n $lock ]]; then
        flock "$lock" cmake --build "$dir/build" --target caustica -j"$(nproc)" >&2
    else
        cmake --build "$dir/build" --target caustica -j"$(nproc)" >&2
    fi
    built=$dir/build/caustica
}

echo "building $commit_a ($rev_a)" >&2
build_commit "$commit_a"
binary_a=$built
if [[ $commit_b == "$commit_a" ]]; then
    echo "$rev_b is the same commit: using one build for both" >&2
    binary_b=$binary_a
else
    echo "building $commit_b ($rev_b)" >&2
    build_commit "$commit_b"
    binary_b=$built
fi

label_a=$commit_a label_b=$commit_b
if [[ $label_a == "$label_b" ]]; then label_a=A-$commit_a label_b=B-$commit_b; fi
"$repo/scripts/bench-scenes.sh" "$@" --label "$label_a" "$binary_a" --label "$label_b" "$binary_b"
