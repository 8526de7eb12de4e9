#!/usr/bin/env bash
# Whether two builds of `rolldyn` write the same outputs: every command's
# standard output, and every file of a run directory (summary.json
# without its timings, run.json, the time series' values and report.html
# without its timings), for the default case (also from the
# traction-consistent start, and a quasi-static speed sweep), every
# example's case, a bearing set (examples/spindle_pair) and a shaft (rigid
# in motion, elastic quasi-statically). For a change that must not change results
# (a refactoring).
#
#   scripts/same-outputs.sh OLD_BINARY [NEW_BINARY] [DURATION]
#
# NEW_BINARY defaults to this work tree's release build; DURATION (default
# "2 ms") shortens the runs. Prints one line per output that differs and
# exits 1 if any does. Needs python3 with pyarrow or pandas to compare the
# Parquet datasets value by value (else their bytes are compared).
set -euo pipefail

[[ $# -ge 1 ]] || { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
old=$(realpath "$1")
root=$(git rev-parse --show-toplevel)
new=$(realpath "${2:-$root/target/release/rolldyn}")
duration=${3:-2 ms}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Both under the name `rolldyn` (usage lines name the program).
mkdir -p "$work/old-bin" "$work/new-bin"
cp "$old" "$work/old-bin/rolldyn"
cp "$new" "$work/new-bin/rolldyn"
old=$work/old-bin/rolldyn
new=$work/new-bin/rolldyn
differ=0

# Keys that measure the machine, not the model.
timings='wall_time|steps_per_s|elapsed|_seconds_wall|wall_s'

normalise_json() {
    python3 - "$1" "$timings" <<'EOF'
import json, re, sys
path, timings = sys.argv[1], re.compile(sys.argv[2])
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items() if not timings.search(k)}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
try:
    print(json.dumps(clean(json.load(open(path))), sort_keys=True, indent=1))
except ValueError:
    print(open(path).read())
EOF
}

dataset_values() {
    python3 - "$1" <<'EOF' 2>/dev/null || cat "$1"/*.parquet | md5sum
import sys
import pyarrow.dataset as ds
t = ds.dataset(sys.argv[1], format="parquet").to_table()
print(t.schema)
for c in t.column_names:
    print(c, t.column(c).to_pylist())
EOF
}

compare() { # label, old file, new file
    if ! cmp -s "$2" "$3"; then
        echo "differs: $1"
        diff "$2" "$3" | head -6 | cut -c1-240 || true
        differ=1
    fi
}

command_pair() { # label, arguments...
    local label=$1
    shift
    (cd "$work" && "$old" "$@" > "$work/old.out" 2>&1 || true)
    (cd "$work" && "$new" "$@" > "$work/new.out" 2>&1 || true)
    sed -E 's/[0-9.]+ ?(s|ms) wall|in [0-9.]+ s//g' "$work/old.out" > "$work/old.txt"
    sed -E 's/[0-9.]+ ?(s|ms) wall|in [0-9.]+ s//g' "$work/new.out" > "$work/new.txt"
    compare "$label (stdout)" "$work/old.txt" "$work/new.txt"
}

run_pair() { # label, case path, extra arguments...
    local label=$1 case=$2
    shift 2
    for build in old new; do
        local bin=$old
        [[ $build == new ]] && bin=$new
        rm -rf "$work/$build"
        "$bin" run "$case" --duration "$duration" -o "$work/$build" --report "$@" > /dev/null 2>&1 || true
    done
    for f in summary.json run.json; do
        if [[ -f $work/old/$f || -f $work/new/$f ]]; then
            normalise_json "$work/old/$f" > "$work/a" 2>/dev/null || true
            normalise_json "$work/new/$f" > "$work/b" 2>/dev/null || true
            compare "$label $f" "$work/a" "$work/b"
        fi
    done
    for d in timeseries.parquet timeseries_slow.parquet; do
        if [[ -d $work/old/$d || -d $work/new/$d ]]; then
            dataset_values "$work/old/$d" > "$work/a"
            dataset_values "$work/new/$d" > "$work/b"
            compare "$label $d" "$work/a" "$work/b"
        fi
    done
    if [[ -f $work/old/report.html ]]; then
        local wall='<tr><td>[^<]*</td><td>[^<]*</td>(<td>)?wall_time_s[^<]*</td></tr>|<tr><td>wall_time_s[^<]*</td><td>[^<]*</td></tr>'
        sed -E "s#$wall##g" "$work/old/report.html" > "$work/a"
        sed -E "s#$wall##g" "$work/new/report.html" > "$work/b"
        compare "$label report.html" "$work/a" "$work/b"
    fi
    command_pair "$label spectrum" spectrum "$work/new" --json
}

cd "$root"
"$new" new > "$work/default.toml"
run_pair "default case" "$work/default.toml"
# A shaft: two 6206 under a gear force (as the tests' shaft).
cat > "$work/shaft.toml" <<'CASE'
[operating]
speed = "3000 rpm"
[shaft]
[[shaft.bearings]]
preset = "6206"
position = "-60 mm"
[[shaft.bearings]]
preset = "6206"
position = "60 mm"
[[shaft.loads]]
position = "20 mm"
force_z = "-4 kN"
force_x = "300 N"
CASE
run_pair "shaft" "$work/shaft.toml"
command_pair "shaft quasistatic" quasistatic "$work/shaft.toml" --json
command_pair "shaft power" power "$work/shaft.toml" --json
command_pair "elastic shaft quasistatic" quasistatic "$work/shaft.toml" --set 'shaft.diameter="30 mm"' --json
run_pair "traction-consistent start" "$work/default.toml" --set solver.start=quasistatic_traction
command_pair "quasistatic speed sweep" quasistatic "$work/default.toml" --sweep "speed=5000rpm,10000rpm,15000rpm" --json
for c in examples/*/case.toml; do
    run_pair "$c" "$c"
done
for c in examples/*/case.toml; do
    command_pair "$c check" check "$root/$c" --json
    command_pair "$c quasistatic" quasistatic "$root/$c" --json
    command_pair "$c power" power "$root/$c" --json
    command_pair "$c thermal" thermal "$root/$c" --json
done
command_pair "frequencies" frequencies
command_pair "traction" traction --json
command_pair "presets" presets

if [[ $differ == 0 ]]; then
    echo "same outputs: $1 and ${2:-the release build of this work tree}"
fi
exit $differ
