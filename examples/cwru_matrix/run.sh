#!/bin/sh
# The CWRU drive-end test matrix as a labelled dataset (one command):
#   sh examples/cwru_matrix/run.sh [OUT]
# healthy; outer-race pits at 6, 3 and 12 o'clock; inner-race and ball
# pits; 0.007, 0.014 and 0.021 in; 0-3 hp (1797-1730 rpm): 64 runs of
# examples/cwru6205/case.toml, each a run directory with its signals, then
# each point's envelope spectrum and OUT/features.csv (one labelled row per
# run). See README.md.
set -eu
OUT=${1:-examples/cwru_matrix/out}
# ROLLDYN (the command; default cargo's release build) and DURATION
# (default the case's 0.3 s) shorten it for the test suite.
R=${ROLLDYN:-cargo run --release --quiet --}
D=${DURATION:-0.3 s}
CASE=examples/cwru6205/case.toml
SPEEDS="speed=1797rpm,1772rpm,1750rpm,1730rpm"
SIZES="0.1778 mm,0.3556 mm,0.5334 mm"
NONE='surface.outer.spall=[]'
PIT='position = "0 deg", length = "0.1778 mm", depth = "0.2794 mm"'
$R run $CASE --duration "$D" --set "$NONE" --sweep "$SPEEDS" -o "$OUT/healthy"
$R run $CASE --duration "$D" --sweep "surface.outer.spall.0.position=270 deg,0 deg,90 deg" \
  --sweep "surface.outer.spall.0.length=$SIZES" --sweep "$SPEEDS" -o "$OUT/outer"
$R run $CASE --duration "$D" --set "$NONE" --set "surface.inner.spall=[{ $PIT }]" \
  --sweep "surface.inner.spall.0.length=$SIZES" --sweep "$SPEEDS" -o "$OUT/inner"
$R run $CASE --duration "$D" --set "$NONE" --set "surface.balls.spall=[{ ball = 0, $PIT }]" \
  --sweep "surface.balls.spall.0.length=$SIZES" --sweep "$SPEEDS" -o "$OUT/ball"
for point in "$OUT"/*/point-*; do
  $R spectrum "$point" --channel sensor_acceleration_m_s2 --kind envelope \
    --band "1200:4800 Hz" --json > /dev/null
done
python3 examples/cwru_matrix/features.py "$OUT"
