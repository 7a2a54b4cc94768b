// Worked examples for approach and retraction (spec/approach-retraction.md), derived by hand.
#include "support.hpp"

namespace cutcom::test {
namespace {

using K = OriginKind;

std::string tool(const std::string& radius = "2") { return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" + radius + "\n"; }

bool alarm_is(const RunResult& r, int number, int line_no) {
  return r.alarms.size() == 1 && r.alarms[0].number == number && r.alarms[0].line == line_no;
}

// covers: TRC-KONT-1
TEST(ApproachRetraction, KontInFrontOrOnTheLineIsNorm) {
  // The start (-10,0) and the end (20,0) lie on the tangent lines y = 0 of N30: in front, margin 0,
  // so the path is NORM's: to (0,2), along y = 2, off to (20,0).
  Runs on = run_both(tool() + "N10 G0 X-10 Y0 T1 D1\nN20 G1 G41 KONT X0 Y0 F100\nN30 X10\nN40 G40 X20 Y0\n");
  for (const RunResult* x : {&on.ref, &on.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-1", "in-front"));
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-1", "behind"));
  }
  expect_both(on, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 2, 0}),
                   line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {20, 0, 0})});
  EXPECT_EQ(on.ref.decisions[2].margin_exact, "0");
  // Strictly in front: start (5,7) and end (15,9) above y = 0, on the compensation side (G41).
  Runs front = run_both(tool() + "N10 G0 X5 Y7 T1 D1\nN20 G1 G41 KONT X0 Y0 F100\nN30 X10\nN40 G40 X15 Y9\n");
  expect_both(front, {line(K::kProgrammed, {0, 0, 0}, {5, 7, 0}), line(K::kApproach, {5, 7, 0}, {0, 2, 0}),
                      line(K::kOffset, {0, 2, 0}, {10, 2, 0}), line(K::kRetraction, {10, 2, 0}, {15, 9, 0})});
  EXPECT_EQ(front.ref.decisions[2].margin_exact, "7");
}

// covers: TRC-KONT-1
TEST(ApproachRetraction, KontOnTheTangentLineOfACircleIsInFrontInBothEngines) {
  // N30 is a ccw circle about S + (5.726, 8.917): its tangent at S = (-2.202, 9.42) is
  // (8.917, -5.726), and the start (-20.036, 20.872) = S - 2 (8.917, -5.726) lies exactly on that
  // line: in front (TRC-KONT-1's boundary rule), NORM. In doubles the start lay a rounding behind
  // it for fast, which travelled around S; the exact tangent decides as ref does.
  Runs r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.5\nN10 G0 X-20.036 Y20.872 T1 D1\nN20 G1 G41 KONT X-2.202 Y9.420 F100\n"
      "N30 G3 X12.441 Y12.611 I5.726 J8.917\nN40 G40 NORM G1 X32.441 Y32.611\n");
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-1", "in-front"));
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-1", "behind"));
  }
}

// covers: TRC-KONT-1 ARC-CR-1
TEST(ApproachRetraction, KontOnTheTangentLineOfACrCircleIsInFrontInBothEngines) {
  // N30 is a cw CR= circle whose tangent at S = (84.298, 76.813) runs along (-10.788, -31.465);
  // the start S - (-10.788, -31.465) lies exactly on that line. The tangent carries the centre's
  // square root: in doubles the start lay 1.4e-14 mm behind it for fast; with the root, in front
  // as ref decides (TRC-KONT-1's boundary rule).
  Runs r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.5\nN10 G0 X95.086 Y108.278 T1 D1\nN20 G1 G42 KONT X84.298 Y76.813 F100\n"
      "N30 G2 X81.8707 Y72.2281 CR=16.6315\nN40 G1 X61.9129 Y45.6177\nN50 G40 NORM G1 X50 Y40\n");
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-1", "in-front"));
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-1", "behind"));
  }
}

