// Worked examples of the straight-line slice, one or more per clause. Every expected coordinate
// is derived by hand in the comment above it (radius r = 2 unless said otherwise); both engines
// must give it.
#include <cmath>

#include "support.hpp"

namespace cutcom::test {
namespace {

using K = OriginKind;
const double kSqrt5 = std::sqrt(5.0);

// The common start: tool T1 D1 with r = 2, at X-10 Y0 before the contour.
std::string program(const std::string& body, const std::string& radius = "2") {
  return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" + radius + "\nN10 G0 X-10 Y0 T1 D1\n" + body;
}

// covers: TRC-SEL-1 TRC-EQ-1 TRC-APPR-NORM-1 TRC-CORNER-1 TRC-INNER-1 TRC-DESEL-1 TRC-RETR-NORM-1 TRC-ELEMENT-1
TEST(SliceExamples, InnerCornerOnTheLeft) {
  // N30 runs +X: its left normal is (0,1), so NORM approaches (0,0)+2(0,1) = (0,2).
  // The corner at (10,0) turns left; G41 is on the inside: the equidistants y=2 and x=10-2=8
  // meet at (8,2). N40 runs +Y, left normal (-1,0): its equidistant is x=8, normal end (8,10).
  // G40 retracts straight to the programmed (20,20).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n"));
  EXPECT_TRUE(r.fast_ok && r.ref_ok);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8, 2, 0}), line(K::kOffset, {8, 2, 0}, {8, 10, 0}),
                  line(K::kRetraction, {8, 10, 0}, {20, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-1", "inner"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-CORNER-1", "inner"));
}

// covers: TRC-G450-1 TRC-CORNER-1 TRC-CORNER-4
TEST(SliceExamples, OuterCornerWithTransitionCircle) {
  // G42: right normal of +X is (0,-2) -> approach to (0,-2). At (10,0) the contour turns left,
  // G42 is outside: circle of radius 2 about (10,0) from (10,-2) to (10,0)+(2,0) = (12,0),
  // counter-clockwise (around the outside on the right). N40's equidistant x=12 up to (12,10).
  // The contour angle is 90 deg, not below MD20230 = 10 deg: G450 stays.
  Runs r = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {10, -2, 0}), arc({10, -2, 0}, {12, 0, 0}, {10, 0, 0}, true),
                  line(K::kOffset, {12, 0, 0}, {12, 10, 0}), line(K::kRetraction, {12, 10, 0}, {20, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-4", "keep-G450"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-CORNER-4", "keep-G450"));
}

// covers: TRC-G451-1 TRC-CORNER-3
TEST(SliceExamples, OuterCornerByIntersection) {
  // As above with G451: the equidistants y=-2 and x=12 meet at (12,-2); 90 deg <= MD20210.
  Runs r = run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {12, -2, 0}), line(K::kOffset, {12, -2, 0}, {12, 10, 0}),
                  line(K::kRetraction, {12, 10, 0}, {20, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-3", "keep-G451"));
}

// covers: TRC-CORNER-3 TRC-G450-1
TEST(SliceExamples, SharpCornerSwitchesG451ToG450) {
  // (0,0)->(10,0)->(0,5): cos(angle) = -100/(10*sqrt(125)) -> 153.43 deg > MD20210 = 100 deg, so
  // G451 becomes a circle. Right normal of (-10,5) is (5,10)/sqrt(125): the circle ends at
  // (10,0) + 2(5,10)/(5 sqrt5) = (10 + 2/sqrt5, 4/sqrt5). The turn is left, G42 outside: ccw.
  Runs r = run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 X0 Y5\nN50 G40 X-10 Y10\n"));
  PathPoint after{10 + 2 / kSqrt5, 4 / kSqrt5, 0};
  // N40's normal end: (0,5) + (2/sqrt5, 4/sqrt5).
  PathPoint end{2 / kSqrt5, 5 + 4 / kSqrt5, 0};
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {10, -2, 0}), arc({10, -2, 0}, after, {10, 0, 0}, true),
                  line(K::kOffset, after, end), line(K::kRetraction, end, {-10, 10, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-3", "switch-to-G450"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-CORNER-3", "switch-to-G450"));
}

// covers: TRC-CORNER-3 TRC-G451-1 MD-20210-1
TEST(SliceExamples, CornerLimitFromMachineData) {
  // The same corner with MD20210 = 160: G451 stays. trim = s r cross/(L + dot)
  // = -2*50/(50 sqrt5 - 100) = -(2 sqrt5 + 4): the intersection lies at (14 + 2 sqrt5, -2).
  MachineData md;
  md.set("MD20210", "160");
  Runs r = run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 X0 Y5\nN50 G40 X-10 Y10\n"), md);
  PathPoint x{14 + 2 * kSqrt5, -2, 0};
  PathPoint end{2 / kSqrt5, 5 + 4 / kSqrt5, 0};
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, x), line(K::kOffset, x, end), line(K::kRetraction, end, {-10, 10, 0})});
}

