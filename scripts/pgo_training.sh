#!/usr/bin/env bash
# The training run of the profile-guided build (CUTCOM_PGO in CMakeLists.txt, run by
# scripts/setup.sh between its two builds): `cutcom run` on two generated serpentine passes
# (with CDOF and with CDON) in text, JSON and SVG, on a parametric spiral, and on the bundled
# examples. The programs are this script's own, unlike the benchmarks' contours: rows of lines,
# half-circle bumps, CR= dents, G91 steps, runs of tiny segments along a shallow curve, feed and
# M words, joined by half circles; a WHILE loop with an IF. Usage: pgo_training.sh BUILD_DIR,
# a build configured with -DCUTCOM_PGO=generate (its earlier profiles are removed first).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: pgo_training.sh BUILD_DIR}
cutcom="$build/cli/cutcom"
if ! grep -q '^CUTCOM_PGO:STRING=generate$' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "pgo_training: $build is not configured with -DCUTCOM_PGO=generate (its profiles are kept)" >&2
  exit 2
fi
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

# A parametric program: a spiral of 3,000 blocks computed in a WHILE loop, with an IF.
cat >"$work/spiral.mpf" <<'EOF'
; cutcom PGO training: a parametric spiral (scripts/pgo_training.sh)
DEF INT KK=0
DEF REAL ANG, RR
$TC_DP1[1,1]=120
$TC_DP6[1,1]=1
N10 G17 G90 G71 T1 D1 F900
G0 X-20 Y-20
G41 G1 X-15 Y-15
WHILE KK<3000
  RR=10+0.01*KK
  ANG=KK*7.5
  IF KK==1500
    M8
  ENDIF
  G1 X=RR*COS(ANG) Y=RR*SIN(ANG)
  KK=KK+1
ENDWHILE
G40 G1 X-60 Y-60
M30
EOF
"$cutcom" run "$work/spiral.mpf" -o /dev/null

# The examples, as a user runs them, with the tool table and offsets beside them (some end in an
# alarm on purpose: that is their point).
find examples -iname '*.mpf' | sort | while read -r program; do
  dir=$(dirname "$program")
  options=()
  [[ -f "$dir/TO_INI.INI" ]] && options+=(--tools "$dir/TO_INI.INI")
  [[ -f "$dir/UFR.INI" ]] && options+=(--offsets "$dir/UFR.INI")
  [[ "$dir" == examples/job ]] && options+=(--md MD22550=1)           # T preselects, M6 changes
  [[ "$dir" == examples/turning ]] && options+=(--md 'MD20150[5]=2')  # a lathe's diameter axis
  "$cutcom" run "$program" "${options[@]}" -o /dev/null || true
done
echo "pgo_training: $(find "$build" -name '*.gcda' | wc -l) profiles written"