// covers: TRC-KONT-1 TRC-KONT-3 TRC-CORNER-4
TEST(ApproachRetraction, ProgrammingManualExampleWithKontAndG450) {
  // Digest §7 (PGA19 p.269, PGA04 p.8-39) as printed, r = 5 assumed. N40 runs +Y from S = (10,10);
  // compensation on its left (-X). The start (35,0) lies at x > 10: behind (margin -25). The approach
  // line d1 = S - P0 = (-25,10), left normal (-2,-5)/sqrt29: A = S + 5 (-2,-5)/sqrt29; deflection
  // 68.2 deg (above MD20230 = 10: circle) about S from A clockwise to (5,10).
  // Retraction: N60 ends at E = (10,10) with t2 = (-2,-1)/sqrt5; the end (-20,50) gives
  // cross(t2, P0 - E) = cross((-2,-1), (-30,40)) = -110 < 0: behind. N60's equidistant ends at
  // E + 5 (1,-2)/sqrt5; the circle about E, clockwise (79.7 deg), to R = E + 5 n(d2),
  // d2 = (-30,40)/50, n = (-0.8,-0.6): R = (6,7); then straight to (-20,50).
  const double s5 = std::sqrt(5.0), s29 = std::sqrt(29.0);
  std::string text = tool("5") +
                     "N10 G17 T1 D1 G0 X35 Y0 Z0 F500\nN20 G1 Z-5\nN30 G41 KONT G450 X10 Y10\nN40 Y60\nN50 X50 Y30\n"
                     "N60 X10 Y10\nN80 G40 X-20 Y50\nN90 G0 Y100\nN100 X200 M30\n";
  Runs r = run_both(text);
  PathPoint a{10 - 10 / s29, 10 - 25 / s29, -5};
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {35, 0, 0}), line(K::kProgrammed, {35, 0, 0}, {35, 0, -5}),
                  line(K::kApproach, {35, 0, -5}, a), arc(a, {5, 10, -5}, {10, 10, -5}, false),
                  line(K::kOffset, {5, 10, -5}, {5, 60, -5}), arc({5, 60, -5}, {13, 64, -5}, {10, 60, -5}, false),
                  line(K::kOffset, {13, 64, -5}, {53, 34, -5}),
                  arc({53, 34, -5}, {50 + s5, 30 - 2 * s5, -5}, {50, 30, -5}, false),
                  line(K::kOffset, {50 + s5, 30 - 2 * s5, -5}, {10 + s5, 10 - 2 * s5, -5}),
                  arc({10 + s5, 10 - 2 * s5, -5}, {6, 7, -5}, {10, 10, -5}, false),
                  line(K::kRetraction, {6, 7, -5}, {-20, 50, -5}), line(K::kProgrammed, {-20, 50, -5}, {-20, 100, -5}),
                  line(K::kProgrammed, {-20, 100, -5}, {200, 100, -5})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-3", "circle"));
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-1", "in-front"));
  }
  EXPECT_EQ(r.ref.decisions[2].margin_exact, "-25");  // TRC-KONT-1 at N30: (35 - 10) behind x = 10
}