// covers: TRC-CORNER-4 TRC-G451-1 MD-20230-1
TEST(SliceExamples, FlatCornerSwitchesG450ToG451) {
  // (0,0)->(10,0)->(20,1): angle atan(1/10) = 5.71 deg < MD20230 = 10 deg: intersection instead of
  // a circle. trim = -2*10/(10 sqrt101 + 100) = -(2 sqrt101 - 20): x = (2 sqrt101 - 10, -2).
  // N40's right normal is (1,-10)/sqrt101: normal end (20 + 2/sqrt101, 1 - 20/sqrt101).
  Runs r = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 X20 Y1\nN50 G40 X30 Y1\n"));
  const double s101 = std::sqrt(101.0);
  PathPoint x{2 * s101 - 10, -2, 0};
  PathPoint end{20 + 2 / s101, 1 - 20 / s101, 0};
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, x), line(K::kOffset, x, end), line(K::kRetraction, end, {30, 1, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-4", "switch-to-G451"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-CORNER-4", "switch-to-G451"));
}

// covers: TRC-CORNER-1
TEST(SliceExamples, TangentTransitionInsertsNothing) {
  // Collinear blocks: the equidistants join at (10,2) without any inserted element.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 X20\nN50 G40 X30 Y10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kOffset, {10, 2, 0}, {20, 2, 0}),
                  line(K::kRetraction, {20, 2, 0}, {30, 10, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-CORNER-1", "tangent"));
}

// covers: TRC-G450-3 TRC-CORNER-1
TEST(SliceExamples, ReversalIsAlwaysACircle) {
  // (0,0)->(10,0)->(0,0) with G41 G451: a reversal has no intersection; the tool goes around
  // the end on a half circle about (10,0) from (10,2) to (10,-2), clockwise (left side).
  Runs r = run_both(program("N20 G1 G41 G451 X0 Y0 F100\nN30 X10\nN40 X0\nN50 G40 X-10 Y-10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), arc({10, 2, 0}, {10, -2, 0}, {10, 0, 0}, false),
                  line(K::kOffset, {10, -2, 0}, {0, -2, 0}), line(K::kRetraction, {0, -2, 0}, {-10, -10, 0})});
  EXPECT_TRUE(has_decision(r.fast, "TRC-CORNER-1", "reversal"));
}

// covers: TRC-LOOK-1 TRC-LOOK-2 ALARM-1 TRC-EDGE-5
TEST(SliceExamples, EquidistantsWithoutIntersectionRaise10751) {
  // N40 is 1 mm long; the inner corner before it would shorten it by r tan(45) = 2: its
  // equidistant x = 8 cannot reach y = 2 (too short). The look-ahead tries N50: its equidistant
  // y = 1 - 2 = -1 is parallel to N30's y = 2, no intersection; the G40 block ends the search.
  // G462 (initial setting) extends the last block N50 beyond its normal end (0,-1) along -X:
  // y = -1 never meets y = 2: alarm 10751 names N60. N30's equidistant was never fixed, so the path
  // stops at the approach.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y1\nN50 X0\nN60 G40 X-10 Y0\n"));
  EXPECT_FALSE(r.fast_ok);
  EXPECT_FALSE(r.ref_ok);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10751);
    EXPECT_EQ(x->alarms[0].line, 8);
    EXPECT_EQ(x->alarms[0].block, 60);
  }
  EXPECT_TRUE(has_decision(r.ref, "TRC-LOOK-1", "too-short"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-EDGE-5", "none"));
}

// covers: TRC-LOOK-1 TRC-LOOK-2 TRC-LOOK-3 MD-20240-1
TEST(SliceExamples, ShortBlockAtAnInnerCornerIsSkipped) {
  // A 0.707 mm chamfer N40 inside a corner: the corner N30/N40 (45 deg, inside) would shorten N40
  // by 2 tan(22.5) = 0.828 > 0.707: too short. The look-ahead intersects N30's equidistant y = 2
  // with N50's x = 10.5 - 2 = 8.5: (8.5,2), 1.5 after N50's normal start (8.5,0.5) and 8 before
  // its end: N40 is skipped, its M8 runs at (8.5,2).
  std::string body = "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 X10.5 Y0.5 M8\nN50 Y10\nN60 G40 X20 Y20\n";
  Runs r = run_both(program(body));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8.5, 2, 0}), line(K::kOffset, {8.5, 2, 0}, {8.5, 10, 0}),
                  line(K::kRetraction, {8.5, 10, 0}, {20, 20, 0})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_TRUE(has_decision(*x, "TRC-LOOK-3", "skipped"));
    ASSERT_EQ(x->actions.size(), 1u);
    expect_point(x->actions[0].at, {8.5, 2, 0}, "M8 of the skipped block");
  }
  // With MD20240 = 1 nothing after the adjacent block is examined: alarm 10751 at N40.
  MachineData md;
  md.set("MD20240", "1");
  Runs one = run_both(program(body), md);
  for (const RunResult* x : {&one.fast, &one.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10751);
    EXPECT_EQ(x->alarms[0].block, 40);
  }
}

