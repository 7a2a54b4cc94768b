#!/usr/bin/env bash
# Set-up, then the main job on the bundled example: the tool-centre path as text, and an SVG
# picture of programmed contour and tool-centre path (examples/pocket.svg).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/cli/cutcom run examples/pocket.mpf
./build/cli/cutcom run examples/pocket.mpf --format svg -o examples/pocket.svg
echo "picture: examples/pocket.svg"
