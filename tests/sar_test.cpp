// Smooth approach and retraction (spec/sar.md): the manual's examples E1 (three variants), E2 and
// the manual's SAR example (PGA06 p.373) and one test per clause, with every coordinate derived by hand.
#include "support.hpp"

namespace cutcom::test {
namespace {

using K = OriginKind;

std::string tool(const std::string& radius) { return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" + radius + "\n"; }

Expect circle(K k, PathPoint s, PathPoint e, PathPoint c, bool ccw) { return {k, s, e, c, true, ccw}; }

bool alarm_is(const RunResult& r, int number, int line_no) {
  return r.alarms.size() == 1 && r.alarms[0].number == number && r.alarms[0].line == line_no;
}

void expect_alarm(const std::string& text, int number, int line_no, const MachineData& md = {}) {
  Runs r = run_both(text, md);
  EXPECT_FALSE(r.fast_ok);
  EXPECT_FALSE(r.ref_ok);
  EXPECT_TRUE(alarm_is(r.fast, number, line_no)) << "fast: " << (r.fast.alarms.empty() ? 0 : r.fast.alarms[0].number);
  EXPECT_TRUE(alarm_is(r.ref, number, line_no)) << "ref: " << (r.ref.alarms.empty() ? 0 : r.ref.alarms[0].number);
}

// Both engines agree on every decision (clause, line, branch), in order.
void expect_same_decisions(const Runs& r) {
  ASSERT_EQ(r.fast.decisions.size(), r.ref.decisions.size());
  for (std::size_t i = 0; i < r.ref.decisions.size(); ++i) {
    EXPECT_EQ(r.fast.decisions[i].clause, r.ref.decisions[i].clause) << i;
    EXPECT_EQ(r.fast.decisions[i].branch, r.ref.decisions[i].branch) << r.ref.decisions[i].clause;
  }
}

void expect_variables(const RunResult& r, PathPoint p3, PathPoint p4) {
  ASSERT_EQ(r.variables.size(), 1u);
  expect_point(r.variables[0].p_apr, p3, "$P_APR");
  expect_point(r.variables[0].p_aep, p4, "$P_AEP");
  EXPECT_EQ(r.variables[0].p_apdv, 1);
}

// E1 (PGA19 p.278): tool radius 7, G41, G147 with DISR=13 and DISCL=3 (G340). P0 = (10,0,30),
// P4 = (40,-10,0), t = +X from N50. The line is 13 + 7 = 20 long: P3 = (20,-10); the tool centre
// stands 7 left of it, at (20,-3), and at P4 at (40,-3). P2 = P3 at Z = 0 + 3. The lead (G0 from
// N20) goes to the tool centre over P3 at Z30 (selection, NORM), rapid infeed to Z3, then the
// spatial line to (40,-3,0) at F1000 (no FAD), N50 along y = -3, and the retraction.
std::vector<Expect> e1_path() {
  return {line(K::kProgrammed, {0, 0, 0}, {0, 0, 30}),    line(K::kProgrammed, {0, 0, 30}, {10, 0, 30}),
          line(K::kApproach, {10, 0, 30}, {20, -3, 30}),  line(K::kInfeed, {20, -3, 30}, {20, -3, 3}),
          line(K::kOffset, {20, -3, 3}, {40, -3, 0}),     line(K::kOffset, {40, -3, 0}, {50, -3, 0}),
          line(K::kRetraction, {50, -3, 0}, {60, -10, 0})};
}

// covers: SAR-P4-1 SAR-P4-2 SAR-TANGENT-1 SAR-POINTS-1 SAR-DISR-1 SAR-DISCL-1 SAR-SEG-1 SAR-TRC-1 SAR-FEED-1 SAR-VAR-1
TEST(Sar, ExampleE1ThreeWaysToProgramP4GiveTheSamePath) {
  const std::string head = tool("7") + "N10 G90 G0 X0 Y0 Z30 D1 T1\nN20 X10\n";
  const std::string tail = "N50 G1 X50\nN60 G40 X60\nM30\n";
  const std::string variants[] = {
      head + "N30 G41 G147 DISCL=3 DISR=13 Z=0 F1000\nN40 G1 X40 Y-10\n" + tail,
      head + "N30 G41 G147 DISCL=3 DISR=13 X40 Y-10 Z0 F1000\n" + tail,
      head + "N30 G41 G147 DISCL=3 DISR=13 F1000\nN40 G1 X40 Y-10 Z0\n" + tail,
  };
  for (const std::string& text : variants) {
    Runs r = run_both(text);
    ASSERT_TRUE(r.fast_ok && r.ref_ok) << text;
    expect_both(r, e1_path());
    expect_same_decisions(r);
    for (const RunResult* x : {&r.fast, &r.ref}) {
      EXPECT_TRUE(x->path[2].rapid && x->path[3].rapid);  // P0 -> P2 at the velocity of N20 (G0)
      EXPECT_FALSE(x->path[4].rapid);
      EXPECT_EQ(x->path[4].feed, Decimal::from_int(1000));
      EXPECT_EQ(x->path[2].origin.sar, SarMove::kLead);
      EXPECT_EQ(x->path[3].origin.sar, SarMove::kFastInfeed);
      EXPECT_EQ(x->path[4].origin.sar, SarMove::kElement);
      expect_variables(*x, {20, -10, 3}, {40, -10, 0});
      EXPECT_TRUE(has_decision(*x, "SAR-DISR-1", "valid"));
    }
    EXPECT_EQ(r.ref.decisions[1].margin_exact, "20");  // SAR-DISR-1: L = 13 + 7
  }
  // Where P4 came from.
  EXPECT_TRUE(has_decision(run_both(variants[0]).ref, "SAR-TANGENT-1", "p4-in-later-block"));
  EXPECT_TRUE(has_decision(run_both(variants[1]).ref, "SAR-TANGENT-1", "p4-in-sar-block"));
}

// covers: SAR-SEG-2 SAR-DISR-2 SAR-SIDE-1 SAR-DISCL-1 SAR-FEED-1 SAR-POINTS-1 SAR-VAR-1
TEST(Sar, ExampleE2QuadrantWithG341AndFad) {
  // E2 (PGA19 p.280), FAD written FAD=500 (the page prints "FAD 500", which the syntax rejects).
  // G140 with G41: from the left; R = 13 + 7 = 20, C = P4 + 20 n = (40,10), P3 = C - 20 t =
  // (20,10); the tool centre runs on radius 13 about C: (27,10) -> (40,-3), counter-clockwise.
  // P1 at Z20 and P2 at Z5 (DISCL=AC(5)) at G0; P3 at Z0 at FAD 500; the quadrant at F200. N30
  // and N40 are G0 blocks (the example programs no G1).
  Runs r = run_both(tool("7") +
                    "N10 G90 G0 X0 Y0 Z20 D1 T1\nN20 G41 G341 G247 DISCL=AC(5) DISR=13 FAD=500 X40 Y-10 Z=0 F200\n"
                    "N30 X50\nN40 X60\nM30\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 0, 20}), line(K::kApproach, {0, 0, 20}, {27, 10, 20}),
                  line(K::kInfeed, {27, 10, 20}, {27, 10, 5}), line(K::kInfeed, {27, 10, 5}, {27, 10, 0}),
                  circle(K::kOffset, {27, 10, 0}, {40, -3, 0}, {40, 10, 0}, true),
                  line(K::kOffset, {40, -3, 0}, {50, -3, 0}), line(K::kOffset, {50, -3, 0}, {60, -3, 0})});
  expect_same_decisions(r);
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_TRUE(x->path[1].rapid && x->path[2].rapid);
    EXPECT_EQ(x->path[3].feed, Decimal::from_int(500));
    EXPECT_EQ(x->path[3].origin.sar, SarMove::kSlowInfeed);
    EXPECT_EQ(x->path[4].feed, Decimal::from_int(200));
    EXPECT_TRUE(has_decision(*x, "SAR-SIDE-1", "G140-left"));
    expect_variables(*x, {20, 10, 0}, {40, -10, 0});
  }
  EXPECT_EQ(r.ref.decisions[2].margin_exact, "20");  // SAR-DISR-2: R = 13 + 7
}

// covers: SAR-P4-2 SAR-POINTS-2 SAR-DISR-2 SAR-END-1 SAR-FEED-2 SAR-TRC-1 SAR-SEG-1 SAR-SEG-2
TEST(Sar, ExampleE3ContourExampleTwoWithOffn) {
  // FM06 p.73: r = 10 + OFFN 5 = 15. Approach G247 G341, P4 = (30,-10,0) from N30, t = +X from
  // N40 (its projection): R = 10 + 15 = 25, C = (30,15), P3 = (5,15); the tool centre on radius
  // 10: (20,15) -> (30,5). P1 at Z20, P2 at Z7 (G0), P3 at Z0 at FAD 200, the quadrant at F1500.
  // Retraction N60 G248 G340 from P4 = (50,-10,2), end tangent +X: R = 5 + 15 = 20, C = (50,10),
  // P3 = (70,10); tool centre on radius 5: (50,5) -> (55,10), a helix up to Z = 2 + 6 = 8 at the
  // old feed 1500; then up to Z20 and across to P0 = (70,0,20), a tool-centre position (case 3,
  // G40 deselects in the lead) at F10000.
  Runs r = run_both(tool("10") +
                    "N10 G0 X0 Y0 Z20 G64 D1 T1 OFFN=5\nN20 G41 G247 G341 Z0 DISCL=AC(7) DISR=10 F1500 FAD=200\n"
                    "N30 G1 X30 Y-10\nN40 X40 Z2\nN50 X50\nN60 G248 G340 X70 Y0 Z20 DISCL=6 DISR=5 G40 F10000\n"
                    "N70 X80 Y0\nN80 M30\n");
  expect_both(r,
              {line(K::kProgrammed, {0, 0, 0}, {0, 0, 20}), line(K::kApproach, {0, 0, 20}, {20, 15, 20}),
               line(K::kInfeed, {20, 15, 20}, {20, 15, 7}), line(K::kInfeed, {20, 15, 7}, {20, 15, 0}),
               circle(K::kOffset, {20, 15, 0}, {30, 5, 0}, {30, 15, 0}, true), line(K::kOffset, {30, 5, 0}, {40, 5, 2}),
               line(K::kOffset, {40, 5, 2}, {50, 5, 2}), circle(K::kOffset, {50, 5, 2}, {55, 10, 8}, {50, 10, 2}, true),
               line(K::kInfeed, {55, 10, 8}, {55, 10, 20}), line(K::kRetraction, {55, 10, 20}, {70, 0, 20}),
               line(K::kProgrammed, {70, 0, 20}, {80, 0, 20})});
  expect_same_decisions(r);
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_EQ(x->path[4].feed, Decimal::from_int(1500));  // the element in N30 at F
    EXPECT_EQ(x->path[4].origin.line, 5);
    EXPECT_EQ(x->path[7].feed, Decimal::from_int(1500));  // retraction element: the old feed
    EXPECT_EQ(x->path[8].feed, Decimal::from_int(10000));
    EXPECT_EQ(x->path[9].feed, Decimal::from_int(10000));
    EXPECT_TRUE(has_decision(*x, "SAR-END-1", "programmed-p0"));
    expect_variables(*x, {5, 15, 0}, {30, -10, 0});
  }
}

