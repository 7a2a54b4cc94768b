// The comparison itself (PROP-DIFF-1): what it counts as a difference between ref's and fast's
// paths, on hand-made runs.
#include "compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "cutcom/boundary_rules.hpp"
#include "cutcom/reader.hpp"

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

// covers: PROP-TRACE-1
TEST(Comparison, FastWithoutItsTraceMustTakeTheSamePathBitForBit) {
  RunResult traced;
  traced.path = {line({0, 0, 0}, {10, 0, 0}), arc({10, 0, 0}, {10, 2, 0}, {10, 1, 0}, true)};
  traced.decisions.push_back(Decision{});
  RunResult untraced = traced;
  untraced.decisions.clear();  // no decisions kept: that alone is no difference
  EXPECT_FALSE(untraced_difference(traced, untraced));
  // One ulp off in one coordinate, far below any tolerance, is a difference.
  untraced.path[1].center.y = std::nextafter(1.0, 2.0);
  ASSERT_TRUE(untraced_difference(traced, untraced));
  EXPECT_NE(untraced_difference(traced, untraced)->find("element 1"), std::string::npos);
  untraced = traced;
  untraced.path.pop_back();
  EXPECT_TRUE(untraced_difference(traced, untraced));
  // The same geometry named after another block, or at another feed, is another path too.
  untraced = traced;
  untraced.path[1].origin.next_block = 50;
  EXPECT_TRUE(untraced_difference(traced, untraced));
  untraced = traced;
  untraced.path[0].feed = Decimal::from_int(300);
  EXPECT_TRUE(untraced_difference(traced, untraced));
  untraced = traced;
  untraced.alarms.push_back(Alarm{});
  EXPECT_TRUE(untraced_difference(traced, untraced));
  untraced = traced;
  untraced.actions.push_back(ActionEvent{});
  EXPECT_TRUE(untraced_difference(traced, untraced));
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
  // fast without its full-circle end snapping: (0, 3) to (0, 2.9999999999999996), one radius,
  // the end points 4.4e-16 mm apart; whether it turns 0 or 2 pi cannot be read from them (fast's
  // own output breaks PATH-ELEMENT-2, whatever ref wrote; and against ref's full circle).
  fast.path = {arc(s, {0, 2.9999999999999996, 0}, {0, 0, 0}, true)};
  Verdict v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("fast element 0 (transition circle at corner line 5/line 0) is an arc whose end points "
                               "leave its turn undetermined"),
            std::string::npos)
      << v.explanation;
  std::swap(ref, fast);  // ref's own output is not held to it: then against fast's full circle
  v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("fast turns a full circle, ref writes end points"), std::string::npos) << v.explanation;
  std::swap(ref, fast);
  // A start level with the centre on x is no reason to read the circle in the YZ plane: the end
  // keeps the applicate z, so it turns in XY, a whole turn less 2.5e-11 rad (a corner cut).
  ref.path = {arc({0, 0, -1}, {0, 0, -1}, {0, -0.001, -1}, false)};
  fast.path = {arc({0, 0, -1}, {-2.5109690751477657e-14, -1.0611755321835595e-19, -1}, {0, -0.001, -1}, false)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
  // A SAR half turn down a helix whose start, end and centre share x: the plane is XY (start and
  // end equally far from the centre there), not YZ where x agrees too.
  ref.path = {arc({-0.659, -5.54, 2.383}, {-0.659, -10.226, 0}, {-0.659, -7.883, 2.383}, true)};
  fast.path = {arc({-0.659, -5.54, 2.383}, {-0.659, -10.226 + 1e-15, 0}, {-0.659, -7.883, 2.383}, true)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree) << compare(ref, fast, tolerance()).explanation;
  // A SAR helix level with its centre in Y and Z, as far from it at its end in ZX as in XY
  // (campaign 20261259, case 64525): both sweeps about ref's axis, whatever fast's ulps favour.
  ref.path = {arc({-3.002, -2.997, 0.002}, {-3, -2.999, 0}, {-3, -2.997, 0.002}, true)};
  fast.path = {arc({-3.0020000000000002, -2.997, 0.002}, {-3, -2.999, 0}, {-3, -2.997, 0.002}, true)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree) << compare(ref, fast, tolerance()).explanation;
  // The same helix where fast's start is off the centre's level in Y by a rounding (campaign
  // 20261331, case 849333): ref's points tie Y and Z, fast's qualify Z only; both about Z.
  ref.path = {arc({6.502, -3.957, 1.983}, {8.485, -5.94, 0}, {8.485, -3.957, 1.983}, true)};
  fast.path = {arc({6.501999999999999, -3.957, 1.983}, {8.485, -5.9399999999999995, 0},
                   {8.485, -3.956999999999999, 1.983}, true)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree) << compare(ref, fast, tolerance()).explanation;
}

}  // namespace
}  // namespace cutcom::props

