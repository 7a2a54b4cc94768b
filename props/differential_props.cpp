// fast agrees with ref (PROP-DIFF-1): same decisions unless ref's margin lies inside the band of
// that clause, then the same path within the tolerance scaled to the contour.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

// CUTCOM_SLOW_CASE=S prints every case that takes longer than S seconds (ref's exact arithmetic
// can be slow at exact degeneracies: this finds them).
void report_if_slow(const ContourCase& c, std::chrono::steady_clock::duration took) {
  static const char* limit = std::getenv("CUTCOM_SLOW_CASE");
  if (!limit || std::chrono::duration<double>(took).count() <= std::atof(limit)) return;
  std::cerr << "slow case (" << std::chrono::duration<double>(took).count() << " s):\n";
  showValue(c, std::cerr);
  std::cerr << "\n";
}

void check_agreement(const ContourCase& c) {
  RC_TAG(c.style);
  auto started = std::chrono::steady_clock::now();
  CaseRuns r = run_case(c, false);
  report_if_slow(c, std::chrono::steady_clock::now() - started);
  if (r.untraced) RC_FAIL(*r.untraced);  // PROP-TRACE-1
  Verdict v = compare(r.ref, r.fast, r.tolerance);
  if (r.ref_unsupported || r.fast_unsupported) {
    // TRC-UNSUP-1: both reject naming the same line, or one does after a knife edge.
    RC_TAG("not supported");
    if (r.ref_unsupported != r.fast_unsupported && v.kind != Verdict::Kind::kKnifeEdge)
      RC_FAIL("not supported at line " + std::to_string(r.ref_unsupported) + " (ref) / " +
              std::to_string(r.fast_unsupported) + " (fast); " + v.explanation);
    if (r.ref_unsupported == r.fast_unsupported) return;
  }
  RC_TAG(v.kind == Verdict::Kind::kKnifeEdge ? "knife-edge " + v.clause : "agreeing");
  RC_TAG(r.ref.alarms.empty() ? "no alarm" : "alarm " + std::to_string(r.ref.alarms[0].number));
  if (v.kind == Verdict::Kind::kDiverge) RC_FAIL(v.explanation);
}

// covers: PROP-DIFF-1 PROP-TRACE-1 TRC-CORNER-1 TRC-CORNER-3 TRC-CORNER-4 TRC-ELEMENT-1 TRC-G450-1 TRC-G451-1
// TRC-INNER-1
RC_GTEST_PROP(Differential, FastAgreesWithRefOnAnyContour, ()) { check_agreement(*any_contour()); }

// covers: PROP-DIFF-1 NC-CONTOUR-1 NC-POLAR-2 NC-FRAME-4 NC-GRID-1
RC_GTEST_PROP(Differential, FastAgreesWithRefOnContourDefinitions, ()) {
  ContourCase c = *contour_definitions();
  try {
    check_agreement(c);
  } catch (const InputError& e) {  // one reader for both engines: the same rejection
    RC_TAG("rejected by the reader");
    RC_CLASSIFY(std::string(e.what()).find("does not fit") != std::string::npos, "rounding does not fit");
  }
}

// covers: PROP-DIFF-1 TRC-CORNER-1
RC_GTEST_PROP(Differential, FastAgreesWithRefNearTangents, ()) { check_agreement(*near_tangent()); }

// covers: PROP-DIFF-1 TRC-CORNER-1 TRC-G450-3
RC_GTEST_PROP(Differential, FastAgreesWithRefNearReversals, ()) { check_agreement(*near_reversal()); }

// covers: PROP-DIFF-1 TRC-ELEMENT-1
RC_GTEST_PROP(Differential, FastAgreesWithRefOnVanishingElements, ()) { check_agreement(*notch()); }

// covers: PROP-HAIR-1 PROP-DIFF-1 TRC-CORNER-3 TRC-CORNER-4 TRC-KONT-1 TRC-KONT-2 TRC-ARC-CORNER-1 TRC-ELEMENT-1
RC_GTEST_PROP(Differential, FastAgreesWithRefInExactSituations, ()) { check_agreement(*exact_situations()); }