// covers: SAR-BLOCK-1 SAR-SIDE-2 SAR-SUB-1
TEST(Sar, G143WithoutCompensationTakesTheSideOfTheStartPoint) {
  // No TRC. P0 = (0,20) lies left of t = +X at P4 = (10,0) (distance 20): the quadrant of radius 5
  // comes from the left, C = (10,5), P3 = (5,5), counter-clockwise. No DISCL: no infeed.
  // G143 is modal (group 43): set in N15, used by N20.
  Runs r = run_both("N10 G0 X0 Y20 Z0\nN15 G143\nN20 G247 DISR=5 X10 Y0 F100\nN30 G1 X30\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kProgrammed, {0, 20, 0}, {5, 5, 0}),
                  circle(K::kProgrammed, {5, 5, 0}, {10, 0, 0}, {10, 5, 0}, true),
                  line(K::kProgrammed, {10, 0, 0}, {30, 0, 0})});
  expect_same_decisions(r);
  EXPECT_TRUE(has_decision(r.ref, "SAR-SIDE-2", "left"));
  EXPECT_TRUE(has_decision(r.ref, "SAR-SUB-1", "lead"));
  EXPECT_EQ(r.ref.decisions[1].margin_exact, "20");
  // Right of the tangent: clockwise about (10,-5), P3 = (5,-5).
  Runs right = run_both("N10 G0 X0 Y-20 Z0\nN20 G247 G143 DISR=5 X10 Y0 F100\nN30 G1 X30\n");
  EXPECT_TRUE(has_decision(right.ref, "SAR-SIDE-2", "right"));
  expect_point(right.ref.path[2].center, {10, -5, 0}, "centre");
  EXPECT_FALSE(right.fast.path[2].ccw);
  // On the tangent line: alarm 10744 (decision 4).
  expect_alarm("N10 G0 X-5 Y0 Z0\nN20 G247 G143 DISR=5 X10 Y0 F100\nN30 G1 X30\n", 10744, 2);
  // G140 without compensation behaves as G143.
  EXPECT_TRUE(
      has_decision(run_both("N10 G0 X0 Y20 Z0\nN20 G247 DISR=5 X10 Y0\nN30 G1 X30\n").fast, "SAR-SIDE-2", "left"));
}

