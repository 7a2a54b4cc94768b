// Worked examples for circles and helices; expected coordinates derived by hand in the comments.
#include <cmath>

#include "cutcom/programmed_decisions.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

using K = OriginKind;
const double kSqrt2 = std::sqrt(2.0);

std::string program(const std::string& body, const std::string& radius = "2") {
  return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" + radius + "\nN10 G0 X-10 Y0 T1 D1\n" + body;
}

Expect offset_arc(PathPoint s, PathPoint e, PathPoint c, bool ccw) { return {K::kOffset, s, e, c, true, ccw}; }
Expect programmed_arc(PathPoint s, PathPoint e, PathPoint c, bool ccw) { return {K::kProgrammed, s, e, c, true, ccw}; }

// covers: ARC-HELIX-1 NC-ARC-1
TEST(ArcExamples, UncompensatedHelix) {
  // A quarter circle ccw about (0,0) from (10,0) to (0,10), Z falling to -5: a helix.
  Runs r = run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 I-10 J0 Z-5 F100\n");
  expect_both(r,
              {line(K::kProgrammed, {0, 0, 0}, {10, 0, 0}), programmed_arc({10, 0, 0}, {0, 10, -5}, {0, 0, 0}, true)});
}

// covers: ARC-CENTRE-1 ARC-CENTRE-2 MD-21000-1 MD-21010-1
TEST(ArcExamples, CentreIsCorrectedWithinTheToleranceElseAlarm14040) {
  // Centre (-0.004, 0.002): radii 10.0040002 and 9.9980008 differ by 0.006 <= 0.01. Projected on
  // the chord's bisector x = y through m = (5,5) with p = (-10,-10): k = ((c-m).p)/|p|^2
  // = (50.04 + 49.98)/200 = 0.5001, c' = (5,5) - 5.001 (1,1) = (-0.001, -0.001).
  Runs ok = run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 I-10.004 J0.002\n");
  expect_both(ok, {line(K::kProgrammed, {0, 0, 0}, {10, 0, 0}),
                   programmed_arc({10, 0, 0}, {0, 10, 0}, {-0.001, -0.001, 0}, true)});
  EXPECT_TRUE(has_decision(ok.ref, "ARC-CENTRE-2", "within"));
  // Centre (-0.02, 0): radii 10.02 and 10.00002 differ by 0.01998 > max(0.01, 0.001 * 10.02).
  Runs bad = run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 I-10.02 J0\n");
  for (const RunResult* x : {&bad.fast, &bad.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 14040);
    EXPECT_EQ(x->alarms[0].line, 2);
  }
  // With MD21000 = 0.05 the same circle is accepted.
  MachineData md;
  md.set("MD21000", "0.05");
  Runs loose = run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 I-10.02 J0\n", md);
  EXPECT_TRUE(loose.fast.alarms.empty());
  EXPECT_TRUE(loose.ref.alarms.empty());
  MachineData md2;
  md2.set("MD21010", "0.002");  // tolerance 0.02004 >= 0.01998
  EXPECT_TRUE(run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 I-10.02 J0\n", md2).ref.alarms.empty());
}

// covers: TRC-ARC-EQ-1 TRC-CORNER-1 TRC-ARC-ELEMENT-1
TEST(ArcExamples, TangentLineArcLineInsideTheCircle) {
  // N30 +X, then a ccw quarter circle about (10,10), radius 10, tangent to it, then +Y, tangent.
  // G41 is the inside of a ccw circle: equidistant radius 10 - 2 = 8, from (10,2) to (18,10).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X20 Y10 I0 J10\nN50 G1 Y20\nN60 G40 X30 Y30\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), offset_arc({10, 2, 0}, {18, 10, 0}, {10, 10, 0}, true),
                  line(K::kOffset, {18, 10, 0}, {18, 20, 0}), line(K::kRetraction, {18, 20, 0}, {30, 30, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-EQ-1", "concentric"));
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-ELEMENT-1", "fits"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-ARC-ELEMENT-1", "fits"));
}

// A circle of exactly the tool's radius, inside: its equidistant has radius 0 and collapses, in
// both engines. The radius is |(1.682, -0.001) - (0.68, -0.001)| = 1.002 = r; in double the
// difference is 1.0019999999999998 and the equidistant 2.2e-16 (campaign 20261208, case 169769).
// Also with the centre corrected onto the chord's bisector (ARC-CENTRE-1): centre (1, 0.001)
// for the chord (0,0)-(2,0) gives rho^2 = 1 + 1e-6, rho = 1.000000499999875: above r = 1.0000004,
// below r = 1.0000005 (whose square is 1.00000100000025).
// covers: TRC-ARC-EQ-1
TEST(ArcExamples, ACircleOfExactlyTheToolRadiusCollapses) {
  Runs r =
      run_both(program("N20 G1 G41 X0.68 Y0 F100\nN30 Y-0.001\nN40 G3 X2.684 Y-0.001 I1.002 J0\n"
                       "N50 G1 Y3\nN60 G40 X0 Y5\n",
                       "1.002"));
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-EQ-1", "collapses"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-ARC-EQ-1", "collapses"));
  EXPECT_EQ(
      circle_radius_sign(ProgrammedCircle{{2'000'000'000, 0}, {1'000'000'000, 1'000'000}, true, 0}, 1'000'000'400), 1);
  EXPECT_EQ(
      circle_radius_sign(ProgrammedCircle{{2'000'000'000, 0}, {1'000'000'000, 1'000'000}, true, 0}, 1'000'000'500), -1);
  EXPECT_EQ(circle_radius_sign(ProgrammedCircle{{0, 0}, {3'000'000'000, 4'000'000'000}, true, 0}, 5'000'000'000), 0);
  EXPECT_EQ(circle_radius_sign(ProgrammedCircle{{0, 0}, {0, 0}, false, -2'000'000'000}, 2'000'000'000), 0);
}

// covers: TRC-ARC-EQ-1
TEST(ArcExamples, TangentLineArcLineOutsideTheCircle) {
  // G42: the outside, radius 12: from (10,-2) to (22,10).
  Runs r = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 G3 X20 Y10 I0 J10\nN50 G1 Y20\nN60 G40 X30 Y30\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {10, -2, 0}), offset_arc({10, -2, 0}, {22, 10, 0}, {10, 10, 0}, true),
                  line(K::kOffset, {22, 10, 0}, {22, 20, 0}), line(K::kRetraction, {22, 20, 0}, {30, 30, 0})});
}

// covers: TRC-ARC-CORNER-1 TRC-INNER-1
TEST(ArcExamples, InnerCornerLineToCircle) {
  // N40: ccw about (5,5) from (10,0) to (10,10), radius sqrt50, starting in direction (1,1): a 45
  // deg left turn, inside for G41. Equidistants: y = 2 and the circle of radius sqrt50 - 2 about
  // (5,5): (x-5)^2 + 9 = (sqrt50 - 2)^2 = 54 - 20 sqrt2, x = 5 + sqrt(45 - 20 sqrt2) (the one
  // nearer (10,0)). The circle's normal end at (10,10), tangent (-1,1): (10 - sqrt2, 10 - sqrt2).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X10 Y10 I-5 J5\nN50 G1 G40 X0 Y20\n"));
  PathPoint x{5 + std::sqrt(45 - 20 * kSqrt2), 2, 0};
  PathPoint end{10 - kSqrt2, 10 - kSqrt2, 0};
  expect_both(
      r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
          line(K::kOffset, {0, 2, 0}, x), offset_arc(x, end, {5, 5, 0}, true), line(K::kRetraction, end, {0, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-CORNER-1", "intersection"));
}

// covers: TRC-G450-1 TRC-CORNER-4
TEST(ArcExamples, OuterCornerLineToCircleWithTransitionCircle) {
  // The same contour with G42: outside; 45 deg >= MD20230, so G450. The circle about (10,0)
  // runs ccw from (10,-2) to (10,0) + 2 (1,-1)/sqrt2 = (10 + sqrt2, -sqrt2); the equidistant
  // (radius sqrt50 + 2) ends at (10,10) + 2 (1,1)/sqrt2.
  Runs r = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 G3 X10 Y10 I-5 J5\nN50 G1 G40 X20 Y20\n"));
  PathPoint from{10 + kSqrt2, -kSqrt2, 0};
  PathPoint end{10 + kSqrt2, 10 + kSqrt2, 0};
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {10, -2, 0}), arc({10, -2, 0}, from, {10, 0, 0}, true),
                  offset_arc(from, end, {5, 5, 0}, true), line(K::kRetraction, end, {20, 20, 0})});
}

// covers: TRC-ARC-EQ-1 TRC-LOOK-1 TRC-LOOK-2 TRC-LOOK-3 ALARM-1 TRC-EDGE-4
TEST(ArcExamples, CircleSmallerThanTheToolOnTheInsideIsSkipped) {
  // An inner fillet N40 of radius 1 < r = 2 (ccw about (10,1)): its equidistant collapses, the
  // look-ahead intersects N30's y = 2 with N50's x = 11 - 2 = 9: (9,2), 1 after N50's normal
  // start (9,1). The fillet is skipped.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X11 Y1 I0 J1\nN50 G1 Y10\nN60 G40 X20 Y20\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {9, 2, 0}), line(K::kOffset, {9, 2, 0}, {9, 10, 0}),
                  line(K::kRetraction, {9, 10, 0}, {20, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-EQ-1", "collapses"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-LOOK-3", "skipped"));
  // A half circle of radius 1 ending the contour: nothing after it meets N30's equidistant before
  // the G40 block. G462 (initial setting) extends N40 beyond its normal end (10,0) along its end
  // tangent +Y: it meets y = 2 at (10,2), N30's normal end, where N40 is skipped.
  Runs end = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X12 Y0 I1 J0\nN50 G1 G40 X20 Y0\n"));
  expect_both(end, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                    line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {20, 0, 0})});
  EXPECT_TRUE(has_decision(end.ref, "TRC-EDGE-1", "G462"));
}

// covers: TRC-ARC-CORNER-2
TEST(ArcExamples, InnerCornerWithoutIntersectionRaises10751) {
  // N40: ccw about (5,-5), radius sqrt50, from (10,0) in direction (-1,1): a 135 deg left turn,
  // inside for G41. The circle of radius sqrt50 - 2 = 5.07 about (5,-5) is 7 away from y = 2.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X0 Y0 I-5 J-5\nN50 G1 G40 X-10 Y0\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10751);
  }
  EXPECT_TRUE(has_decision(r.ref, "TRC-ARC-CORNER-1", "none"));
}

