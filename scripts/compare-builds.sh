#!/usr/bin/env bash
# Wall time of one `rolldyn run` with this work tree's build against
# another commit's, alternating, in one session: the ratio is what a
# noisy machine still measures (docs/performance.md).
#
#   scripts/compare-builds.sh [--instructions] REF [PAIRS] -- RUN_ARGUMENTS...
#
# REF is any commit name git understands; PAIRS (default 3) how many
# runs of each build, alternating. RUN_ARGUMENTS are those of `rolldyn
# run` without `-o`, e.g.
#
#   scripts/compare-builds.sh eac2172 3 -- - --duration "1 s" < <(rolldyn new)
#   scripts/compare-builds.sh HEAD~5 -- examples/spindle_pair/case.toml
#
# Run from anywhere in the repository (paths in RUN_ARGUMENTS are taken
# from where it is run). A case read from standard input is read once
# and given to every run.
# REF's build is kept in target/compare/ (one binary per commit); each
# run writes to a temporary directory, removed at the end. Prints each
# run's wall time and step count, the medians and their ratio, and
# whether the two builds' summaries agree apart from the timings and
# the right-hand-side counts.
# With --instructions, each build runs once on one thread under
# valgrind's callgrind (needs valgrind) and the instructions it executed
# are compared instead: a count the machine's speed does not move (up to
# the few syncs a run makes by the clock), for changes of a few percent;
# PAIRS is then ignored.
set -euo pipefail

usage() {
    sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
}

instructions=false
if [[ ${1:-} == --instructions ]]; then
    instructions=true
    shift
    command -v valgrind > /dev/null || {
        echo "--instructions needs valgrind (callgrind), which is not installed" >&2
        exit 2
    }
fi
[[ $# -ge 2 ]] || usage
ref=$1
shift
pairs=3
if [[ $1 != -- ]]; then
    pairs=$1
    shift
fi
[[ ${1:-} == -- ]] || usage
shift
[[ $pairs =~ ^[1-9][0-9]*$ ]] || {
    echo "PAIRS must be a whole number ≥ 1, got '$pairs'" >&2
    exit 2
}

root=$(git rev-parse --show-toplevel)
sha=$(git rev-parse --verify --quiet --short=12 "$ref^{commit}") || {
    echo "REF '$ref' is not a commit of this repository" >&2
    exit 2
}
work=$(mktemp -d)
trap 'git -C "$root" worktree remove --force "$work/tree" 2>/dev/null || true; rm -rf "$work"; git -C "$root" worktree prune' EXIT

old="$root/target/compare/rolldyn-$sha"
if [[ ! -x $old ]]; then
    echo "building $sha (once; kept in $old)" >&2
    git -C "$root" worktree add --detach --quiet "$work/tree" "$sha"
    CARGO_TARGET_DIR="$root/target/compare/build" \
        cargo build --quiet --release --manifest-path "$work/tree/Cargo.toml" -p rolldyn-cli
    cp "$root/target/compare/build/release/rolldyn" "$old"
fi
echo "building the work tree" >&2
cargo build --quiet --release --manifest-path "$root/Cargo.toml" -p rolldyn-cli
new="$root/target/release/rolldyn"

# Standard input, if the case comes from it, is read once.
args=("$@")
for i in "${!args[@]}"; do
    if [[ ${args[$i]} == - ]]; then
        cat > "$work/case.toml"
        args[i]="$work/case.toml"
    fi
done

run() { # build label pair
    local out="$work/$2-$3"
    if $instructions; then
        RAYON_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$out.callgrind" \
            "$1" run "${args[@]}" -o "$out" > "$out.log" 2>&1 || true
    else
        "$1" run "${args[@]}" -o "$out" > "$out.log" 2>&1 || true
    fi
    grep -q '^completed:' "$out.log" || {
        echo "$2 run $3 did not complete:" >&2
        cat "$out.log" >&2
        exit 1
    }
    python3 - "$out" "$2" "$3" <<'EOF'
import json, os, sys
out = sys.argv[1]
s = json.load(open(out + "/summary.json"))
if os.path.exists(out + ".callgrind"):
    total = next(int(l.split()[1]) for l in open(out + ".callgrind") if l.startswith("summary:"))
    measure = f"{total:16,} instructions"
else:
    measure = f"{s['wall_time_s']:8.3f} s"
print(f"{sys.argv[2]:4} {int(sys.argv[3]):2}  {measure}  {s['steps']:8} steps")
EOF
}

if $instructions; then
    pairs=1 # one run each: the count does not scatter
    echo "     run      instructions                steps"
else
    echo "     run      wall        steps"
fi
for p in $(seq 1 "$pairs"); do
    run "$old" ref "$p"
    run "$new" new "$p"
done

python3 - "$work" "$sha" <<'EOF'
import json, pathlib, statistics, sys
work, sha = pathlib.Path(sys.argv[1]), sys.argv[2]
counts = {b: work / f"{b}-1.callgrind" for b in ("ref", "new")}
if counts["ref"].exists():
    n = {b: next(int(l.split()[1]) for l in p.open() if l.startswith("summary:"))
         for b, p in counts.items()}
    print(f"instructions: {sha} {n['ref']:,}, work tree {n['new']:,}, "
          f"ratio new/ref {n['new'] / n['ref']:.4f}")
else:
    med = {b: statistics.median(json.loads(d.joinpath("summary.json").read_text())["wall_time_s"]
                               for d in work.glob(f"{b}-*") if d.is_dir())
           for b in ("ref", "new")}
    print(f"median wall: {sha} {med['ref']:.3f} s, work tree {med['new']:.3f} s, "
          f"ratio new/ref {med['new'] / med['ref']:.3f}")
timing = {"wall_time_s", "rhs_evaluations", "jacobian_rhs_evaluations"}
def summary(build):
    data = json.loads((work / f"{build}-1" / "summary.json").read_text())
    def strip(v):
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items() if k not in timing}
        if isinstance(v, list):
            return [strip(x) for x in v]
        return v
    return strip(data)
same = summary("ref") == summary("new")
print("summaries apart from timings and RHS counts:", "identical" if same else "differ")
EOF