// covers: TRC-KONT-4 TRC-CORNER-3
TEST(ApproachRetraction, KontWithG451MeetsTheExtendedEquidistant) {
  // From (-10,-10) to S = (0,0), N30 along +X, G41 (compensation side +Y): behind. Approach line
  // (1,1)/sqrt2, deflection 45 deg (G451 kept, MD20210 = 100). Its equidistant passes
  // A = (-sqrt2, sqrt2) with direction (1,1) and meets y = 2 at X = (2 - 2 sqrt2, 2).
  // Retraction from E = (20,0) to (30,-10): behind; R = E + 2 (1,1)/sqrt2, the line R + t (1,-1)
  // meets y = 2 at (18 + 2 sqrt2, 2).
  const double s2 = std::sqrt(2.0);
  Runs r = run_both(tool() + "N10 G0 X-10 Y-10 T1 D1\nN20 G1 G41 KONT G451 X0 Y0 F100\nN30 X20\nN40 G40 X30 Y-10\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, -10, 0}), line(K::kApproach, {-10, -10, 0}, {2 - 2 * s2, 2, 0}),
                  line(K::kOffset, {2 - 2 * s2, 2, 0}, {18 + 2 * s2, 2, 0}),
                  line(K::kRetraction, {18 + 2 * s2, 2, 0}, {30, -10, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-4", "intersection"));
    EXPECT_TRUE(has_decision(*x, "TRC-CORNER-3", "keep-G451"));
  }
  // At 135 deg (start (10,-10)) G451 switches to the circle: A = 2 (-1,-1)/sqrt2, circle to (0,2);
  // the retraction to (20,2) (in front) has length 0 and is not output.
  Runs sharp = run_both(tool() + "N10 G0 X10 Y-10 T1 D1\nN20 G1 G41 KONT G451 X0 Y0 F100\nN30 X20\nN40 G40 Y2\n");
  expect_both(sharp, {line(K::kProgrammed, {0, 0, 0}, {10, -10, 0}), line(K::kApproach, {10, -10, 0}, {-s2, -s2, 0}),
                      arc({-s2, -s2, 0}, {0, 2, 0}, {0, 0, 0}, false), line(K::kOffset, {0, 2, 0}, {20, 2, 0})});
}

// covers: TRC-KONT-2
TEST(ApproachRetraction, KontNeedsRoomAroundTheStartAndEndPoint) {
  // Behind and inside the circle of radius 2 about S = (0,0): alarm 10755 at the selection block.
  Runs in = run_both(tool() + "N10 G0 X1 Y-1 T1 D1\nN20 G1 G41 KONT X0 Y0 F100\nN30 X20\nN40 G40 X30 Y5\n");
  EXPECT_TRUE(alarm_is(in.ref, 10755, 4));
  EXPECT_TRUE(alarm_is(in.fast, 10755, 4));
  EXPECT_EQ(in.ref.path.size(), 1u);  // only N10
  // On the circle is room: from (0,-2) straight to A = (-2,0), then about S to (0,2).
  Runs on = run_both(tool() + "N10 G0 X0 Y-2 T1 D1\nN20 G1 G41 KONT X0 Y0 F100\nN30 X20\nN40 G40 X21 Y-1\n");
  EXPECT_TRUE(alarm_is(on.ref, 10756, 6));  // the end (21,-1) lies behind, inside the circle about (20,0)
  EXPECT_TRUE(alarm_is(on.fast, 10756, 6));
  expect_both(on, {line(K::kProgrammed, {0, 0, 0}, {0, -2, 0}), line(K::kApproach, {0, -2, 0}, {-2, 0, 0}),
                   arc({-2, 0, 0}, {0, 2, 0}, {0, 0, 0}, false)});
  for (const RunResult* x : {&on.ref, &on.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-2", "room"));
    EXPECT_TRUE(has_decision(*x, "TRC-KONT-2", "inside"));
  }
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

using K = OriginKind;

std::string retraction_case(const std::string& strategy) {
  // r = 5. N30 runs +X (equidistant y = 5); N40 goes up 3 < r at an inner corner: its equidistant
  // x = 35 ends at (35,3) below y = 5, too short; the look-ahead meets the deselection N50.
  return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F100\nN30 X40\nN40 Y3\nN50 G40 " +
         strategy + " X20 Y20\n";
}

// covers: TRC-EDGE-1 TRC-EDGE-2 TRC-EDGE-3 TRC-EDGE-4 TRC-EDGE-5 MD-20150-1
TEST(ApproachRetraction, TooShortLastBlockWithG460G461G462) {
  // G462 (initial setting): N40's equidistant extended beyond (35,3) along +Y meets y = 5 at (35,5).
  // G461: the circle of radius 5 about N40's end (40,3) meets y = 5 at 40 -+ sqrt21; the first
  // along N30 is (40 - sqrt21, 5): the tool touches the corner point and N30.
  // G460: the line from (35,3) to the end (20,20) meets y = 5 at t = 2/17: (35 - 30/17, 5).
  // In each case N40 is skipped and the retraction runs from the hit to (20,20).
  const double hits[] = {35, 40 - std::sqrt(21.0), 35 - 30.0 / 17};
  const char* words[] = {"", "G461", "G460"};
  const char* names[] = {"G462", "G461", "G460"};
  for (int i = 0; i < 3; ++i) {
    Runs r = run_both(retraction_case(words[i]));
    expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 5, 0}),
                    line(K::kOffset, {0, 5, 0}, {hits[i], 5, 0}), line(K::kRetraction, {hits[i], 5, 0}, {20, 20, 0})});
    for (const RunResult* x : {&r.ref, &r.fast}) {
      EXPECT_TRUE(has_decision(*x, "TRC-EDGE-1", names[i])) << names[i];
      EXPECT_TRUE(has_decision(*x, "TRC-EDGE-5", "hit")) << names[i];
      EXPECT_TRUE(has_decision(*x, "TRC-LOOK-3", "skipped")) << names[i];
    }
  }
  // MD20150[47] = 2 makes G461 the initial setting.
  MachineData md;
  md.set("MD20150[47]", "2");
  Runs g461 = run_both(retraction_case(""), md);
  EXPECT_TRUE(has_decision(g461.ref, "TRC-EDGE-1", "G461"));
  EXPECT_TRUE(has_decision(g461.fast, "TRC-EDGE-1", "G461"));
}