// The look-ahead's decision TRC-LOOK-4 in `run` at `line`; fails the test when there is none.
const Decision& nearer_choice(const RunResult& run, int line) {
  static const Decision kNone{};
  for (const Decision& d : run.decisions)
    if (d.clause == "TRC-LOOK-4" && d.line == line) return d;
  ADD_FAILURE() << "no TRC-LOOK-4 decision at line " << line;
  return kNone;
}

// covers: TRC-LOOK-2 TRC-LOOK-4
TEST(SliceExamples, LookAheadTakesTheFurtherAlongOfTwoEquallyNearIntersections) {
  // Radius 1. N40 (0.5 mm up) is too short at the inner corner after N30. The look-ahead meets N30's
  // equidistant y = 1 with N50's, the circle of radius 5 + 1 about (10,-4.5), at x = 10 -+
  // sqrt(5.75): the points lie symmetric about x = 10, and N50's normal start (10,1.5) lies on
  // that axis. Equally near, exactly: the one further along N50's start tangent (+X) is taken,
  // and it lies on N50's equidistant.
  std::string tie =
      "N20 G1 G41 G450 X0 Y0 F500\nN30 X10\nN40 Y0.5\nN50 G2 X15 Y-4.5 I0 J-5\nN60 G1 Y-20\n"
      "N70 G40 X25\n";
  Runs r = run_both(program(tie, "1"));
  ASSERT_TRUE(r.fast_ok && r.ref_ok);
  const double x = 10 + std::sqrt(5.75);
  for (const RunResult* run : {&r.fast, &r.ref}) {
    const Decision& d = nearer_choice(*run, 7);
    EXPECT_EQ(d.branch, "tie");
    EXPECT_TRUE(has_decision(*run, "TRC-LOOK-2", "intersection"));
    ASSERT_GE(run->path.size(), 4u);
    expect_point(run->path[2].end, {x, 1, 0}, "N30's equidistant ends at the intersection");
  }
  EXPECT_EQ(nearer_choice(r.ref, 7).margin_exact, "0");
  EXPECT_EQ(nearer_choice(r.fast, 7).margin, 0);
  // N40 0.9 up, N50 a circle of radius 1 about (10.28,-0.06) (7-24-25): its normal start
  // (10,0.9) + (-0.28,0.96) = (9.72,1.86) lies 0.56 left of the axis x = 10.28, on the side of the
  // first point (behind along y = 1), which is the nearer by 0.56 (less than the carriers'
  // overlap, 0.94).
  Runs off =
      run_both(program("N20 G1 G41 G450 X0 Y0 F500\nN30 X10\nN40 Y0.9\nN50 G2 X11.28 Y-0.06 I0.28 J-0.96\n"
                       "N60 G1 Y-20\nN70 G40 X25\n",
                       "1"));
  const double by = 0.56;
  for (const RunResult* run : {&off.fast, &off.ref}) EXPECT_EQ(nearer_choice(*run, 7).branch, "first");
  EXPECT_NEAR(nearer_choice(off.fast, 7).margin, by, 1e-12);
  EXPECT_NEAR(std::stod(nearer_choice(off.ref, 7).margin_exact), by, 1e-15);
}

// covers: TRC-ELEMENT-1
TEST(SliceExamples, ElementShortenedToZeroVanishes) {
  // N40 is exactly 4 mm: the inner corners at both of its ends take r tan(45) = 2 mm each, so its
  // equidistant x = 8 has length 0 and is not output: both corners are at (8,2). N50 runs -X,
  // left normal (0,-1): equidistant y = 4-2 = 2, normal end (0,2).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y4\nN50 X0\nN60 G40 X-10 Y0\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8, 2, 0}), line(K::kOffset, {8, 2, 0}, {0, 2, 0}),
                  line(K::kRetraction, {0, 2, 0}, {-10, 0, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-ELEMENT-1", "vanishes"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-ELEMENT-1", "vanishes"));
}

// covers: TRC-DUMMY-1 PATH-ACTION-1
TEST(SliceExamples, InfeedBetweenCompensatedBlocksRunsAtTheCornerPoint) {
  // N35 moves only Z: it runs at the intersection point (8,2), from Z0 to Z-5; its M8 runs there.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN35 Z-5 M8\nN40 Y10\nN50 G40 X20 Y20\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8, 2, 0}), line(K::kInfeed, {8, 2, 0}, {8, 2, -5}),
                  line(K::kOffset, {8, 2, -5}, {8, 10, -5}), line(K::kRetraction, {8, 10, -5}, {20, 20, -5})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->actions.size(), 1u);
    EXPECT_EQ(x->actions[0].function.value, 8);
    expect_point(x->actions[0].at, {8, 2, 0}, "M8 position");
  }
}

// covers: TRC-DUMMY-2 MD-20250-1
TEST(SliceExamples, TooManyBlocksWithoutPlaneMotionRaise10762) {
  MachineData md;
  md.set("MD20250", "1");
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN31 Z-1\nN32 Z-2\nN40 Y10\nN50 G40 X20\n"), md);
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10762);
    EXPECT_EQ(x->alarms[0].block, 32);
  }
}

