#!/usr/bin/env bash
# The training run of the profile-guided build (CUTCOM_PGO in CMakeLists.txt, run by
# scripts/setup.sh between its two builds): `cutcom run` on the bundled examples and on two
# generated serpentine passes (with CDOF and with CDON), in text, JSON and SVG. The passes are
# this script's own, unlike the benchmarks' contours: rows of lines, half-circle bumps, CR=
# dents, G91 steps, runs of tiny segments along a wide curve, feed and M words, joined by
# half circles. Usage: pgo_training.sh BUILD_DIR (its earlier profiles are removed first).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: pgo_training.sh BUILD_DIR}
cutcom="$build/cli/cutcom"
find "$build" -name '*.gcda' -delete
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# serpentine ROWS CDON: a pocket pass of ROWS rows 8 mm apart under G41 with a 0.5 mm tool.
serpentine() {
  awk -v rows="$1" -v cdon="$2" 'BEGIN {
    print "; cutcom PGO training pass (scripts/pgo_training.sh)"
    print "$TC_DP1[1,1]=120"
    print "$TC_DP6[1,1]=0.5"
    print "N10 G17 G90 G71 G450 T1 D1 F1000 S3000 M3" (cdon ? " CDON" : "")
    print "G0 X-5 Y0"
    print "G41 G1 X0 Y0"
    n = 20
    x = 0
    for (j = 0; j < rows; j++) {
      y = 8 * j
      dir = (j % 2 == 0) ? 1 : -1
      printf "N%d G1 F%d\n", n += 10, (j % 3 == 0) ? 800 : 1200
      for (c = 0; c < 4; c++) {
        x += 2 * dir; printf "G1 X%.4f Y%.4f\n", x, y
        # a half circle of radius 1 below the row (the tool inside it out, outside it back)
        x += 2 * dir; printf "%s X%.4f Y%.4f I%d J0\n", (dir > 0) ? "G3" : "G2", x, y, dir
        x += 1 * dir; printf "G1 X%.4f Y%.4f\n", x, y
        # two steps of a small peak, written incrementally
        printf "G91 G1 X%.4f Y0.2\n", 0.8 * dir
        printf "G1 X%.4f Y-0.2\n", 0.8 * dir
        printf "G90\n"
        x += 1.6 * dir
        # a shallow dent of radius 5 by CR=
        x += 2 * dir; printf "%s X%.4f Y%.4f CR=5\n", (dir > 0) ? "G3" : "G2", x, y
        if (c == 1) print "M8"
        # tiny segments along a shallow curve below the row (radius about 5) back to the row
        for (i = 1; i <= 24; i++) {
          t = i / 24
          printf "G1 X%.4f Y%.4f\n", x + 1.2 * t * dir, y - 0.15 * t * (1 - t)
        }
        x += 1.2 * dir
      }
      print "M9"
      # the turn to the next row: a half circle of radius 4 around the row end
      if (j < rows - 1) printf "%s X%.4f Y%.4f I0 J4\n", (dir > 0) ? "G3" : "G2", x, y + 8
    }
    print "G40 G1 X" x " Y" (y - 5)
    print "M30"
  }'
}

serpentine 250 0 >"$work/cdof.mpf"
serpentine 250 1 >"$work/cdon.mpf"
for program in "$work/cdof.mpf" "$work/cdon.mpf"; do
  "$cutcom" run "$program" -o /dev/null
  "$cutcom" run "$program" --format json -o /dev/null
done
"$cutcom" run "$work/cdon.mpf" --format svg -o /dev/null
"$cutcom" run "$work/cdof.mpf" --format json --trace -o /dev/null

# The examples, as a user runs them (some end in an alarm on purpose: that is their point).
for program in examples/*.mpf; do
  "$cutcom" run "$program" -o /dev/null || true
done
"$cutcom" run examples/job/PLATE.MPF --tools examples/job/TO_INI.INI --offsets examples/job/UFR.INI \
  --md MD22550=1 -o /dev/null || true
echo "pgo_training: $(find "$build" -name '*.gcda' | wc -l) profiles written"