// covers: TRC-ARC-ELEMENT-1 TRC-APPR-NORM-1
TEST(ArcExamples, FullCircleInside) {
  // A full ccw circle about (5,0) from (0,0): start tangent -Y, left normal +X: approach to (2,0);
  // the equidistant (radius 3) runs once round back to (2,0); G40 retracts to (-10,0).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 G3 X0 Y0 I5 J0\nN40 G1 G40 X-10 Y0\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {2, 0, 0}),
                  offset_arc({2, 0, 0}, {2, 0, 0}, {5, 0, 0}, true), line(K::kRetraction, {2, 0, 0}, {-10, 0, 0})});
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: ARC-CR-1
TEST(ArcExamples, CircleByRadius) {
  // From (10,0) to (0,10): chord sqrt200, CR = 10 gives h = sqrt(100 - 50) = sqrt50 along the
  // chord's normal. G3 CR=10 (short, ccw): centre (0,0). G2 CR=-10 back (long, cw): the other
  // side, (10,10). CR=5 cannot reach (2 * 5 < sqrt200): alarm 14040.
  Runs r = run_both("N10 G0 X10 Y0\nN20 G3 X0 Y10 CR=10\nN30 G2 X10 Y0 CR=-10\nN40 G3 X0 Y10 CR=5\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {10, 0, 0}), programmed_arc({10, 0, 0}, {0, 10, 0}, {0, 0, 0}, true),
                  programmed_arc({0, 10, 0}, {10, 0, 0}, {10, 10, 0}, false)});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 14040);
    EXPECT_EQ(x->alarms[0].clause, "ARC-CR-1");
  }
}