namespace cutcom::props {
namespace {

Decision decision(std::string_view clause, std::string_view branch, double margin, std::string exact = {}) {
  Decision d;
  d.clause = clause, d.branch = branch, d.line = 7, d.has_margin = true, d.margin = margin,
  d.margin_exact = std::move(exact);
  return d;
}

// A branch taken against its own margin is a divergence even where both engines agree and ref's
// margin lies in the band: `<` for `<=` at MD20230 shows as `switch-to-G451` at margin 0.
// covers: PROP-BOUNDARY-1 TRC-CORNER-4 TRC-KONT-1 TRC-ELEMENT-1 TRC-CD-3 TRC-LOOK-2
TEST(Comparison, ABranchAgainstItsOwnMarginBreaksTheBoundaryRule) {
  RunResult ref, fast;
  ref.decisions = {decision("TRC-CORNER-4", "keep-G450", 0, "0")};
  fast.decisions = {decision("TRC-CORNER-4", "switch-to-G451", 0)};
  Verdict v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("fast decision 0: TRC-CORNER-4 line 7 `switch-to-G451` with margin 0 breaks"),
            std::string::npos)
      << v.explanation;
  // The same branch at a margin that says so: a knife edge, as before.
  fast.decisions = {decision("TRC-CORNER-4", "switch-to-G451", -1e-12)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kKnifeEdge);
  // ref is held to its rules too, by the exact sign of its margin text.
  ref.decisions = {decision("TRC-KONT-1", "behind", 0, "0")};
  fast.decisions = {decision("TRC-KONT-1", "behind", -1e-15)};
  EXPECT_NE(compare(ref, fast, tolerance()).explanation.find("ref decision 0"), std::string::npos);
  ref.decisions = fast.decisions = {decision("TRC-ELEMENT-1", "vanishes", 0, "0")};
  fast.decisions[0].margin_exact.clear();
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
  fast.decisions[0].branch = ref.decisions[0].branch = "reverses";
  ref.decisions[0].margin_exact = "-1.5e-30";
  EXPECT_NE(compare(ref, fast, tolerance()).explanation.find("fast decision 0: TRC-ELEMENT-1"), std::string::npos);
  // A crossing exactly at a piece's end left out shows as `none` at margin 0 (TRC-CD-3); collinear
  // pieces that overlap are `overlap` at 0.
  ref.decisions = {decision("TRC-CD-3", "cut", 0, "0")};
  fast.decisions = {decision("TRC-CD-3", "none", 0)};
  EXPECT_NE(compare(ref, fast, tolerance()).explanation.find("fast decision 0: TRC-CD-3 line 7 `none` with margin 0"),
            std::string::npos);
  ref.decisions = {decision("TRC-CD-3", "overlap", 0, "0")};
  fast.decisions = {decision("TRC-CD-3", "overlap", -0.0)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
  // An intersection exactly at the candidate's start left out shows as `none` at margin 0 (TRC-LOOK-2).
  ref.decisions = {decision("TRC-LOOK-2", "intersection", 0, "0")};
  fast.decisions = {decision("TRC-LOOK-2", "none", 0)};
  EXPECT_NE(compare(ref, fast, tolerance()).explanation.find("fast decision 0: TRC-LOOK-2"), std::string::npos);
  // A NaN margin satisfies no rule.
  fast.decisions[0].margin = std::nan("");
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
}

// A whole turn and a rest of 4.1e-8 mm in ref against the whole turn alone in fast (PATH-ELEMENT-2
// lets fast close a circle within 1e-8 of its radius): agree; a rest of 1e-6 mm is a divergence.
// covers: PROP-DIFF-1 PATH-ELEMENT-2
TEST(Comparison, TheRestAfterAWholeTurnWithinTheSnapOfFastDoesNotCount) {
  RunResult ref, fast;
  auto circle = [](PathPoint from, PathPoint to) { return arc(from, to, {0, 0, 0}, true); };
  PathPoint x{36, 0, 0};
  const double rest = 4.1e-8 / 36;  // the rest's turn, rad
  ref.path = {circle(x, x), circle(x, {36 * std::cos(rest), 36 * std::sin(rest), 0})};
  fast.path = {circle(x, x)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kAgree);
  ref.path[1].end = {36 * std::cos(1e-6 / 36), 36 * std::sin(1e-6 / 36), 0};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
}

// fast writes no element of length zero (PATH-ELEMENT-1): a transition circle of radius 0 is a
// point that the tolerance would hide (mutant 14); a full circle is not one.
// covers: PATH-ELEMENT-1 PROP-BOUNDARY-1
TEST(Comparison, AZeroLengthElementOfFastIsADivergence) {
  RunResult ref, fast;
  PathElement circle;
  circle.type = ElementType::kArc, circle.start = circle.end = circle.center = {1, 2, 0};
  circle.origin.kind = OriginKind::kTransitionCircle, circle.origin.line = 7;
  fast.path = {circle};
  Verdict v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("fast element 0 (transition circle"), std::string::npos) << v.explanation;
  fast.path[0].type = ElementType::kLine;
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
  // A full circle (start and end the same, the centre elsewhere) turns: no breach.
  fast.path[0].type = ElementType::kArc, fast.path[0].center = {1, 5, 0};
  EXPECT_FALSE(zero_length_element(fast, "fast"));
  // ref rounds exact slivers after deciding on them: it is not held to this.
  ref.path = {circle};
  EXPECT_FALSE(compare(ref, fast, tolerance()).explanation.find("ref element") != std::string::npos);
}

// covers: PATH-ELEMENT-2 PROP-DIFF-1
TEST(Comparison, AnArcOfFastWhoseTurnItsPointsLeaveUndeterminedIsADivergence) {
  RunResult ref, fast;
  // A transition circle whose ends lie two ulps apart on one radius (corpus
  // transition-circle-at-a-tangent-sar-corner): a sliver or a whole turn to whoever reads it.
  const double y = 3, y_next = std::nextafter(std::nextafter(y, 4.0), 4.0);
  fast.path = {arc({1, y, 0}, {1, y_next, 0}, {1, 0, 0}, true)};
  ASSERT_TRUE(undetermined_turn(fast, "fast"));
  Verdict v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("fast element 0 (transition circle"), std::string::npos) << v.explanation;
  // Readable: the whole turn (the same point), a helix's whole turn (its end over its start), an
  // arc whose end lies off the start's direction by more than rounding, and the half turn.
  fast.path[0].end = fast.path[0].start;
  EXPECT_FALSE(undetermined_turn(fast, "fast"));
  fast.path[0].end = {1, y, -2};
  EXPECT_FALSE(undetermined_turn(fast, "fast"));
  fast.path[0].end = {1 + 1e-9, y, 0};
  EXPECT_FALSE(undetermined_turn(fast, "fast"));
  fast.path[0].end = {1, -y, 0};
  EXPECT_FALSE(undetermined_turn(fast, "fast"));
}

