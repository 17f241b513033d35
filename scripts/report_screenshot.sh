#!/usr/bin/env bash
# Regenerates docs/report.png: the run report of the pick-and-place cell, taken in
# headless Chromium at 1400x1800 (the top of the page: header, 3D path, axis plots).
# Needs /usr/bin/chromium (Debian: apt-get install chromium).
set -euo pipefail

cd "$(dirname "$0")/.."

browser=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$browser" ]; then
    echo "error: $browser not found (install chromium or set CHROMIUM)" >&2
    exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cargo run -q -p rapid-cli -- run --quiet --home "$work/home" \
    --stimulus examples/pick_and_place_cell/parts.stim \
    --report "$work/report.html" examples/pick_and_place_cell >/dev/null

"$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$work/profile" --hide-scrollbars --window-size=1400,1800 \
    --virtual-time-budget=5000 --screenshot="$PWD/docs/report.png" \
    "file://$work/report.html" 2>/dev/null

echo "wrote docs/report.png"