// A half circle given by CR= in a frame turned by 30 degrees: its end points go onto the grid
// (NC-GRID-1) and the chord of exactly 2|CR| in the program's system comes out up to two grid
// units longer. Within two units it is a half circle about the chord's midpoint; three units
// beyond (programmed) it stays unreachable.
// covers: ARC-CR-1 NC-GRID-1 NC-FRAME-4
TEST(ArcExamples, AHalfCircleByRadiusInATurnedFrameStillReachesItsEnd) {
  for (const char* chf : {"", " CHF=1"}) {
    Runs r = run_both(std::string("$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nN10 G17 G90 T1 D1\nN15 AROT RPL=30\n"
                                  "N20 G0 X-10 Y-10\nN30 G41 G1 X0 Y0 F800\nN40 G1 X60") +
                      chf + "\nN50 G3 X60 Y30 CR=15\nN60 G1 X0\nN70 G40 X-10 Y-10\nN80 M30\n");
    for (const RunResult* x : {&r.fast, &r.ref}) {
      EXPECT_TRUE(x->alarms.empty()) << chf;
      // (With the chamfer the contour stage gives the circle by its centre: ARC-CENTRE-2.)
      EXPECT_TRUE(has_decision(*x, *chf ? "ARC-CENTRE-2" : "ARC-CR-1", *chf ? "within" : "circle")) << chf;
    }
    EXPECT_EQ(r.fast.path.size(), r.ref.path.size()) << chf;
  }
  // Programmed decimals: a chord of 2|CR| + 2 units reaches, + 3 units does not.
  for (auto [end, reaches] : {std::pair{"30.000000002", true}, std::pair{"30.000000003", false}}) {
    Runs r = run_both(std::string("N10 G0 X0 Y0\nN20 G3 X") + end + " Y0 CR=15\n");
    for (const RunResult* x : {&r.fast, &r.ref}) EXPECT_EQ(x->alarms.empty(), reaches) << end;
  }
}