// covers: SAR-SIDE-1 SAR-DISR-2
TEST(Sar, DisrIsTheToolCentreRadiusOnEitherSide) {
  // r = 2, G41. G141 (the compensation side): R = 5 + 2, tool inside, tool-centre radius 5.
  // G142: R = 5 - 2 = 3, tool outside, tool-centre radius again 5, clockwise about (10,-3).
  std::string head = tool("2") + "N10 G0 X0 Y20 Z0 T1 D1\n";
  Runs left = run_both(head + "N20 G41 G247 G141 DISR=5 X10 Y0 F100\nN30 G1 X30\nN40 G40 X40\n");
  expect_point(left.ref.path[2].center, {10, 7, 0}, "G141 centre");
  expect_point(left.ref.path[2].start, {5, 7, 0}, "G141 tool centre at P3");
  expect_point(left.fast.path[2].end, {10, 2, 0}, "tool centre at P4");
  Runs right = run_both(head + "N20 G41 G247 G142 DISR=5 X10 Y0 F100\nN30 G1 X30\nN40 G40 X40\n");
  EXPECT_TRUE(has_decision(right.ref, "SAR-SIDE-1", "G142-right"));
  EXPECT_EQ(right.ref.decisions[2].margin_exact, "3");
  expect_point(right.ref.path[2].center, {10, -3, 0}, "G142 centre");
  expect_point(right.ref.path[2].start, {5, -3, 0}, "G142 tool centre at P3");
  EXPECT_FALSE(right.fast.path[2].ccw);
  // A negative radius swaps G41 to the right (decision 2): G140 comes from the right.
  Runs neg = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=-2\nN10 G0 X0 Y20 Z0 T1 D1\n"
      "N20 G41 G247 DISR=5 X10 Y0 F100\nN30 G1 X30\nN40 G40 X40\n");
  EXPECT_TRUE(has_decision(neg.ref, "SAR-SIDE-1", "G140-right"));
  EXPECT_TRUE(has_decision(neg.fast, "SAR-SIDE-1", "G140-right"));
  // 10742: radius not positive inside (DISR = r with the tool outside), DISR missing, DISR <= 0.
  expect_alarm(head + "N20 G41 G247 G142 DISR=2 X10 Y0\nN30 G1 X30\n", 10742, 4);
  expect_alarm(head + "N20 G41 G247 X10 Y0\nN30 G1 X30\n", 10742, 4);
  expect_alarm(head + "N20 G41 G347 DISR=0 X10 Y0\nN30 G1 X30\n", 10742, 4);
}