// A circle of radius exactly r on the inside: both engines decide its collapse in integers, so
// another branch of fast at ref's margin of exactly 0 is no knife edge (mutant 22).
// covers: PROP-DIFF-1 TRC-CD-2 TRC-ARC-EQ-1
TEST(Comparison, ACollapseAtAnExactZeroRadiusIsNoKnifeEdge) {
  RunResult ref, fast;
  ref.decisions = {decision("TRC-CD-2", "collapsed", 0, "0")};
  fast.decisions = {decision("TRC-CD-2", "inner", 0.5)};
  Verdict v = compare(ref, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  ref.decisions = {decision("TRC-ARC-EQ-1", "collapses", 0, "0")};
  fast.decisions = {decision("TRC-ARC-EQ-1", "concentric", 1e-300)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kDiverge);
  // A radius a rounding from 0 that is not exactly 0 stays a knife edge.
  ref.decisions = {decision("TRC-ARC-EQ-1", "collapses", -1e-12, "-1.0e-12")};
  fast.decisions = {decision("TRC-ARC-EQ-1", "concentric", 1e-12)};
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kKnifeEdge);
}

// fast decides TRC-CORNER-1 and TRC-KONT-1 exactly on programmed decimals (CR= circles
// included): the other branch at ref's exact tie is a divergence there, a knife edge only at or
// next to a block about which fast computes points (a SAR block, a side change). Mutant 78.
// covers: PROP-DIFF-1 TRC-CORNER-1 TRC-KONT-1
TEST(Comparison, AnExactTieOnProgrammedDecimalsTakenOtherwiseDiverges) {
  auto at = [](Decision d, int line) {
    d.line = line;
    return d;
  };
  Tolerance tol = tolerance();
  tol.plane_lines = {5, 6, 7, 8, 9};
  RunResult ref, fast;
  ref.decisions = {at(decision("TRC-KONT-1", "in-front", 0, "0"), 5)};
  fast.decisions = {at(decision("TRC-KONT-1", "behind", -1.4e-14), 5)};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  ref.decisions = {at(decision("TRC-CORNER-1", "tangent", 0, "0"), 7)};
  fast.decisions = {at(decision("TRC-CORNER-1", "outer", -5e-16), 7)};
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  for (int computed : {6, 7, 8}) {  // the block before, the block itself, the block after
    tol.computed_lines = {computed};
    v = compare(ref, fast, tol);
    EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << computed << ": " << v.explanation;
  }
  tol.computed_lines = {9};  // two blocks on: no longer next to it
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  // The blocks about which fast computes points, from the program: a SAR block, a side change, the
  // same side again (campaign 20261249, case 1089: KONT from where the tool stood).
  std::istringstream in(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nG1 G41 X0 Y0 F100\nX10\nG42 Y10\nX20\nG42 Y20\nX30\n"
      "G40 G248 G340 DISR=2 X40\n");
  ProgramReader reader(in);
  std::vector<Block> blocks;
  for (Block b; reader.next(b);) blocks.push_back(b);
  EXPECT_EQ(conditioning_of(blocks).computed_lines, (std::vector<int>{6, 8, 10}));
  tol.plane_lines.clear();  // blocks unknown: a knife edge, as before
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
  // A margin a rounding from 0 that is not exactly 0 stays a knife edge.
  tol.plane_lines = {5, 6, 7, 8, 9}, tol.computed_lines.clear();
  ref.decisions = {at(decision("TRC-CORNER-1", "inner", 1e-17, "1.0e-17"), 7)};
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
}