// covers: TRC-RADIUS-1 TOOL-EDGE-1
TEST(SliceExamples, EffectiveRadiusAddsWearAndOffn) {
  // 2.5 + (-0.3) + (-0.2) = 2: the path of InnerCornerOnTheLeft.
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2.5\n$TC_DP15[1,1]=-0.3\nN10 G0 X-10 Y0 T1 D1 OFFN=-0.2\n"
      "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n";
  Runs r = run_both(text);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8, 2, 0}), line(K::kOffset, {8, 2, 0}, {8, 10, 0}),
                  line(K::kRetraction, {8, 10, 0}, {20, 20, 0})});
}

// covers: TRC-RADIUS-2
TEST(SliceExamples, NegativeRadiusSwapsTheSide) {
  // r = -2 with G41 acts as G42 with r = 2: the path of OuterCornerWithTransitionCircle.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n", "-2"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, -2, 0}),
                  line(K::kOffset, {0, -2, 0}, {10, -2, 0}), arc({10, -2, 0}, {12, 0, 0}, {10, 0, 0}, true),
                  line(K::kOffset, {12, 0, 0}, {12, 10, 0}), line(K::kRetraction, {12, 10, 0}, {20, 20, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-RADIUS-2", "negative"));
}

// covers: TRC-G450-2
TEST(SliceExamples, ZeroRadiusFollowsTheContour) {
  // r = 0: every equidistant is the block itself, no transition circle at the outer corner.
  Runs r = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n", "0"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 0, 0}),
                  line(K::kOffset, {0, 0, 0}, {10, 0, 0}), line(K::kOffset, {10, 0, 0}, {10, 10, 0}),
                  line(K::kRetraction, {10, 10, 0}, {20, 20, 0})});
}

// covers: TRC-SEL-4
TEST(SliceExamples, SelectionWaitsForAPlaneAxis) {
  // N20 programs G41 with Z only: no selection yet; N30 selects (modal G41) and approaches.
  Runs r = run_both(program("N20 G1 G41 Z-1 F100\nN30 X0 Y0\nN40 X10\nN50 G40 X10 Y-10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kProgrammed, {-10, 0, 0}, {-10, 0, -1}),
                  line(K::kApproach, {-10, 0, -1}, {0, 2, -1}), line(K::kOffset, {0, 2, -1}, {10, 2, -1}),
                  line(K::kRetraction, {10, 2, -1}, {10, -10, -1})});
  EXPECT_TRUE(has_decision(r.fast, "TRC-SEL-4", "no-plane-axis"));
}

// covers: TRC-SEL-5
TEST(SliceExamples, D0SelectsNothing) {
  Runs r = run_both("N10 G0 X-10 T1 D0\nN20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G40 X20\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kProgrammed, {-10, 0, 0}, {0, 0, 0}),
                  line(K::kProgrammed, {0, 0, 0}, {10, 0, 0}), line(K::kProgrammed, {10, 0, 0}, {20, 0, 0})});
  EXPECT_EQ(r.fast.notices.size(), 1u);
  EXPECT_EQ(r.ref.notices.size(), 1u);
}

// covers: TRC-SEL-6 TRC-SEL-7 TRC-SEL-2 TRC-DESEL-2 TRC-PLANE-1 ALARM-1
TEST(SliceExamples, SelectionAndDeselectionAlarms) {
  struct Case {
    std::string text;
    int alarm;
  } cases[] = {
      {"N10 G1 G41 X0 Y0 F100\nN20 X10\n", 10750},                      // no tool
      {"N10 T1 D3\nN20 G1 G41 X0 Y0 F100\nN30 X10\n", 17181},           // edge not defined
      {"$TC_DP6[1,1]=2\nN10 T1 D1\nN20 G2 G41 X10 Y0 I5 J0\n", 10753},  // selection in a circle
      {"$TC_DP6[1,1]=2\nN10 T1 D1 G1 F1\nN20 G41 X10\nN30 X20\nN40 G40 G2 X30 I5 J0\n", 10754},
      {"$TC_DP6[1,1]=2\nN10 T1 D1 G1 F1\nN20 G41 X10\nN30 X20\nN40 G18 X30\n", 10757},
  };
  for (const Case& c : cases) {
    Runs r = run_both(c.text);
    for (const RunResult* x : {&r.fast, &r.ref}) {
      ASSERT_EQ(x->alarms.size(), 1u) << c.text;
      EXPECT_EQ(x->alarms[0].number, c.alarm) << c.text;
    }
  }
}

// covers: TRC-SEL-8
TEST(SliceExamples, DeselectionBeforeTheContourMeansNoSelection) {
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 G40 X10 Y5\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kProgrammed, {-10, 0, 0}, {0, 0, 0}),
                  line(K::kProgrammed, {0, 0, 0}, {10, 5, 0})});
}

