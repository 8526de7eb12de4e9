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
# Tall enough for the whole page, from what it holds (a plot ~420 px, a
# table row ~30 px, a line of preformatted text ~16 px, headings and
# paragraphs), generously: blank below the page does no harm, a page cut
# short does. --virtual-time-budget lets layout finish.
count() { grep -o "$1" "$html" | wc -l; }
height=$(( 420 * $(count '<svg') + 30 * $(count '<tr>') + 16 * $(wc -l < "$html") + 80 * $(count '<h2') + 2000 ))
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --window-size="${width},${height}" --virtual-time-budget=2000 \
  --screenshot="$dir/report.png" "file://$html" 2>/dev/null
echo "wrote $dir/report.png (${width} × ${height} px)"