// A CDON entry at margin 0 between two lines is an entry of one point, well conditioned: a parting
// after it is a divergence (mutant 23: the point entry refused after it was traced). At a corner
// with a circle the margin is also the carriers' gap: there it is touching carriers.
// covers: PROP-DIFF-1 TRC-CD-2 TRC-CD-3
TEST(Comparison, AnEntryOfOnePointBetweenLinesExplainsNothingAfterIt) {
  auto at = [](Decision d, int line) {
    d.line = line;
    return d;
  };
  Tolerance tol = tolerance();
  tol.plane_lines = {6, 7, 8, 9};
  RunResult ref, fast;
  ref.decisions = {at(decision("TRC-CD-2", "entry", 0, "0"), 8), at(decision("TRC-CD-3", "none", -1, "-1"), 8)};
  fast.decisions = {at(decision("TRC-CD-2", "entry", 0), 8), at(decision("TRC-CORNER-1", "inner", 1), 8)};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  tol.circle_lines = {7};  // the block before is a circle
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("after touching carriers"), std::string::npos) << v.explanation;
  tol.circle_lines = {8};  // the block itself
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
  tol.circle_lines = {6};  // two blocks before: not at this corner
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  // fast's entry a rounding longer than ref's point: a sliver whose crossing touches a held piece
  // (its own margin 0) where ref compares nothing: that crossing is the knife edge.
  fast.decisions[1] = at(decision("TRC-CD-3", "cut", 0), 8);
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("fast's crossing touches"), std::string::npos) << v.explanation;
  fast.decisions[1] = at(decision("TRC-CD-3", "cut", 0.5), 8);  // a crossing well inside: no knife edge
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  // The sliver along a held piece: collinear pieces overlap, a miss of 0 (campaign 20261267,
  // case 991544); an overlap is only ever traced at 0, so a margin off it is no touching.
  fast.decisions[1] = at(decision("TRC-CD-3", "overlap", -0.0), 8);
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("fast's entry overlaps"), std::string::npos) << v.explanation;
  fast.decisions[1] = at(decision("TRC-CD-3", "overlap", -0.5), 8);
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
}