// covers: SAR-DISR-1
TEST(Sar, StraightLineLengthIsDisrPlusRadius) {
  // r = 7, DISR = -2: L = 5 (allowed while |DISR| < r). P3 = (15,0), tool centre (15,7).
  std::string head = tool("7") + "N10 G0 X0 Y20 Z0 T1 D1\n";
  Runs r = run_both(head + "N20 G41 G147 DISR=-2 X20 Y0 F100\nN30 G1 X40\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 0}), line(K::kApproach, {0, 20, 0}, {15, 7, 0}),
                  line(K::kOffset, {15, 7, 0}, {20, 7, 0}), line(K::kOffset, {20, 7, 0}, {40, 7, 0})});
  EXPECT_EQ(r.ref.decisions[1].margin_exact, "5");
  expect_alarm(head + "N20 G41 G147 DISR=-7 X20 Y0\nN30 G1 X40\n", 10742, 4);  // L = 0
  expect_alarm(head + "N20 G41 G147 X20 Y0\nN30 G1 X40\n", 10742, 4);          // no DISR
  // Without compensation L = DISR (decision 5).
  expect_alarm("N10 G0 X0 Y20\nN20 G147 DISR=0 X20 Y0\nN30 G1 X40\n", 10742, 2);
  Runs plain = run_both("N10 G0 X0 Y20\nN20 G147 DISR=4 X20 Y0\nN30 G1 X40\n");
  expect_point(plain.fast.path[1].end, {16, 0, 0}, "P3 without compensation");
  expect_point(plain.ref.path[1].end, {16, 0, 0}, "P3 without compensation");
}

