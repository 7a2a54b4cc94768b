#!/usr/bin/env bash
# The mutation score of the certification (docs/certification.md, "Mutants"): each patch in
# mutants/ is one realistic change of fast, applied alone to this checkout, built, and judged
# first by a 20,000-case campaign against the knife-edge baseline (PROP-BOUNDARY-1, PROP-DIFF-1,
# PROP-KNIFE-1: the quickest killer), then, if it survives, by the CI properties (ctest -L props).
# Prints one Markdown row per mutant (killed / survived, the killing check, seconds to kill) and
# the score. Usage: scripts/mutants.sh [mutants/NN-name.patch ...]   (default: all; BUILD=dir;
# CAMPAIGN_ONLY=1: the campaign alone, a survivor marked so, about a minute per mutant).
# A patch that no longer applies (fast changed around it) is regenerated: make the one-line
# change by hand, then `git diff fast > patch` under its "Mutant:" line; ctest MutantsApply checks.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
campaign_only=${CAMPAIGN_ONLY:-0}
targets="cutcom prop_tests"
[ "$campaign_only" = 1 ] && targets=cutcom
if [ $# -gt 0 ]; then patches=("$@"); else patches=(mutants/*.patch); fi
if ! git diff --quiet -- fast; then
  echo "mutants.sh: fast/ has uncommitted changes; commit or stash them first" >&2
  exit 2
fi
current=""
trap '[ -n "$current" ] && git apply -R "$current" 2>/dev/null; exit 130' INT TERM
log=$(mktemp -d)
killed=0
total=0
echo "| mutant | what it changes | verdict | killed by | seconds |"
echo "|---|---|---|---|---|"
for p in "${patches[@]}"; do
  name=$(basename "$p" .patch)
  what=$(head -1 "$p" | sed 's/^Mutant: //')
  if ! git apply --check "$p" 2>/dev/null; then
    echo "| $name | $what | does not apply | | |"
    continue
  fi
  git apply "$p"
  current=$p
  total=$((total + 1))
  start=$(date +%s)
  verdict=survived
  by=""
  if ! cmake --build "$build" -j"$(nproc)" --target $targets >"$log/build" 2>&1; then
    verdict=killed
    by="does not build"
  elif ! "$build/cli/cutcom" certify --seed 20261201 --cases 20000 --budget 60 --no-progress \
    --knife-baseline tests/knife-edges.json >"$log/campaign" 2>&1; then
    verdict=killed
    by="campaign: $(grep -m1 -E 'unexplained divergence:|knife edges rose' "$log/campaign" | cut -c1-160 | tr '|' '/')"
  elif [ "$campaign_only" = 1 ]; then
    verdict="survived the campaign"
    by="(properties not run)"
  elif ! (cd "$build" && ctest -L props -E KnifeEdgeWatch -j"$(nproc)" >"$log/props" 2>&1); then
    verdict=killed
    by="properties: $(grep -E '^\s+[0-9]+ - ' "$log/props" | sed 's/^ *[0-9]* - //; s/ (Failed)//' | head -3 | tr '\n' ' ')"
  fi
  seconds=$(($(date +%s) - start))
  git apply -R "$p"
  current=""
  [ "$verdict" = killed ] && killed=$((killed + 1))
  echo "| $name | $what | $verdict | $by | $seconds |"
done
cmake --build "$build" -j"$(nproc)" --target $targets >"$log/build" 2>&1
echo
echo "score: $killed of $total mutants killed"
rm -rf "$log"