// fast's hit where its carriers touch (margin in the band) against ref's point just off the piece:
// a knife edge while ref's miss is within the touching tolerance (campaign 20261286, case 993226).
// covers: PROP-DIFF-1 TRC-CD-6 TRC-EDGE-5
TEST(Comparison, AHitOnTouchingCarriersIsAKnifeEdgeWithinTheTouchingTolerance) {
  Tolerance tol = tolerance();  // band 1e-9, touching 1e-6
  RunResult ref, fast;
  ref.decisions = {decision("TRC-CD-6", "none", -1e-8, "-1e-8")};
  fast.decisions = {decision("TRC-CD-6", "later-block", 2e-15)};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("fast's hit on touching carriers"), std::string::npos) << v.explanation;
  ref.decisions[0] = decision("TRC-CD-6", "none", -1e-5, "-1e-5");  // farther off than touching allows
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  ref.decisions[0] = decision("TRC-CD-6", "none", -1e-8, "-1e-8");
  fast.decisions[0] = decision("TRC-CD-6", "later-block", 1e-7);  // a hit well inside: no touching
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  ref.decisions = {decision("TRC-EDGE-5", "none", -1e-8, "-1e-8")};
  fast.decisions = {decision("TRC-EDGE-5", "hit", 0)};
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
  fast.decisions = {decision("TRC-LOOK-2", "intersection", 0)};  // another clause at the same line
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
}

// What an element belongs to and its feed, the actions and where they run, SAR's variables and
// the notices: a bug that changes only these would otherwise pass.
// covers: PROP-DIFF-3
TEST(Comparison, FeedsActionsSarVariablesAndNoticesAreCompared) {
  RunResult ref;
  ref.path = {line({0, 0, 0}, {10, 0, 0})};
  ref.path[0].feed = *Decimal::parse("500").value;
  ActionEvent m8;
  m8.line = 6, m8.function.value = 8, m8.at = {10, 0, 0};
  ref.actions = {m8};
  SarVariables sv;
  sv.line = 6, sv.p_apr = {1, 2, 3}, sv.p_aep = {4, 5, 6};
  ref.variables = {sv};
  ref.notices = {Notice{6, "TRC-END-1", "compensation selected at the end", 0}};
  EXPECT_EQ(compare(ref, ref, tolerance()).kind, Verdict::Kind::kAgree);
  auto expect_diverges = [&](const RunResult& fast, const char* why) {
    Verdict v = compare(ref, fast, tolerance());
    EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << why;
    EXPECT_NE(v.explanation.find(why), std::string::npos) << v.explanation;
  };
  RunResult fast = ref;
  fast.path[0].feed = *Decimal::parse("250").value;  // the SAR infeed's FAD taken for the plane move
  expect_diverges(fast, "feed 500 vs 250");
  fast = ref;
  fast.path[0].feed_type = FeedType::kG95;  // the same number, per revolution
  expect_diverges(fast, "feed 500 vs 500 (G95)");
  fast = ref;
  fast.path[0].rapid = true;  // a G0 block's line output at feed, or the other way round
  expect_diverges(fast, "line offset of line 6 vs line rapid offset of line 6");
  fast = ref;
  fast.path[0].origin.sar = SarMove::kElement;
  expect_diverges(fast, "what it belongs to");
  // A transition circle's second corner named without its insert (mutant 92: "N30/N30" for
  // "N30/(chamfer of N30/N40)"), or with another number: the same lines, another name.
  RunResult circle = ref;
  circle.path[0].type = ElementType::kArc, circle.path[0].center = {5, 0, 0}, circle.path[0].ccw = true;
  circle.path[0].origin.kind = OriginKind::kTransitionCircle, circle.path[0].origin.next_line = 7;
  circle.path[0].origin.next_insert.kind = InsertKind::kChamfer, circle.path[0].origin.next_insert.next_line = 8;
  EXPECT_EQ(compare(circle, circle, tolerance()).kind, Verdict::Kind::kAgree);
  fast = circle;
  fast.path[0].origin.next_insert = ContourInsert{};
  Verdict v = compare(circle, fast, tolerance());
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("what it belongs to"), std::string::npos) << v.explanation;
  fast = circle;
  fast.path[0].origin.next_block = 70;
  EXPECT_EQ(compare(circle, fast, tolerance()).kind, Verdict::Kind::kDiverge);
  fast = ref;
  fast.path[0].origin.source = 3;  // another subprogram's line of the same number
  expect_diverges(fast, "what it belongs to");
  fast = ref;
  fast.actions[0].at = {10, 1e-3, 0};  // M8 one micrometre off where the tool is
  expect_diverges(fast, "placed 0.001 mm apart");
  fast = ref;
  fast.actions[0].function.value = 9;
  expect_diverges(fast, "M8 at line 6 vs M9");
  fast = ref;
  fast.variables[0].p_apdv = -1;
  expect_diverges(fast, "$P_APDV 1 vs -1");
  fast = ref;
  fast.variables[0].p_aep.x += 1e-3;
  expect_diverges(fast, "SAR variables of line 6");
  fast = ref;
  fast.notices.clear();
  expect_diverges(fast, "different notices");
}