std::string manual_g461(const std::string& strategy) {
  return "N10 $TC_DP1[1,1]=120 ; Tool type mill\nN20 $TC_DP6[1,1]=10 ; Radius\nN30 X0 Y0 F10000 T1 D1\nN40 Y20\n"
         "N50 G42 X50 Y5 " +
         strategy + "\nN60 Y0 F600\nN70 X30\nN80 X20 Y-5\nN90 X0 Y0 G40\nN100 M30\n";
}

// covers: TRC-EDGE-1 TRC-EDGE-3 TRC-EDGE-4 TRC-EDGE-5 TRC-G450-1
TEST(ApproachRetraction, ManualG461ApproachExample) {
  // Digest §2.6 (FM06 p.94) verbatim. r = 10, G42. The first block N60 runs -Y from (50,5) to (50,0)
  // (equidistant x = 40, 5 long); N70 runs -X (equidistant y = 10). The inner corner's intersection
  // (40,10) lies before N60's normal start (40,5): N60 would run backwards. G461: the circle of
  // radius 10 about N60's start (50,5) meets y = 10 at 50 -+ 5 sqrt3; on N70's equidistant (x from
  // 50 to 30) only 50 - 5 sqrt3. The approach goes there, N60 is skipped. N70/N80 is an outer corner
  // (left turn, G42): circle about (30,0) from (30,10) to (30,0) - 10 (1,-2)/sqrt5; N80's
  // equidistant ends at (20,-5) - 10 (1,-2)/sqrt5; G40 retracts to (0,0). No G1: all moves are G0.
  const double s3 = std::sqrt(3.0), s5 = std::sqrt(5.0);
  PathPoint c{30 - 10 / s5, 20 / s5, 0}, e{20 - 10 / s5, -5 + 20 / s5, 0};
  Runs r = run_both(manual_g461("G461"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kApproach, {0, 20, 0}, {50 - 5 * s3, 10, 0}),
                  line(K::kOffset, {50 - 5 * s3, 10, 0}, {30, 10, 0}), arc({30, 10, 0}, c, {30, 0, 0}, true),
                  line(K::kOffset, c, e), line(K::kRetraction, e, {0, 0, 0})});
  // G462: N60's equidistant extended backwards from (40,5) along +Y meets y = 10 at (40,10).
  Runs g462 = run_both(manual_g461("G462"));
  expect_both(g462, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kApproach, {0, 20, 0}, {40, 10, 0}),
                     line(K::kOffset, {40, 10, 0}, {30, 10, 0}), arc({30, 10, 0}, c, {30, 0, 0}, true),
                     line(K::kOffset, c, e), line(K::kRetraction, e, {0, 0, 0})});
}

// covers: TRC-EDGE-2 TRC-EDGE-5 ALARM-1
TEST(ApproachRetraction, G460ApproachFindsNoIntersection) {
  // G460: the approach line from (0,20) to N60's normal start (40,5) meets y = 10 at x = 26.7,
  // outside N70's equidistant (30..50): alarm 10751 names N70; the approach line was decided and
  // is output.
  Runs r = run_both(manual_g461("G460"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kApproach, {0, 20, 0}, {40, 5, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10751);
    EXPECT_EQ(x->alarms[0].line, 7);
    EXPECT_TRUE(has_decision(*x, "TRC-EDGE-5", "none"));
  }
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: TRC-EDGE-6 TRC-KONT-1 TRC-KONT-2 TRC-LOOK-3
TEST(ApproachRetraction, KontFromBehindAfterATooShortLastBlockMeetsTheInsertedCircle) {
  // r = 5, G41: N30 along y = 0 (equidistant y = 5), N40 3 mm up (x = 35) is too short. The end
  // (60,20) lies behind N40's line x = 40, 26.2 mm from E = (40,3): the circle r about E is
  // inserted (G450, 49.6 deg) whatever G462 says. N30's equidistant meets it first at
  // (40 - sqrt21, 5); the rest of the circle, clockwise, runs to R = E + 5 (-17,20)/sqrt689;
  // N40 is skipped; then the line to (60,20).
  Runs r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F100\nN30 X40\n"
      "N40 Y3\nN50 G40 KONT X60 Y20\n");
  const double s21 = std::sqrt(21.0), s689 = std::sqrt(689.0);
  PathPoint x{40 - s21, 5, 0}, rp{40 - 85 / s689, 3 + 100 / s689, 0};
  expect_both(r,
              {line(K::kProgrammed, {0, 0, 0}, {-10, 0, 0}), line(K::kApproach, {-10, 0, 0}, {0, 5, 0}),
               line(K::kOffset, {0, 5, 0}, x), arc(x, rp, {40, 3, 0}, false), line(K::kRetraction, rp, {60, 20, 0})});
  for (const RunResult* run : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*run, "TRC-EDGE-6", "circle"));
    EXPECT_TRUE(has_decision(*run, "TRC-LOOK-3", "skipped"));
  }
}