// covers: TRC-DESEL-3
TEST(SliceExamples, DeselectionWithoutPlaneAxisLeavesTheToolAtTheNormalEnd) {
  // N40 programs G40 with Z only: N30 ends at its normal end (10,2), N40 lifts there; N50 retracts.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G40 Z5\nN50 X20 Y-5\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {10, 2, 5}),
                  line(K::kRetraction, {10, 2, 5}, {20, -5, 5})});
}

// covers: TRC-DESEL-3 NC-WORD-3 NC-WORD-4
TEST(SliceExamples, AJobRunsOnAfterG40WithoutPlaneAxis) {
  // The blocks between G40 Z100 and the next plane move are no empty blocks of an active
  // compensation: more of them than MD20250 (5) raise no alarm 10762. N130 selects again from
  // where the tool is.
  Runs r =
      run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G0 G40 Z100\nN50 M5\nN60 M9\nN70 T1 M6\n"
                       "N80 S1000 M3\nN90 M8\nN100 G4 F2\nN110 Z50\nN120 X30 Y0\nN130 G1 G41 X40 Y0\n"
                       "N140 X50\nN150 G40 X60 Y-10\n"));
  ASSERT_TRUE(r.fast.alarms.empty());
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {10, 2, 100}),
                  line(K::kRetraction, {10, 2, 100}, {10, 2, 50}), line(K::kRetraction, {10, 2, 50}, {30, 0, 50}),
                  line(K::kApproach, {30, 0, 50}, {40, 2, 50}), line(K::kOffset, {40, 2, 50}, {50, 2, 50}),
                  line(K::kRetraction, {50, 2, 50}, {60, -10, 50})});
  EXPECT_EQ(r.ref.actions.size(), 7u);  // M5 M9 M6 S1000 M3 M8 G4 F2, all at (10, 2, 100)
}

// covers: TRC-END-1
TEST(SliceExamples, ProgramEndingWithCompensationActive) {
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 M30\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0})});
  EXPECT_EQ(r.fast.notices.size(), 1u);
  EXPECT_EQ(r.ref.actions.size(), 1u);  // M30, at the end point
}

// covers: NC-PLANE-1 TRC-EQ-1
TEST(SliceExamples, PlaneG18UsesZAsAbscissaAndXAsOrdinate) {
  // G18: plane Z/X, applicate Y. A block along +Z has its left normal along +X: the approach
  // ends at Z0 X2. At Z10 the contour turns towards +X (left turn, G41 inside): the equidistants
  // X=2 and Z=8 meet at Z8 X2.
  std::string text =
      "$TC_DP6[1,1]=2\nN10 G18 G0 Z-10 X0 T1 D1\nN20 G1 G41 Z0 X0 F100\nN30 Z10\nN40 X10\nN50 G40 Z20 X20\n";
  Runs r = run_both(text);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 0, -10}), line(K::kApproach, {0, 0, -10}, {2, 0, 0}),
                  line(K::kOffset, {2, 0, 0}, {2, 0, 8}), line(K::kOffset, {2, 0, 8}, {10, 0, 8}),
                  line(K::kRetraction, {10, 0, 8}, {20, 0, 20})});
}