// covers: PROP-DIFF-1 TRC-ARC-EQ-1 TRC-ARC-CORNER-1 TRC-ARC-CORNER-2 TRC-ARC-ELEMENT-1 ARC-CENTRE-1
RC_GTEST_PROP(Differential, FastAgreesWithRefWithCircles, ()) { check_agreement(*with_circles()); }

// covers: PROP-DIFF-1 TRC-LOOK-1 TRC-LOOK-2 TRC-LOOK-3 MD-20240-1
RC_GTEST_PROP(Differential, FastAgreesWithRefOnTinyBlocks, ()) { check_agreement(*tiny_blocks()); }

// covers: PROP-DIFF-1 TRC-ARC-EQ-1 TRC-ARC-ELEMENT-1
RC_GTEST_PROP(Differential, FastAgreesWithRefOnCirclesNearTheToolRadius, ()) {
  check_agreement(*circles_near_radius());
}

// covers: PROP-DIFF-1 TRC-KONT-1 TRC-KONT-2 TRC-KONT-3 TRC-KONT-4 TRC-APPR-NORM-1 TRC-RETR-NORM-1 TRC-EDGE-1
// covers: TRC-EDGE-2 TRC-EDGE-3 TRC-EDGE-4 TRC-EDGE-5 TRC-EDGE-6
RC_GTEST_PROP(Differential, FastAgreesWithRefAtApproachAndRetraction, ()) {
  ContourCase c = *around_ends();
  // Which end rules the case reached (ref's trace), to show the generator reaches them.
  CaseRuns r = run_case(c, false);
  std::string reached = "NORM";
  for (const Decision& d : r.ref.decisions) {
    if (d.clause == "TRC-KONT-3" || d.clause == "TRC-KONT-4") reached = std::string(d.clause);
    if (d.clause == "TRC-EDGE-1") reached = "EDGE " + std::string(d.branch);
    if (d.clause == "TRC-EDGE-6") reached = "KONT around a short block, " + std::string(d.branch);
  }
  RC_TAG(reached);
  check_agreement(c);
}

// covers: PROP-DIFF-1 PROP-TRACE-1 TRC-CD-1 TRC-CD-3 TRC-CD-4
RC_GTEST_PROP(Differential, FastAgreesWithRefOnLongCdonWalls, ()) {
  ContourCase c = *long_bottleneck();
  RC_TAG(std::to_string(c.steps.size() / 100 * 100) + "+ blocks");
  check_agreement(c);
}

// covers: PROP-DIFF-1 PROP-SAR-5 SAR-TANGENT-1 SAR-SIDE-1 SAR-SIDE-2 SAR-SIDE-3 SAR-DISR-1 SAR-DISR-2
// covers: SAR-DISCL-3 SAR-DISRP-2 SAR-SUB-1 SAR-END-1 SAR-END-2 SAR-END-3 SAR-TRC-1 SAR-FEED-1 SAR-FEED-2
RC_GTEST_PROP(Differential, FastAgreesWithRefOnSarContours, ()) {
  ContourCase c = *sar_contour();
  CaseRuns r = run_case(c, false);
  std::string reached = "no SAR decision";
  for (const Decision& d : r.ref.decisions)
    if (d.clause == "SAR-DISCL-3" || d.clause == "SAR-END-1")
      reached = std::string(d.clause) + " " + std::string(d.branch);
  RC_TAG(reached);
  check_agreement(c);
}

// covers: PROP-CONT-1 PATH-CONT-1
RC_GTEST_PROP(Fast, PathIsContinuousAndFinite, ()) {
  ContourCase c = *any_contour();
  CaseRuns r = run_case(c, false);
  for (std::size_t i = 0; i < r.fast.path.size(); ++i) {
    const PathElement& e = r.fast.path[i];
    for (double v : {e.start.x, e.start.y, e.start.z, e.end.x, e.end.y, e.end.z, e.center.x, e.center.y, e.center.z})
      RC_ASSERT(std::isfinite(v));
    if (i == 0) continue;
    const PathPoint& a = r.fast.path[i - 1].end;
    double gap = std::max({std::fabs(a.x - e.start.x), std::fabs(a.y - e.start.y), std::fabs(a.z - e.start.z)});
    RC_ASSERT(gap <= r.tolerance.coordinate);
  }
}

}  // namespace
}  // namespace cutcom::props