// covers: TRC-KONT-1 TRC-SIDE-1
TEST(ApproachRetraction, KontAtASideChangeWithRadiusZeroIsDecidedOnTheProgrammedPoint) {
  // Radius 0: after the side change the tool stands on N30's end, and N40 runs back along N50's
  // line, so the start lies exactly on N50's tangent line: in front, margin 0. In double the unit
  // tangent makes the cross product 1.8e-15, which with G41 read as "behind" (a circle around S).
  Runs r = run_both(tool("0") +
                    "N10 G0 X0 Y0 T1 D1\nN20 G1 G42 X0 Y0 F500\nN30 X-2.540 Y11.187\n"
                    "N40 G41 KONT X7.620 Y-33.561\nN50 X-2.540 Y11.187\nN60 G40 X0 Y0\n");
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-1", "behind"));
    EXPECT_FALSE(has_decision(*x, "TRC-KONT-3", "circle"));
  }
  for (const Decision& d : r.fast.decisions) {
    if (d.clause == "TRC-KONT-1" && d.line == 6) {
      EXPECT_EQ(d.margin, 0.0);
    }
  }
  for (const Decision& d : r.ref.decisions) {
    if (d.clause == "TRC-KONT-1" && d.line == 6) {
      EXPECT_EQ(d.margin_exact, "0");
    }
  }
}