// covers: SAR-DISCL-3
TEST(Sar, DirectionReversalIsClampedWithinMd20204ElseAlarm10741) {
  // P0 at Z3 (h1 = 3), P4 at Z0. DISCL = 3.005 lies 0.005 above P1: within MD20204 = 0.01, P2 is
  // clamped to Z3 (no fast infeed), and G340 runs the line from (15,0,3) to (20,0,0).
  std::string head = "N10 G0 X0 Y20 Z3\n";
  std::string tail = " X20 Y0 Z0 F100\nN30 G1 X40\n";
  Runs r = run_both(head + "N20 G147 DISR=5 DISCL=3.005" + tail);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 3}), line(K::kProgrammed, {0, 20, 3}, {15, 0, 3}),
                  line(K::kProgrammed, {15, 0, 3}, {20, 0, 0}), line(K::kProgrammed, {20, 0, 0}, {40, 0, 0})});
  EXPECT_TRUE(has_decision(r.ref, "SAR-DISCL-3", "clamped"));
  EXPECT_EQ(r.ref.decisions[2].margin_exact, "0.005");
  // Exactly MD20204 outside is clamped (margin 0); a nanometre more is the alarm.
  Runs on = run_both(head + "N20 G147 DISR=5 DISCL=3.01" + tail);
  EXPECT_TRUE(has_decision(on.ref, "SAR-DISCL-3", "clamped"));
  EXPECT_EQ(on.ref.decisions[2].margin_exact, "0");
  expect_alarm(head + "N20 G147 DISR=5 DISCL=3.010000001" + tail, 10741, 2);
  // Below P4's plane: clamped up to Z0; the fast infeed runs down to it, the line in the plane.
  Runs below = run_both(head + "N20 G147 DISR=5 DISCL=-0.005" + tail);
  expect_path(below.ref,
              {line(K::kProgrammed, {0, 0, 0}, {0, 20, 3}), line(K::kProgrammed, {0, 20, 3}, {15, 0, 3}),
               line(K::kProgrammed, {15, 0, 3}, {15, 0, 0}), line(K::kProgrammed, {15, 0, 0}, {20, 0, 0}),
               line(K::kProgrammed, {20, 0, 0}, {40, 0, 0})},
              "ref");
  // A larger tolerance accepts more.
  MachineData md;
  md.wab_clearance_tolerance = Decimal::from_int(1);
  EXPECT_TRUE(run_both(head + "N20 G147 DISR=5 DISCL=3.5" + tail, md).ref_ok);
}