// covers: PROP-DIFF-2
TEST(Comparison, AKnifeEdgeDoesNotHideWhatFollowsIt) {
  auto at = [](Decision d, int line) {
    d.line = line;
    return d;
  };
  auto plain = [](std::string_view clause, std::string_view branch, int line) {
    Decision d;
    d.clause = clause, d.branch = branch, d.line = line;
    return d;
  };
  auto element = [](int origin_line, PathPoint start, PathPoint end) {
    PathElement e = line(start, end);
    e.origin.line = origin_line;
    return e;
  };
  // The runs part at the corner of line 5 inside the band (G450 kept in ref, G451 in fast); the
  // next block (window 1) may follow from it; from line 8 on they take the same branches again.
  Tolerance tol = tolerance();
  tol.window = 1;
  RunResult ref, fast;
  ref.decisions = {at(decision("TRC-CORNER-4", "keep-G450", 1e-13, "1e-13"), 5), plain("TRC-ELEMENT-1", "fits", 6),
                   plain("TRC-ELEMENT-1", "kept", 8), plain("TRC-ELEMENT-1", "kept", 9)};
  fast.decisions = {at(decision("TRC-CORNER-4", "switch-to-G451", -1e-13), 5), plain("TRC-ELEMENT-1", "vanishes", 6),
                    plain("TRC-ELEMENT-1", "kept", 8), plain("TRC-ELEMENT-1", "kept", 9)};
  ref.path = {element(5, {0, 0, 0}, {1, 0, 0}), element(6, {1, 0, 0}, {2, 0, 0}), element(9, {2, 0, 0}, {10, 0, 0})};
  fast.path = {element(5, {0, 0, 0}, {1, 0.5, 0}), element(9, {2, 0, 0}, {10, 0, 0})};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;  // lines 5 and 6 are the knife edge's
  EXPECT_NE(v.explanation.find("again at line 8 and are compared after it"), std::string::npos) << v.explanation;
  // A path 38 mm off after the runs met again is a divergence, not hidden by the knife edge.
  fast.path[1].end = {10, 38, 0};
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("took the same branches again at line 8, then: element 0"), std::string::npos)
      << v.explanation;
  // So is a later parting without a margin in the band.
  fast.path[1].end = {10, 0, 0};
  fast.decisions[3].branch = "vanishes";
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge);
  EXPECT_NE(v.explanation.find("then: unexplained decision 3"), std::string::npos) << v.explanation;
  // Runs that do not take the same branch after the window stay a knife edge, compared no further;
  // so do runs with a larger window that reaches their end.
  fast.decisions[2].branch = "vanishes";
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
  fast.decisions[2].branch = "kept";
  EXPECT_EQ(compare(ref, fast, tolerance()).kind, Verdict::Kind::kKnifeEdge);
  // A look-ahead's later decision about a line of the knife edge's (line 4, after line 8) is the
  // knife edge's: it may differ.
  fast.decisions[3].branch = "kept";
  ref.decisions.insert(ref.decisions.begin() + 3, plain("TRC-ELEMENT-1", "fits", 4));
  fast.decisions.insert(fast.decisions.begin() + 3, plain("TRC-ELEMENT-1", "vanishes", 4));
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge) << compare(ref, fast, tol).explanation;
  // Runs whose path goes back to earlier lines (a loop) are not resumed: "a later block" may be
  // another pass.
  fast.path[1].end = {10, 38, 0};
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  ref.path.push_back(element(3, {10, 0, 0}, {0, 0, 0}));
  fast.path.push_back(element(3, {10, 38, 0}, {0, 0, 0}));
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kKnifeEdge);
}

