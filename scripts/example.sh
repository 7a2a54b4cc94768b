#!/usr/bin/env bash
# Set-up, then the main job on the bundled example: the tool-centre path as text, and an SVG
# picture of programmed contour and tool-centre path (examples/pocket.svg).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/cli/cutcom run examples/pocket.mpf
./build/cli/cutcom run examples/pocket.mpf --format svg -o examples/pocket.svg
# A complete shop job: named tools from the control's tool table, work offsets, a mirrored frame,
# SAR in and out, a drilling cycle reported as not simulated.
job=examples/job
./build/cli/cutcom run $job/PLATE.MPF --tools $job/TO_INI.INI --offsets $job/UFR.INI --md MD22550=1 \
  --format svg -o $job/PLATE.svg
echo "pictures: examples/pocket.svg, examples/job/PLATE.svg"