// covers: SAR-DISCL-2 SAR-SEG-1 SAR-SEG-2 SAR-SUB-1
TEST(Sar, WithoutDisclOrWithDisclZero) {
  // G341 without DISCL: P2 = P1, no fast infeed; the slow infeed P1 -> P3 at the SAR block's F.
  Runs g341 = run_both("N10 G0 X0 Y20 Z10\nN20 G147 G341 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  expect_both(g341, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 10}), line(K::kProgrammed, {0, 20, 10}, {15, 0, 10}),
                     line(K::kProgrammed, {15, 0, 10}, {15, 0, 0}), line(K::kProgrammed, {15, 0, 0}, {20, 0, 0}),
                     line(K::kProgrammed, {20, 0, 0}, {40, 0, 0})});
  EXPECT_EQ(g341.fast.path[2].origin.sar, SarMove::kSlowInfeed);
  EXPECT_FALSE(g341.fast.path[2].rapid);
  // G340 with DISCL=0: P1, P2, P3 merge, one spatial element from P1 (decision 12).
  Runs g340 = run_both("N10 G0 X0 Y20 Z10\nN20 G147 DISCL=0 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  expect_both(g340, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 10}), line(K::kProgrammed, {0, 20, 10}, {15, 0, 10}),
                     line(K::kProgrammed, {15, 0, 10}, {20, 0, 0}), line(K::kProgrammed, {20, 0, 0}, {40, 0, 0})});
  // G341 with DISCL=0: P2 = P3 at Z0, the fast infeed goes all the way (rapid, from G0).
  Runs g341z = run_both("N10 G0 X0 Y20 Z10\nN20 G147 G341 DISCL=0 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  EXPECT_EQ(g341z.ref.path[2].origin.sar, SarMove::kFastInfeed);
  EXPECT_TRUE(g341z.ref.path[2].rapid);
  EXPECT_EQ(g341z.ref.path.size(), 5u);
  // P0 exactly over P3 (and no DISRP): no lead at all.
  Runs nolead = run_both("N10 G0 X15 Y0 Z10\nN20 G147 DISCL=2 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  EXPECT_TRUE(has_decision(nolead.ref, "SAR-SUB-1", "no-lead"));
  EXPECT_TRUE(has_decision(nolead.fast, "SAR-SUB-1", "no-lead"));
  EXPECT_EQ(nolead.ref.path[1].origin.sar, SarMove::kFastInfeed);
}

// covers: SAR-DISRP-1 SAR-DISRP-2
TEST(Sar, DisrpSetsTheRetractionPlane) {
  // DISRP=5: P1 at Z5; the lead from (0,20,20) is a spatial line to (15,0,5); fast infeed to Z2.
  Runs r = run_both("N10 G0 X0 Y20 Z20\nN20 G147 DISRP=5 DISCL=2 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {0, 20, 20}), line(K::kProgrammed, {0, 20, 20}, {15, 0, 5}),
                  line(K::kProgrammed, {15, 0, 5}, {15, 0, 2}), line(K::kProgrammed, {15, 0, 2}, {20, 0, 0}),
                  line(K::kProgrammed, {20, 0, 0}, {40, 0, 0})});
  EXPECT_TRUE(has_decision(r.ref, "SAR-DISRP-2", "same-side"));
  // P1 below P4's plane with P2 above it: alarm 10748.
  expect_alarm("N10 G0 X0 Y20 Z20\nN20 G147 DISRP=-5 DISCL=2 DISR=5 X20 Y0 Z0\nN30 G1 X40\n", 10748, 2);
}

// covers: SAR-FEED-1 SAR-ACTION-1
TEST(Sar, FadAndActionsOnApproach) {
  // G341, FAD=PR(0.1): the slow infeed at 0.1 per revolution; M8 runs before the first sub-block.
  Runs r = run_both("N10 G0 X0 Y20 Z10\nN20 G147 G341 DISCL=2 FAD=PR(0.1) DISR=5 X20 Y0 Z0 F100 M8\nN30 G1 X40\n");
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->path.size(), 6u);
    EXPECT_EQ(x->path[3].origin.sar, SarMove::kSlowInfeed);
    EXPECT_EQ(x->path[3].feed, Decimal::parse("0.1").value);
    EXPECT_EQ(x->path[3].feed_type, FeedType::kG95);
    EXPECT_EQ(x->path[4].feed, Decimal::from_int(100));
    EXPECT_EQ(x->path[4].feed_type, FeedType::kG94);
    ASSERT_EQ(x->actions.size(), 1u);
    expect_point(x->actions[0].at, {0, 20, 10}, "M8");
  }
  // G340 with FAD: the element at FAD; F applies after it.
  Runs g340 = run_both("N10 G0 X0 Y20 Z10\nN20 G147 DISCL=2 FAD=50 DISR=5 X20 Y0 Z0 F100\nN30 G1 X40\n");
  EXPECT_EQ(g340.ref.path[3].feed, Decimal::from_int(50));
  EXPECT_EQ(g340.fast.path[4].feed, Decimal::from_int(100));
}