// covers: PROP-DIFF-2 TRC-LOOK-1 TRC-LOOK-2
TEST(Comparison, ALookAheadSearchingAtTheWindowsEndIsTheKnifeEdges) {
  // Campaign 20261320, case 276013, in small: the runs part at line 4 in the band (window 2: lines
  // 5 and 6 are the knife edge's). In ref a look-ahead begun at line 5 is still searching at line
  // 6; in fast a cut ended it. At line 7 both deselect, then ref takes the retraction's strategy
  // and fast the plain retraction: the search's, so the knife edge's, not a divergence.
  auto made = [](std::string_view clause, std::string_view branch, int line, double margin = 1,
                 const char* exact = "1") {
    Decision d = decision(clause, branch, margin, exact);
    d.line = line;
    return d;
  };
  auto fast_made = [](std::string_view clause, std::string_view branch, int line, double margin = 1) {
    Decision d = decision(clause, branch, margin);
    d.line = line;
    return d;
  };
  Tolerance tol = tolerance();
  tol.window = 2;
  RunResult ref, fast;
  ref.decisions = {made("TRC-KONT-1", "in-front", 4, 0, "0"),
                   made("TRC-LOOK-1", "too-short", 5, -1, "-1"),
                   made("TRC-LOOK-2", "none", 6, -2, "-2"),
                   made("TRC-DESEL-1", "deselected", 7),
                   made("TRC-EDGE-1", "G461", 7),
                   made("TRC-ELEMENT-1", "fits", 9)};
  fast.decisions = {fast_made("TRC-KONT-1", "behind", 4, -1e-15), fast_made("TRC-LOOK-1", "too-short", 5, -1),
                    fast_made("TRC-CD-3", "cut", 6, 4),           fast_made("TRC-LOOK-3", "skipped", 5),
                    fast_made("TRC-DESEL-1", "deselected", 7),    fast_made("TRC-RETR-NORM-1", "line", 7),
                    fast_made("TRC-ELEMENT-1", "fits", 9)};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("ref's look-ahead from line 5 still searching"), std::string::npos) << v.explanation;
  // Its blocks reach two plane blocks past line 5 (lines 6 and 7): the runs are compared again
  // after them, from line 9, where a parting is a divergence.
  fast.decisions.back().branch = "vanishes";
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  EXPECT_NE(v.explanation.find("line 9"), std::string::npos) << v.explanation;
  // Without the search open (an intersection found at line 6), the deselection is compared.
  fast.decisions.back().branch = "fits";
  ref.decisions[2].branch = "intersection";
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
}