// covers: PATH-ELEMENT-1 NC-END-1
TEST(SliceExamples, UncompensatedProgramIsItsOwnPath) {
  Runs r = run_both("N10 G0 X10 Y10\nN20 G1 X10 Y10 F100\nN30 G91 X5 Y-5\nN40 M30\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {10, 10, 0}), line(K::kProgrammed, {10, 10, 0}, {15, 5, 0})});
  EXPECT_TRUE(r.fast.path[0].rapid);
  EXPECT_FALSE(r.fast.path[1].rapid);
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: TRC-SEL-3
TEST(SliceExamples, OneProgrammedPlaneAxisIsCompleted) {
  // N20 programs only X0: Y stays 0 from N10; the selection approaches (0,2) as usual.
  Runs r = run_both(program("N20 G1 G41 X0 F100\nN30 X10\nN40 G40 X20 Y10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {20, 10, 0})});
}

// covers: TRC-DUMMY-3
TEST(SliceExamples, ProgrammedAxisWithoutDisplacementIsABlockWithoutPlaneMotion) {
  // N35 programs X10 where the tool already is: no direction, it runs at the corner point (8,2).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN35 X10 Z-1\nN40 Y10\nN50 G40 X20 Y20\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {8, 2, 0}), line(K::kInfeed, {8, 2, 0}, {8, 2, -1}),
                  line(K::kOffset, {8, 2, -1}, {8, 10, -1}), line(K::kRetraction, {8, 10, -1}, {20, 20, -1})});
}

// covers: TRC-CORNER-2 TRC-CORNER-3 TRC-CORNER-4
TEST(SliceExamples, ContourAngleExactlyOnTheLimitDoesNotSwitch) {
  // A 90 deg outer corner with MD20210 = 90 is not above it: G451 stays (intersection (12,-2)).
  // A 45 deg outer corner with MD20230 = 45 is not below it: G450 stays (circle).
  MachineData md;
  md.set("MD20210", "90");
  Runs a = run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 Y10\nN50 G40 X20 Y20\n"), md);
  for (const RunResult* x : {&a.fast, &a.ref}) {
    EXPECT_TRUE(has_decision(*x, "TRC-CORNER-3", "keep-G451"));
    ASSERT_EQ(x->path.size(), 5u);
    expect_point(x->path[2].end, {12, -2, 0}, "intersection");
  }
  EXPECT_EQ(a.ref.decisions[4].margin_exact, "0");
  MachineData md2;
  md2.set("MD20230", "45");
  Runs b = run_both(program("N20 G1 G42 X0 Y0 F100\nN30 X10\nN40 X20 Y10\nN50 G40 X30 Y10\n"), md2);
  for (const RunResult* x : {&b.fast, &b.ref}) EXPECT_TRUE(has_decision(*x, "TRC-CORNER-4", "keep-G450"));
  // Directions 2e-9 deg above and 4e-9 deg below 100 deg (computed independently with 50-digit
  // mpmath: theta - 100 = +1.9874e-9 and -3.6551e-9). cos(100 deg) is irrational; the exact
  // comparison separates them, and so does fast here (far outside its band).
  Runs above =
      run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 X8.263518223 Y9.848077530\nN50 G40 X0 Y20\n"));
  Runs below =
      run_both(program("N20 G1 G42 G451 X0 Y0 F100\nN30 X10\nN40 X8.263518224 Y9.848077530\nN50 G40 X0 Y20\n"));
  for (const RunResult* x : {&above.ref, &above.fast}) EXPECT_TRUE(has_decision(*x, "TRC-CORNER-3", "switch-to-G450"));
  for (const RunResult* x : {&below.ref, &below.fast}) EXPECT_TRUE(has_decision(*x, "TRC-CORNER-3", "keep-G451"));
  EXPECT_EQ(above.ref.decisions[4].margin_exact.substr(0, 6), "1.9874");
  EXPECT_EQ(below.ref.decisions[4].margin_exact.substr(0, 7), "-3.6551");
}

// covers: TRC-UNSUP-1 TRC-DISC-1
TEST(SliceExamples, ConstructsNotYetSupportedAreRejectedWithTheirLine) {
  const std::pair<std::string, int> cases[] = {
      {program("N20 G1 G41 X0 Y0 F100\nN30 X10 DISC=10\n"), 5},
      {program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G40 KONTC X20 Y10\n"), 6},
      {program("N20 G1 G41 KONTT X0 Y0 F100\nN30 X10\n"), 4},
      {program("N20 G1 G41 KONTC X0 Y0 F100\nN30 X10\n"), 4},
      {program("N20 G1 G41 X0 Y0 F100\nN30 X10 OFFN=1\n"), 5},
      {program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 D2 X20\n"), 6},  // G41 again is TRC-SIDE-2
  };
  for (const auto& [text, line_no] : cases) expect_not_supported(text, line_no);
}

// covers: NC-ERR-2 ALARM-1
TEST(SliceExamples, ReadingErrorAfterAnAlarmStillRejectsTheProgram) {
  std::string text = program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y1\nN50 X0\nN60 G40 X-10 Y0\nN70 Q1\n");
  for (const char* engine : {"fast", "ref"}) {
    bool ok = true;
    EXPECT_THROW(run_engine(engine, text, {}, &ok), InputError) << engine;
  }
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: TRC-SIDE-1
TEST(SliceExamples, SideChangeWithoutG40IsANewSelection) {
  // N30 (+X, left side) ends at its normal end (10,2). N40 G42 is a selection block: from the tool
  // at (10,2) to the normal point of N50 (+X, right normal (0,-1)) at (10,10): (10,8). N50's
  // equidistant y = 8 to (20,8), then G40 to (30,10).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G42 X10 Y10\nN50 X20\nN60 G40 X30 Y10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kApproach, {10, 2, 0}, {10, 8, 0}),
                  line(K::kOffset, {10, 8, 0}, {20, 8, 0}), line(K::kRetraction, {20, 8, 0}, {30, 10, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-SIDE-1", "side-change"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-SIDE-1", "side-change"));
}

// covers: TRC-SIDE-2
TEST(SliceExamples, TheSameG41AgainIsANewSelection) {
  // N30 (+X, left) ends at its normal end (10,2). N40 programs G41 again: a selection block from
  // the tool at (10,2) to the normal point of N50 (+X, left normal (0,1)) at (10,10): (10,12).
  // N50's equidistant y = 12 to (20,12), then G40 to (30,10). Without N40's G41 the corner at
  // (10,0) and (10,10) would be intersections instead: (8,2), (8,12).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G41 X10 Y10\nN50 X20\nN60 G40 X30 Y10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kApproach, {10, 2, 0}, {10, 12, 0}),
                  line(K::kOffset, {10, 12, 0}, {20, 12, 0}), line(K::kRetraction, {20, 12, 0}, {30, 10, 0})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-SIDE-2", "selected-again"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-SIDE-2", "selected-again"));
}

// covers: TRC-SIDE-2 TRC-UNSUP-1
TEST(SliceExamples, AnEdgeProgrammedWithG41AgainStartsWithItsRadius) {
  // D2 (r = 3) comes with G41 alone in N40: no plane axis, so N40 and N45 (Z1) are held back and
  // run at N30's normal end (10,2); N50 is the selection block, to (10,10) + 3 (0,1) = (10,13).
  std::string body =
      "$TC_DP1[1,2]=120\n$TC_DP6[1,2]=3\n"
      "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 G41 D2\nN45 Z1\nN50 X10 Y10\nN55 X20\nN60 G40 X30 Y10\n";
  Runs r = run_both(program(body));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kInfeed, {10, 2, 0}, {10, 2, 1}),
                  line(K::kApproach, {10, 2, 1}, {10, 13, 1}), line(K::kOffset, {10, 13, 1}, {20, 13, 1}),
                  line(K::kRetraction, {20, 13, 1}, {30, 10, 1})});
  EXPECT_TRUE(has_decision(r.ref, "TRC-SIDE-2", "no-plane-axis"));
  EXPECT_TRUE(has_decision(r.fast, "TRC-SIDE-2", "no-plane-axis"));
}