// covers: ARC-CR-1 TRC-ARC-EQ-1 TRC-CORNER-1
TEST(ArcExamples, CompensatedCircleByRadiusTangentToLines) {
  // TangentLineArcLineInsideTheCircle written with CR=10: the same path.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G3 X20 Y10 CR=10\nN50 G1 Y20\nN60 G40 X30 Y30\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), offset_arc({10, 2, 0}, {18, 10, 0}, {10, 10, 0}, true),
                  line(K::kOffset, {18, 10, 0}, {18, 20, 0}), line(K::kRetraction, {18, 20, 0}, {30, 30, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-1", "tangent"));
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: PATH-ELEMENT-2 TRC-ARC-CORNER-1 TRC-ARC-ELEMENT-1
TEST(ArcExamples, FullCircleOpenedBeforeItsStartIsAWholeTurnThenTheRest) {
  // r = 2, G41, G451. N30 runs along (1,1) into (0,0); N40 is the full ccw circle about (0,10).
  // The outer corner is cut at the intersection of the line's equidistant (t - sqrt2, t + sqrt2)
  // with the circle of radius 8: t^2 - 10t + 20 - 10 sqrt2 = 0, the nearer root
  // t = 5 - sqrt(5 + 10 sqrt2), P = (-0.78938620, 2.03904092), before the normal start (0,2). N40
  // then turns a whole turn and the rotation from P to (0,2): one arc from P to (0,2) would read as
  // that short rotation alone, so the whole turn comes first (P to P), then the rest.
  Runs r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G0 X-20 Y-20 T1 D1\nN20 G1 G41 G451 X-10 Y-10 F100\n"
      "N30 X0 Y0\nN40 G3 X0 Y0 I0 J10\nN50 G40 G1 X10 Y-10\n");
  ASSERT_TRUE(r.fast_ok && r.ref_ok);
  const double t = 5 - std::sqrt(5 + 10 * std::sqrt(2.0)), s2 = std::sqrt(2.0);
  PathPoint p{t - s2, t + s2, 0};
  expect_both(
      r, {line(K::kProgrammed, {0, 0, 0}, {-20, -20, 0}), line(K::kApproach, {-20, -20, 0}, {-10 - s2, -10 + s2, 0}),
          line(K::kOffset, {-10 - s2, -10 + s2, 0}, p), offset_arc(p, p, {0, 10, 0}, true),
          offset_arc(p, {0, 2, 0}, {0, 10, 0}, true), line(K::kRetraction, {0, 2, 0}, {10, -10, 0})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_EQ(x->path[3].start.x, x->path[3].end.x);
    EXPECT_EQ(x->path[3].start.y, x->path[3].end.y);
  }
}

// covers: PATH-ELEMENT-2 TRC-INNER-1
TEST(ArcExamples, FullCircleCutARoundingPastItsStartStaysAWholeTurn) {
  // r = 0: the equidistants are the contour. N30 is a full cw circle about (21.476, -30.438)
  // through (13.19, -30.038); N40's circle meets it again at (13.19, -30.038) itself, nearly
  // tangent, so fast's intersection lands a few 1e-12 mm from that point. Where it lands past
  // the start along N30, the arc would read as a sliver: it must end exactly at its start, a
  // whole turn, as ref's exact end does.
  Runs r =
      run_both(program("N20 G1 G42 X13.19 Y-30.038 F500\nN30 G2 X13.19 Y-30.038 I8.286 J-0.4\n"
                       "N40 G2 X26.138 Y-3.422 I37.526 J-1.798\nN50 G1 G40 X30 Y0\n",
                       "0"));
  ASSERT_TRUE(r.fast_ok && r.ref_ok);
  for (const RunResult* x : {&r.fast, &r.ref}) {
    const PathElement* circle = nullptr;
    for (const PathElement& e : x->path)
      if (e.type == ElementType::kArc && e.origin.line == 5) circle = &e;
    ASSERT_NE(circle, nullptr);
    EXPECT_EQ(circle->start.x, circle->end.x);
    EXPECT_EQ(circle->start.y, circle->end.y);
    EXPECT_NEAR(circle->start.x, 13.19, 1e-9);
    EXPECT_NEAR(circle->start.y, -30.038, 1e-9);
  }
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

std::vector<std::string> corner_kinds(const RunResult& r) {
  std::vector<std::string> kinds;
  for (const auto& d : r.decisions)
    if (d.clause == "TRC-CORNER-1") kinds.emplace_back(d.branch);
  return kinds;
}

// covers: TRC-CORNER-1
TEST(ArcExamples, TangentCornersAtCirclesWithACentreAreExactInBothEngines) {
  // A line along (3.217, 4.289), a ccw circle tangent to it (centre on its left normal, I/J the
  // normal itself), a line leaving along the circle's end tangent (-4.289, 3.217). In doubles the
  // tangents differ by a rounding (fast once took both corners as outer, with slivers of circle);
  // as integer vectors they are parallel: both engines decide tangent.
  Runs r =
      run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X3.217 Y4.289\nN40 G3 X2.145 Y11.795 I-4.289 J3.217\n"
                       "N50 G1 X-2.144 Y15.012\nN60 G40 X-10 Y15\n",
                       "0.5"));
  EXPECT_EQ(corner_kinds(r.fast), (std::vector<std::string>{"tangent", "tangent"}));
  EXPECT_EQ(corner_kinds(r.ref), corner_kinds(r.fast));
  // A centre a little off (I-4.29: the end lies 0.0008 off its circle, within MD21000) is moved
  // onto the chord's bisector (ARC-CENTRE-1): then the circle meets the line at an angle, and
  // both engines see the same kind at the first corner.
  Runs off =
      run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X3.217 Y4.289\nN40 G3 X2.145 Y11.795 I-4.29 J3.217\n"
                       "N50 G1 X-2.144 Y15.012\nN60 G40 X-10 Y15\n",
                       "0.5"));
  ASSERT_FALSE(corner_kinds(off.ref).empty());
  EXPECT_NE(corner_kinds(off.ref)[0], "tangent");
  EXPECT_EQ(corner_kinds(off.fast), corner_kinds(off.ref));
  // A full circle after a line tangent to it, and the line after it.
  Runs full =
      run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X3.217 Y4.289\nN40 G3 X3.217 Y4.289 I-4.289 J3.217\n"
                       "N50 G1 X6.434 Y8.578\nN60 G40 X10 Y0\n",
                       "0.5"));
  EXPECT_EQ(corner_kinds(full.fast), (std::vector<std::string>{"tangent", "tangent"}));
  EXPECT_EQ(corner_kinds(full.ref), corner_kinds(full.fast));
}

