#!/usr/bin/env bash
# The accuracy table of docs/catalogue.md: `rolldyn new --bearing` cases
# run at their defaults with `--verify`, one row per bearing.
#   scripts/catalogue-accuracy.sh [ROLLDYN] [BEARING...]
# ROLLDYN defaults to target/release/rolldyn (build it first with
# `cargo build --release`).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/rolldyn}
shift || true
bearings=("$@")
if [ ${#bearings[@]} -eq 0 ]; then
  bearings=(6000 6020 6205 6300 6320 7000C 7020A 7210B 7320AC)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| bearing (load) | run wall [s] | steps | energy balance | mean cage speed [rpm] | dissipated power [W] | largest changes under \`--verify\` | verify |"
echo "|---|---|---|---|---|---|---|---|"
for b in "${bearings[@]}"; do
  "$bin" new --bearing "$b" > "$work/$b.toml"
  "$bin" run "$work/$b.toml" -o "$work/$b" --verify > /dev/null 2>&1 || true
  python3 - "$work/$b/summary.json" "$work/$b.toml" "$b" <<'EOF'
import json, re, sys
s = json.load(open(sys.argv[1]))
case = open(sys.argv[2]).read()
load = re.search(r'^(force_[xz]) = "([^"]+)"', case, re.M)
v = s["accuracy"]["verify"]
changes = sorted(v["changes"], key=lambda c: -c["relative_change"] / c["limit"])
top = ", ".join(f'{c["key"]} {100 * c["relative_change"]:.2f} %' for c in changes[:2])
print(f'| {sys.argv[3]} ({load.group(1).replace("force_", "F_")} {load.group(2)}) '
      f'| {s["wall_time_s"]:.1f} | {s["steps"]} '
      f'| {s["energy_balance_relative_error"]:.1e} | {s["mean_cage_speed_rpm"]:.1f} '
      f'| {s["mean_dissipated_power_w"]:.3g} | {top} | {v["status"]} |')
EOF
done