// covers: TRC-EDGE-7
TEST(ApproachRetraction, KontFromBehindNotSupportedYetWithG451OrOnApproach) {
  const std::string tool10 = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=10\n";
  const std::pair<std::string, int> cases[] = {
      // Retraction as above with G451: the intersection variant is not built.
      {"$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F100\nN30 X40\nN40 Y3\n"
       "N50 G40 KONT G451 X60 Y20\n",
       7},
      // Approach: from (80,20), behind N60's line x = 50 (G42: compensation on -X); N60 is too short.
      {tool10 + "N30 X0 Y0 F10000 T1 D1\nN40 X80 Y20\nN50 G42 KONT X50 Y5\nN60 Y0\nN70 X30\nN80 X20 Y-5\n"
                "N90 X0 Y0 G40\n",
       5},
  };
  for (const auto& [text, line_no] : cases) expect_not_supported(text, line_no);
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

using K = OriginKind;

// covers: TRC-EDGE-1 TRC-EDGE-4 TRC-EDGE-5 TRC-LOOK-2 TRC-LOOK-3
TEST(ApproachRetraction, TooShortFirstBlockFoundByTheLookAhead) {
  // r = 10, G42. N60 (first block) runs -Y from (50,5), equidistant x = 40 from (40,5); N70 runs
  // -X for 3 mm, equidistant y = 10 from (50,10) to (47,10): the corner's intersection (40,10) lies
  // beyond its end, too short; the look-ahead finds N80's equidistant y = 10 (x from 47 to 30) at
  // (40,10), which lies before N60's normal start: N60 would run backwards. G462 extends N60's
  // equidistant backwards from (40,5) along +Y: it meets N80's at (40,10). The approach goes
  // there; N60 and N70 are skipped; N80 runs to (30,10); NORM retraction to (20,30).
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=10\nN30 G0 X0 Y20 T1 D1\nN50 G1 G42 G462 X50 Y5 F100\nN60 Y0\nN70 X47\n"
      "N80 X30\nN90 G40 X20 Y30\n";
  Runs r = run_both(text);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kApproach, {0, 20, 0}, {40, 10, 0}),
                  line(K::kOffset, {40, 10, 0}, {30, 10, 0}), line(K::kRetraction, {30, 10, 0}, {20, 30, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-LOOK-1", "too-short"));
    EXPECT_TRUE(has_decision(*x, "TRC-LOOK-2", "intersection"));
    EXPECT_TRUE(has_decision(*x, "TRC-ELEMENT-1", "reverses"));
    EXPECT_TRUE(has_decision(*x, "TRC-EDGE-1", "G462"));
    int skipped = 0;
    for (const Decision& d : x->decisions) skipped += d.clause == "TRC-LOOK-3";
    EXPECT_EQ(skipped, 2);  // N60 and N70
  }
}

// covers: TRC-EDGE-2 TRC-EDGE-5 TRC-ARC-ELEMENT-1
TEST(ApproachRetraction, RetractionHitEarlyOnAnArcOfMoreThanHalfATurnEndsItThere) {
  // N30 turns 270 degrees ccw about (0,0); G42 puts its equidistant outside, radius 13, from
  // (13,0) to (0,-13). N40 turns right into -Y: x = -3 meets that circle below its end, so it is
  // too short. G460's line from its normal end (-3,-10.5) to (13,34.5) meets the circle at (5,12)
  // (5-12-13), 67.4 degrees along the piece: N30 ends there. Measured from its normal end
  // (-202.6 degrees, read as +157.4) the end lay a whole turn later: a whole turn, then the rest.
  Runs r = run_both(tool("3") +
                    "N10 G0 X20 Y0 T1 D1\nN20 G1 G42 X10 Y0 F100\nN30 G3 X0 Y-10 I-10 J0\nN40 G1 X0 Y-10.5\n"
                    "N50 G40 G460 X13 Y34.5\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {20, 0, 0}), line(K::kApproach, {20, 0, 0}, {13, 0, 0}),
                  Expect{K::kOffset, {13, 0, 0}, {5, 12, 0}, {0, 0, 0}, true, true},
                  line(K::kRetraction, {5, 12, 0}, {13, 34.5, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-EDGE-5", "hit"));
    EXPECT_TRUE(has_decision(*x, "TRC-ARC-ELEMENT-1", "fits"));
  }
}

// covers: TRC-EDGE-2 TRC-EDGE-5 TRC-ARC-ELEMENT-1
TEST(ApproachRetraction, ApproachHitLateOnAnArcOfMoreThanHalfATurnStartsItThere) {
  // The mirror: N30 (-Y to +Y at x = 0, equidistant x = -3) runs backwards into N40's circle, so
  // G460's line from (13,34.5) to N30's normal start (-3,-10.5) meets N40's equidistant (radius 13,
  // cw from (0,-13) to (13,0), 270 degrees) at (5,12), 202.6 degrees along it: the rest turns
  // 67.4 degrees. Measured from the normal start (-157.4) the start lay a whole turn earlier.
  Runs r = run_both(tool("3") +
                    "N10 G0 X13 Y34.5 T1 D1\nN20 G1 G41 G460 X0 Y-10.5 F100\nN30 G1 X0 Y-10\n"
                    "N40 G2 X10 Y0 I0 J10\nN50 G1 X10 Y-10\nN60 G40 X20 Y-10\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {13, 34.5, 0}), line(K::kApproach, {13, 34.5, 0}, {5, 12, 0}),
                  Expect{K::kOffset, {5, 12, 0}, {13, 0, 0}, {0, 0, 0}, true, false},
                  line(K::kOffset, {13, 0, 0}, {13, -10, 0}), line(K::kRetraction, {13, -10, 0}, {20, -10, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) EXPECT_TRUE(has_decision(*x, "TRC-EDGE-5", "hit"));
}

// covers: TRC-EDGE-3 TRC-EDGE-5 TRC-ARC-ELEMENT-1
TEST(ApproachRetraction, RetractionHitOnAFullCircleIsTheFirstPointAlongIt) {
  // N30 is a full circle, equidistant radius 7 about (0,0) from (7,0). N40 turns inwards and is
  // too short; G461's circle of radius 3 about (9.5,0.5) meets the equidistant at about 14.5 and
  // -8.5 degrees: the first along the circle, 14.5 degrees from its start, ends it (TRC-EDGE-5),
  // no whole turn before it.
  Runs r = run_both(tool("3") +
                    "N10 G0 X20 Y0 T1 D1\nN20 G1 G41 X10 Y0 F100\nN30 G3 X10 Y0 I-10 J0\nN40 G1 X9.5 Y0.5\n"
                    "N50 G1 G40 G461 X0 Y0\n");
  for (const RunResult* x : {&r.ref, &r.fast}) {
    ASSERT_EQ(x->path.size(), 4u);
    const PathElement& a = x->path[2];
    EXPECT_EQ(a.type, ElementType::kArc);
    EXPECT_NEAR(std::atan2(a.end.y, a.end.x),
                std::atan2(0.5, 9.5) + std::acos((49 + 90.5 - 9) / (2 * 7 * std::sqrt(90.5))), 1e-12);
  }
}

}  // namespace
}  // namespace cutcom::test