// covers: TRC-CORNER-1 ARC-CR-1
TEST(ArcExamples, TangentCornersAtCrCirclesAreExactInBothEngines) {
  // A line along (-10.788, -31.465), a cw CR= circle tangent to it (a 3-4-5 and an 8-15-17
  // triangle place its centre and end), a line leaving along its end tangent. The centre carries
  // a square root; in doubles fast took the corners as outer and inner, with a sliver of
  // transition circle at the first. Decided with the root (fast/src/root_tangent.hpp): tangent.
  Runs r =
      run_both(program("N20 G1 G42 X95.086 Y108.278 F100\nN30 X84.298 Y76.813\n"
                       "N40 G2 X81.8707 Y72.2281 CR=16.6315\nN50 G1 X61.9129 Y45.6177\nN60 G40 X50 Y40\n",
                       "0.4"));
  EXPECT_EQ(corner_kinds(r.fast), (std::vector<std::string>{"tangent", "tangent"}));
  EXPECT_EQ(corner_kinds(r.ref), corner_kinds(r.fast));
  // The same circle the long way round (CR=-16.6315): its centre on the other side of the chord,
  // the line meets it at an angle; both engines see the same kinds.
  Runs other =
      run_both(program("N20 G1 G42 X95.086 Y108.278 F100\nN30 X84.298 Y76.813\n"
                       "N40 G2 X81.8707 Y72.2281 CR=-16.6315\nN50 G1 X61.9129 Y45.6177\nN60 G40 X50 Y40\n",
                       "0.4"));
  ASSERT_FALSE(corner_kinds(other.ref).empty());
  EXPECT_NE(corner_kinds(other.ref)[0], "tangent");
  EXPECT_EQ(corner_kinds(other.fast), corner_kinds(other.ref));
}

}  // namespace
}  // namespace cutcom::test
