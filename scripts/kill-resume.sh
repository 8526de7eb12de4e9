#!/usr/bin/env bash
# Kill -9 `rolldyn run` at random moments, N times (default 20),
# alternating ROS34PW2 and DOPRI5; after each kill the run directory must
# hold a readable time series (rolldyn spectrum reads it) and
# `rolldyn run --resume` must finish with a time series whose part files
# are byte-identical to the uninterrupted run's and the same summary
# (wall time aside).
# Usage: scripts/kill-resume.sh [N]   (release build; a few minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20}
cargo build --release -q -p rolldyn-cli
bin=$PWD/target/release/rolldyn
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
strip_wall() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d.pop("wall_time_s"); print(json.dumps(d, sort_keys=True))' "$1"; }
declare -A reference
for integrator in ros34pw2 dopri5; do
  duration=0.15; [ "$integrator" = dopri5 ] && duration=0.01
  "$bin" run -o "$work/ref-$integrator" --duration "$duration s" --set "solver.integrator=\"$integrator\"" >/dev/null
  reference[$integrator]=$duration
done
ok=0
for i in $(seq 1 "$runs"); do
  integrator=ros34pw2; [ $((i % 2)) -eq 0 ] && integrator=dopri5
  duration=${reference[$integrator]}
  dir="$work/run-$i"
  "$bin" run -o "$dir" --duration "$duration s" --set "solver.integrator=\"$integrator\"" \
      --checkpoint-interval "0.05 s" >/dev/null 2>&1 &
  pid=$!
  # A random moment within the run's first ~0.9 s (release: the runs take ~1 s).
  sleep "0.$(printf '%03d' $((RANDOM % 900 + 50)))"
  if kill -9 "$pid" 2>/dev/null; then killed=yes; else killed="no (finished first)"; fi
  wait "$pid" 2>/dev/null || true
  if [ -d "$dir/timeseries.parquet" ]; then
    "$bin" spectrum "$dir" --list >/dev/null 2>&1 \
      || { echo "run $i: time series after the kill not readable"; exit 1; }
  fi
  if [ -f "$dir/checkpoint.bin" ] && ! grep -q '"completed"' "$dir/summary.json" 2>/dev/null; then
    "$bin" run --resume "$dir" >/dev/null
  elif [ ! -f "$dir/summary.json" ] || ! grep -q '"completed"' "$dir/summary.json"; then
    # Killed before its first checkpoint: nothing to resume; start again.
    "$bin" run -o "$dir" --duration "$duration s" --set "solver.integrator=\"$integrator\"" >/dev/null
  fi
  diff -r -q "$dir/timeseries.parquet" "$work/ref-$integrator/timeseries.parquet" >/dev/null \
    || { echo "run $i ($integrator): resumed time series differs"; exit 1; }
  [ "$(strip_wall "$dir/summary.json")" = "$(strip_wall "$work/ref-$integrator/summary.json")" ] \
    || { echo "run $i ($integrator): resumed summary differs"; exit 1; }
  echo "run $i ($integrator): killed $killed; resumed bit-identical"
  ok=$((ok + 1))
done
echo "$ok of $runs runs: readable after the kill, resumed bit-identical"
