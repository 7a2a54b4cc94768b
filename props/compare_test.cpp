// The comparison itself (PROP-DIFF-1): what it counts as a difference between ref's and fast's
// paths, on hand-made runs.
#include "compare.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cutcom::props {
namespace {

PathElement arc(PathPoint start, PathPoint end, PathPoint centre, bool ccw) {
  PathElement e;
  e.type = ElementType::kArc, e.start = start, e.end = end, e.center = centre, e.ccw = ccw;
  e.origin.kind = OriginKind::kTransitionCircle, e.origin.line = 5;
  return e;
}
PathElement line(PathPoint start, PathPoint end) {
  PathElement e;
  e.start = start, e.end = end;
  e.origin.kind = OriginKind::kOffset, e.origin.line = 6;
  return e;
}

Tolerance tolerance() {
  Tolerance t{};
  t.coordinate = 1e-9, t.sine = 1e-12, t.degrees = 1e-9, t.touching = 1e-6;
  return t;
}

// covers: PROP-DIFF-1
TEST(Comparison, AnArcIsASliverByItsLengthAlongTheCircleNotByItsChord) {
  // In G18 (Z/X plane, applicate Y): a transition circle of radius 5 turning 3.4e-12 rad, about
  // 1.7e-11 mm along it, in fast only; ref has no element there (its equidistants meet exactly).
  const PathPoint c{20, 0, -26}, s{20 - 5 * std::sqrt(0.5), 0, -26 - 5 * std::sqrt(0.5)};
  const double a = 3.4e-12;  // turn clockwise about +Y: from Z towards -X
  const double t0 = std::atan2(s.x - c.x, s.z - c.z) - a;
  const PathPoint e{c.x + 5 * std::sin(t0), 0, c.z + 5 * std::cos(t0)};
  RunResult ref, fast;
  ref.path = {line(s, {30, 0, 0})};
  fast.path = {arc(s, e, c, false), line(e, {30, 0, 0})};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
  // The same end points turned the other way round is nearly a full circle: 31 mm of path.
  fast.path[0].ccw = true;
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
}

// covers: PROP-DIFF-1
TEST(Comparison, AFullCircleAgainstAnArcWithTheSameEndPointsDiverges) {
  // ref: a full circle (start == end) about (0,0) in G17 of radius 3; fast: an arc from (0,3) to
  // a point 2e-9 rad further counter-clockwise, i.e. a sliver, or the full circle minus it.
  const PathPoint s{0, 3, 0};
  const double a = 2e-9;
  const PathPoint near{-3 * std::sin(a), 3 * std::cos(a), 0};
  RunResult ref, fast;
  ref.path = {arc(s, s, {0, 0, 0}, true)};
  fast.path = {arc(s, near, {0, 0, 0}, true)};  // a sliver of 6e-9 mm: not the full circle
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
  fast.path = {arc(near, s, {0, 0, 0}, true)};  // the full circle less 6e-9 mm: beyond 1e-9 mm
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
  fast.path = {arc(s, s, {0, 0, 0}, true)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
}

}  // namespace
}  // namespace cutcom::props