// covers: SAR-END-1 SAR-END-2 SAR-END-3 SAR-FEED-2 SAR-ACTION-1
TEST(Sar, RetractionWithoutEndPoint) {
  // r = 2, G41 along +X to P4 = (30,0,0). G248 DISR=5 DISCL=3 (G340): R = 7, C = (30,7),
  // P3 = (37,7); the tool centre on radius 5 from (30,2) to (35,7), a helix up to Z3.
  std::string head = tool("2") + "N10 G0 X0 Y0 Z5 T1 D1\nN20 G1 G41 X10 Y0 Z0 F100\nN30 X30\n";
  std::vector<Expect> common = {line(K::kProgrammed, {0, 0, 0}, {0, 0, 5}), line(K::kApproach, {0, 0, 5}, {10, 2, 0}),
                                line(K::kOffset, {10, 2, 0}, {30, 2, 0}),
                                circle(K::kOffset, {30, 2, 0}, {35, 7, 3}, {30, 7, 0}, true)};
  // Case 1 without G40: ends at P2, compensation stays active to the end of the program.
  Runs case1 = run_both(head + "N40 G248 DISR=5 DISCL=3\n");
  expect_both(case1, common);
  EXPECT_TRUE(has_decision(case1.ref, "SAR-END-1", "ends-at-p2"));
  // Case 1 with G40: P1 -> P0, P0 the tool centre at P1: the deselection does not move. The next
  // blocks start there; N60 programs both plane axes.
  Runs desel = run_both(head + "N40 G248 DISR=5 DISCL=3 G40 M9\nN50 G0 Z50\nN60 X0 Y0\n");
  std::vector<Expect> want = common;
  want.push_back(line(K::kProgrammed, {35, 7, 3}, {35, 7, 50}));
  want.push_back(line(K::kProgrammed, {35, 7, 50}, {0, 0, 50}));
  expect_both(desel, want);
  for (const RunResult* x : {&desel.fast, &desel.ref}) {
    ASSERT_EQ(x->actions.size(), 1u);  // M9 in the last sub-block (the end path)
    expect_point(x->actions[0].at, {35, 7, 3}, "M9");
    EXPECT_EQ(x->path[3].feed, Decimal::from_int(100));  // the element at the old feed
  }
  // Case 2 (only Z): ends at P1 at Z10; the fast infeed P2 -> P1 runs at the tool centre.
  Runs case2 = run_both(head + "N40 G248 DISR=5 DISCL=3 Z10 G40\nN50 G0 Z50\n");
  want = common;
  want.push_back(line(K::kInfeed, {35, 7, 3}, {35, 7, 10}));
  want.push_back(line(K::kProgrammed, {35, 7, 10}, {35, 7, 50}));
  expect_both(case2, want);
  EXPECT_TRUE(has_decision(case2.fast, "SAR-END-1", "ends-at-p1"));
  // SAR-END-3: one plane axis after it would need the irrational position as programmed data.
  expect_not_supported(head + "N40 G248 DISR=5 DISCL=3 G40\nN50 G0 X5\n", 7);
}

// covers: SAR-SIDE-3
TEST(Sar, G143OnRetractionNeedsTheEndPoint) {
  std::string head = tool("2") + "N10 G0 X0 Y0 Z5 T1 D1\nN20 G1 G41 X10 Y0 Z0 F100\nN30 X30\n";
  expect_alarm(head + "N40 G248 G143 DISR=5 DISCL=3\n", 10747, 6);
  expect_alarm(head + "N40 G248 G143 DISR=5 Z5\n", 10747, 6);
  // With the end point programmed (case 3), G143 takes its side: (40,-20) is right of +X.
  Runs r = run_both(head + "N40 G248 G143 DISR=5 X40 Y-20 G40\n");
  EXPECT_TRUE(has_decision(r.ref, "SAR-SIDE-2", "right"));
  EXPECT_TRUE(has_decision(r.fast, "SAR-SIDE-2", "right"));
  // G140 without compensation falls back to G143: the same alarm without end point.
  expect_alarm("N10 G0 X0 Y0\nN20 G1 X10 F100\nN30 G248 DISR=5\n", 10747, 3);
}

// covers: SAR-P4-1 SAR-TANGENT-1 SAR-STOP-1 SAR-AGAIN-1
TEST(Sar, SequenceAlarms) {
  std::string head = "N10 G0 X0 Y20 Z0\nN20 G147 DISR=5 X20 Y0 F100\n";
  // MD20202 = 5 blocks without motion between the SAR block and the direction block; the sixth
  // raises 10740.
  expect_alarm(head + "M8\nM9\nM8\nM9\nM8\nM9\nN30 G1 X40\n", 10740, 8);
  MachineData md;
  md.wab_maxnum_dummy_blocks = 6;
  EXPECT_TRUE(run_both(head + "M8\nM9\nM8\nM9\nM8\nM9\nN30 G1 X40\n", md).ref_ok);
  expect_alarm(head + "N25 STOPRE\nN30 G1 X40\n", 10746, 3);
  expect_alarm(head + "N25 G147 DISR=5 X30 Y0\nN30 G1 X40\n", 10743, 3);
  // No direction block before the end of the program; a retraction without contour.
  expect_alarm(head + "M30\n", 10744, 2);
  expect_alarm("N10 G0 Z5\nN20 G148 DISR=5 X30 Y0\n", 10744, 2);
  // Axis motion between the SAR block and the block that gives P4: not supported.
  expect_not_supported("N10 G0 X0 Y20 Z5\nN20 G147 DISR=5 F100\nN25 Z3\nN30 G1 X20 Y0\nN40 X40\n", 3);
}