// covers: TRC-ELEMENT-1
TEST(SliceExamples, AVanishingElementStillRunsItsApplicateMotion) {
  // N40 (+Y, 2 long) between N30 (+X) and N50 (-X) on the left (r = 1): the equidistants of N30
  // (y = 1) and N50 (y = 1) meet N40's (x = 9) at (9,1) and (9,1): its element has length 0. It
  // moves Z from 0 to -1: that runs at (9,1), and N50 starts at Z-1 (no gap).
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 Y2 Z-1\nN50 X0 Y2\nN60 G40 X-10 Y2\n", "1"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 1, 0}),
                  line(K::kOffset, {0, 1, 0}, {9, 1, 0}), line(K::kInfeed, {9, 1, 0}, {9, 1, -1}),
                  line(K::kOffset, {9, 1, -1}, {0, 1, -1}), line(K::kRetraction, {0, 1, -1}, {-10, 2, -1})});
  for (const RunResult* x : {&r.ref, &r.fast}) EXPECT_TRUE(has_decision(*x, "TRC-ELEMENT-1", "vanishes"));
}

// covers: TRC-RADIUS-3 TRC-UNSUP-1
TEST(SliceExamples, ADChangeWhileActiveIsBlendedOverItsBlock) {
  // D2 (r = 3) in N40 without G41: the corner N30/N40 is taken with r = 2 (a tangent: (10,2)),
  // the corner N40/N50 with r = 3: N50 (+X) and N60 (+Y) meet inside at (30-3, 0+3) = (27,3).
  // N40 runs inclined from (10,2) to its end on the new equidistant, (20,3).
  const std::string d2 = "$TC_DP1[1,2]=120\n$TC_DP6[1,2]=3\n";
  Runs r = run_both(program(d2 + "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 D2 X20\nN50 X30\nN60 Y10\nN70 G40 X40 Y20\n"));
  const std::vector<Expect> blended{
      line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}),  line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
      line(K::kOffset, {0, 2, 0}, {10, 2, 0}),       line(K::kOffset, {10, 2, 0}, {20, 3, 0}),
      line(K::kOffset, {20, 3, 0}, {27, 3, 0}),      line(K::kOffset, {27, 3, 0}, {27, 10, 0}),
      line(K::kRetraction, {27, 10, 0}, {40, 20, 0})};
  expect_both(r, blended);
  for (const RunResult* x : {&r.ref, &r.fast}) EXPECT_TRUE(has_decision(*x, "TRC-RADIUS-3", "blend"));
  // The corner at N40's end turns outside (G450): its circle has the new radius about (20,0),
  // from (20,3) to N50's normal start (20+3, 0), clockwise on the left.
  Runs o = run_both(program(d2 + "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 D2 X20\nN50 Y-10\nN60 G40 X30 Y-20\n"));
  expect_both(o, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kOffset, {10, 2, 0}, {20, 3, 0}),
                  arc({20, 3, 0}, {23, 0, 0}, {20, 0, 0}, false), line(K::kOffset, {23, 0, 0}, {23, -10, 0}),
                  line(K::kRetraction, {23, -10, 0}, {30, -20, 0})});
  // A tool change is blended as a D change is: T2 D1 (r = 3) in N40 gives D2's path.
  Runs t = run_both(program(d2 + "$TC_DP1[2,1]=120\n$TC_DP6[2,1]=3\nN20 G1 G41 X0 Y0 F100\nN30 X10\nN40 T2 D1 X20\n"
                                 "N50 X30\nN60 Y10\nN70 G40 X40 Y20\n"));
  expect_both(t, blended);
  // Not specified (yet): in a circle (a spiral), under CDON, in the first contour block, a
  // turning tool's new tip (its edge centre lies elsewhere from the tip: TOOL-TURN-1).
  expect_not_supported(program(d2 + "N20 G1 G41 X0 Y0 F100\nN30 X10\nN40 D2 G3 X20 Y0 CR=5\nN50 G40 X30\n"), 8);
  expect_not_supported(program(d2 + "N20 G1 G41 CDON X0 Y0 F100\nN30 X10\nN40 D2 X20\nN50 G40 X30\n"), 8);
  expect_not_supported(program(d2 + "N20 G1 G41 X0 Y0 F100\nN30 D2 X10\nN40 G40 X30\n"), 7);
  const std::string turning =
      "$TC_DP1[1,1]=500\n$TC_DP2[1,1]=3\n$TC_DP6[1,1]=0.4\n$TC_DP1[1,2]=500\n$TC_DP2[1,2]=3\n$TC_DP6[1,2]=0.8\n"
      "G18 T1 D1\nG0 X30 Z5\nG1 G42 X20 Z0 F0.2\nZ-10\n";
  expect_not_supported(turning + "D2 Z-20\nG40 X40\n", 11);
  expect_not_supported(turning + "OFFN=0.1\nZ-20\nD2\nG40 X40\n", 13);
}