// covers: PROP-DIFF-2
TEST(Comparison, AKnifeEdgeInsideAnotherOwnsTheBlocksAfterIt) {
  // Campaign 20261225, case 399951, in small: the runs part at line 5 in the band (window 1: line
  // 6 is the knife edge's); at line 6 ref decides at margin 0 (there a touching crossing, here
  // the look-ahead) and fast takes the other branch. Its consequences reach line 8, where ref
  // decides on a circle and fast checks a collision first. That second parting is a knife edge of
  // its own: the blocks after it are its, and the runs are compared again from line 9.
  auto made = [](std::string_view clause, std::string_view branch, int line, double margin, const char* exact) {
    Decision d = decision(clause, branch, margin, exact ? exact : "");
    d.line = line;
    return d;
  };
  Tolerance tol = tolerance();
  tol.window = 1;
  RunResult ref, fast;
  ref.decisions = {
      made("TRC-KONT-1", "in-front", 5, 0, "0"),         made("TRC-LOOK-1", "reaches", 6, 0, "0"),
      made("ARC-CENTRE-2", "within", 8, -0.01, "-0.01"), made("TRC-ARC-EQ-1", "concentric", 8, 0.012, "0.012"),
      made("TRC-ELEMENT-1", "fits", 9, 0.5, "0.5"),      made("TRC-ELEMENT-1", "fits", 10, 0.5, "0.5"),
      made("TRC-ELEMENT-1", "fits", 11, 0.5, "0.5")};
  fast.decisions = {
      made("TRC-KONT-1", "behind", 5, -5e-17, nullptr),      made("TRC-LOOK-1", "too-short", 6, -8e-8, nullptr),
      made("ARC-CENTRE-2", "within", 8, -0.01, nullptr),     made("TRC-CD-2", "outer", 8, -1, nullptr),
      made("TRC-ARC-EQ-1", "concentric", 8, 0.012, nullptr), made("TRC-ELEMENT-1", "fits", 9, 0.5, nullptr),
      made("TRC-ELEMENT-1", "fits", 10, 0.5, nullptr),       made("TRC-ELEMENT-1", "fits", 11, 0.5, nullptr)};
  Verdict v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_NE(v.explanation.find("then ref TRC-LOOK-1 line 6 reaches (margin 0) in its band too"), std::string::npos)
      << v.explanation;
  EXPECT_NE(v.explanation.find("again at line 9"), std::string::npos) << v.explanation;
  // What follows is still compared: a parting at line 10 outside the band is a divergence.
  fast.decisions[6].branch = "vanishes", fast.decisions[6].margin = 0;
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
  fast.decisions[6] = made("TRC-ELEMENT-1", "fits", 10, 0.5, nullptr);
  // Outside the band, the look-ahead at line 6 is no knife edge of its own; but fast's search,
  // begun there and still open at the window's end, is the first knife edge's until it has
  // examined the next plane block (line 8): the parting at line 8 is the knife edge's, one at
  // line 10 (after the runs met again at line 9) is not.
  ref.decisions[1] = made("TRC-LOOK-1", "reaches", 6, 0.25, "0.25");
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kKnifeEdge) << v.explanation;
  EXPECT_EQ(v.explanation.find("in its band too"), std::string::npos) << v.explanation;
  EXPECT_NE(v.explanation.find("fast's look-ahead from line 6 still searching"), std::string::npos) << v.explanation;
  fast.decisions[6].branch = "vanishes", fast.decisions[6].margin = 0;
  v = compare(ref, fast, tol);
  EXPECT_EQ(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  EXPECT_NE(v.explanation.find("again at line 9"), std::string::npos) << v.explanation;
  fast.decisions[6] = made("TRC-ELEMENT-1", "fits", 10, 0.5, nullptr);
  // Nor is a decision in the band that fast took the same way.
  ref.decisions[1] = made("TRC-LOOK-1", "reaches", 6, 0, "0");
  fast.decisions[1] = made("TRC-LOOK-1", "reaches", 6, 1e-17, nullptr);
  EXPECT_EQ(compare(ref, fast, tol).kind, Verdict::Kind::kDiverge);
}

// Every rule names a clause of the spec and a branch its engines trace.
// covers: PROP-BOUNDARY-1
TEST(Comparison, EveryBoundaryRuleNamesAClauseOfTheSpec) {
  std::string spec;
  for (const char* file : {"arcs.md", "trc-lines.md", "approach-retraction.md", "sar.md"}) {
    std::ifstream in(std::string(CUTCOM_SOURCE_DIR) + "/spec/" + file);
    spec += std::string(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_GT(boundary_rules().size(), 40u);
  for (const BoundaryRule& r : boundary_rules()) {
    std::string heading = "### ", branch = "`";
    heading.append(r.clause).append(" ");
    branch.append(r.branch).append("`");
    EXPECT_NE(spec.find(heading), std::string::npos) << r.clause;
    EXPECT_NE(spec.find(branch), std::string::npos) << r.clause << " " << r.branch;
  }
}

}  // namespace
}  // namespace cutcom::props
