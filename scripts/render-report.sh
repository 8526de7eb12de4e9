#!/usr/bin/env bash
# Renders DIR/report.html in headless Chromium to DIR/report.png for a
# look (the report needs no network and no script).
#   scripts/render-report.sh DIR [WIDTH]
# Installs Debian's chromium when it is missing (needs root and apt).
set -euo pipefail
dir=${1:?usage: scripts/render-report.sh DIR [WIDTH]}
width=${2:-1100}
html="$(cd "$dir" && pwd)/report.html"
[ -f "$html" ] || { echo "no $html: run \`rolldyn report $dir\` first" >&2; exit 2; }
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  apt-get install -y chromium >/dev/null
  browser=$(command -v chromium)
fi
# Tall enough for the whole page; --virtual-time-budget lets layout finish.
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --window-size="${width},9000" --virtual-time-budget=2000 \
  --screenshot="$dir/report.png" "file://$html" 2>/dev/null
echo "wrote $dir/report.png"