// covers: TRC-SIDE-3 TRC-SEL-4 TRC-SEL-1
TEST(SliceExamples, ANewSelectionBeforeAnyContourLeavesTheFirstWithout) {
  // N25 programs G41 again before any block moved in the plane: N20 has no contour and runs as
  // programmed, N25 (no plane axis) too. N30 is then the selection block, but N40 selects anew
  // (G42) before N30 had a contour: N30 runs as programmed to (10,0,1). N40 approaches the normal
  // point of N50 (+X, right normal (0,-1)): (20,-2); N50's equidistant y = -2 to (30,-2), G40.
  Runs r = run_both(program("N20 G1 G41 X0 Y0 F100\nN25 G41 Z1\nN30 X10\nN40 G42 X20\nN50 X30\nN60 G40 X40 Y-10\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kProgrammed, {-10, 0, 0}, {0, 0, 0}),
                  line(K::kProgrammed, {0, 0, 0}, {0, 0, 1}), line(K::kProgrammed, {0, 0, 1}, {10, 0, 1}),
                  line(K::kApproach, {10, 0, 1}, {20, -2, 1}), line(K::kOffset, {20, -2, 1}, {30, -2, 1}),
                  line(K::kRetraction, {30, -2, 1}, {40, -10, 1})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-SIDE-3", "before-contour"));
    EXPECT_TRUE(has_decision(*x, "TRC-SEL-4", "no-plane-axis"));
  }
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: TRC-G450-1 TRC-CORNER-4 TRC-DESEL-1 TRC-RETR-NORM-1
TEST(SliceExamples, ProgrammingManualOuterCornerExampleWithNorm) {
  // Digest §7 (PGA19 p.269, PGA04 p.8-39): N10-N60 and N80-N100, with NORM for KONT (KONT is
  // issue #4; from X35 Y0 the start lies behind the contour) and a tool radius of 5 assumed (the
  // manual gives none). N40 runs +Y: left normal (-1,0), equidistant x = 5, approach to (5,10).
  // At (10,60) the contour turns right into (0.8,-0.6): outer for G41, 126.87 deg, circle
  // about (10,60) from (5,60) to (10,60) + 5 (0.6,0.8) = (13,64), clockwise. At (50,30) it turns
  // right into (-2,-1)/sqrt5: outer, 116.57 deg, circle from (53,34) to
  // (50,30) + 5 (1,-2)/sqrt5 = (50 + sqrt5, 30 - 2 sqrt5). N60 ends at its normal point
  // (10 + sqrt5, 10 - 2 sqrt5); G40 retracts to (-20,50); then G0 Y100 and X200.
  const double s5 = std::sqrt(5.0);
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\n"
      "N10 G17 T1 D1 G0 X35 Y0 Z0 F500\nN20 G1 Z-5\nN30 G41 NORM G450 X10 Y10\nN40 Y60\nN50 X50 Y30\nN60 X10 Y10\n"
      "N80 G40 X-20 Y50\nN90 G0 Y100\nN100 X200 M30\n";
  Runs r = run_both(text);
  expect_both(
      r, {line(K::kProgrammed, {0, 0, 0}, {35, 0, 0}), line(K::kProgrammed, {35, 0, 0}, {35, 0, -5}),
          line(K::kApproach, {35, 0, -5}, {5, 10, -5}), line(K::kOffset, {5, 10, -5}, {5, 60, -5}),
          arc({5, 60, -5}, {13, 64, -5}, {10, 60, -5}, false), line(K::kOffset, {13, 64, -5}, {53, 34, -5}),
          arc({53, 34, -5}, {50 + s5, 30 - 2 * s5, -5}, {50, 30, -5}, false),
          line(K::kOffset, {50 + s5, 30 - 2 * s5, -5}, {10 + s5, 10 - 2 * s5, -5}),
          line(K::kRetraction, {10 + s5, 10 - 2 * s5, -5}, {-20, 50, -5}),
          line(K::kProgrammed, {-20, 50, -5}, {-20, 100, -5}), line(K::kProgrammed, {-20, 100, -5}, {200, 100, -5})});
}

}  // namespace
}  // namespace cutcom::test