// covers: SAR-TANGENT-1 SAR-POINTS-1
TEST(Sar, TangentOfACircleAndASemicircle) {
  // P4 = (10,0) in the SAR block; the direction block is G3 about the origin: start tangent +Y.
  // G347 from the right (G142), R = 4: C = P4 - 4 n = (14,0), P3 = P4 - 8 n = (18,0), n = (-1,0);
  // clockwise from (18,0) about (14,0) to (10,0), arriving with direction +Y.
  Runs r = run_both("N10 G0 X30 Y-10 Z0\nN20 G347 G142 DISR=4 X10 Y0 F100\nN30 G3 X0 Y10 I-10 J0\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {30, -10, 0}), line(K::kProgrammed, {30, -10, 0}, {18, 0, 0}),
                  circle(K::kProgrammed, {18, 0, 0}, {10, 0, 0}, {14, 0, 0}, false),
                  circle(K::kProgrammed, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, true)});
  expect_same_decisions(r);
}

// covers: SAR-POINTS-2 SAR-SEG-2 SAR-FEED-2
TEST(Sar, SemicircleRetractionInG18) {
  // G18: the plane is Z/X (abscissa Z, ordinate X), applicate Y. Contour along +Z at X = 0 to
  // P4 = (X0, Y0, Z10). G348 G141 DISR=3, no TRC: C = P4 + 3 n, n = left of +Z in (Z,X) = +X:
  // C = (X3, Z10), P3 = (X6, Z10): counter-clockwise seen from +Y. G341 DISCL=2: the semicircle in
  // the plane and the slow infeed P3 -> P2 up to Y2 at the old feed (no FAD), then the lead across
  // to P0 = (X20 Z30) at Y2 (case 3 without the applicate: P0 at P2's level) at the new F50.
  // The next block starts where the retraction ended, at Y2.
  Runs r = run_both("N10 G18 G1 X0 Y0 Z0 F200\nN20 Z10\nN30 G348 G141 G341 DISR=3 DISCL=2 X20 Z30 F50\nN40 X30\n");
  expect_both(
      r, {line(K::kProgrammed, {0, 0, 0}, {0, 0, 10}), circle(K::kProgrammed, {0, 0, 10}, {6, 0, 10}, {3, 0, 10}, true),
          line(K::kProgrammed, {6, 0, 10}, {6, 2, 10}), line(K::kProgrammed, {6, 2, 10}, {20, 2, 30}),
          line(K::kProgrammed, {20, 2, 30}, {30, 2, 30})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_EQ(x->path[1].feed, Decimal::from_int(200));
    EXPECT_EQ(x->path[2].feed, Decimal::from_int(200));
    EXPECT_EQ(x->path[3].feed, Decimal::from_int(50));
  }
}

// covers: SAR-P4-2 SAR-SUB-1 SAR-ACTION-1
TEST(Sar, SarBlockWithoutMotionStillRunsItsActions) {
  // P4 = (10,0) from N30, t = +X from N40, L = 10 (no TRC): P3 = (0,0) = P0 and no DISCL, so the
  // SAR block N20 has no motion at all; its last sub-block still runs, with M8, at (0,0,0). The
  // line P3 -> P4 runs in N30.
  Runs r = run_both("N10 G0 X0 Y0 Z0\nN20 G147 DISR=10 F100 M8\nN30 G1 X10 Y0\nN40 X20\n");
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {10, 0, 0}), line(K::kProgrammed, {10, 0, 0}, {20, 0, 0})});
  for (const RunResult* x : {&r.fast, &r.ref}) {
    EXPECT_TRUE(has_decision(*x, "SAR-SUB-1", "no-lead"));
    ASSERT_EQ(x->actions.size(), 1u);
    EXPECT_EQ(x->actions[0].line, 2);
    expect_point(x->actions[0].at, {0, 0, 0}, "M8");
    EXPECT_EQ(x->path[0].origin.line, 3);
    EXPECT_EQ(x->path[0].origin.sar, SarMove::kElement);
  }
}

}  // namespace
}  // namespace cutcom::test
