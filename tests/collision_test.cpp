// Collision (bottleneck) detection CDON (spec/approach-retraction.md, TRC-CD-*), derived by hand.
#include "support.hpp"

namespace cutcom::test {
namespace {

using K = OriginKind;

// A straight wall y = 0 (part below, G41 along +x) with a recess 1 mm wide and 5 mm deep at
// x = 10 ... 11; r = 2. `extra` goes into N50 (the recess's floor), `between` after it.
std::string notch(const std::string& mode, const std::string& extra = "", const std::string& between = "") {
  return "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-5 Y5 Z0 T1 D1\nN20 G41 " + mode +
         " G1 X0 Y0 F500\nN30 X10\nN40 Y-5\nN50 X11 " + extra + "\n" + between +
         "N60 Y0\nN70 X20\nN80 G40 X25 Y5\nN90 M30\n";
}

bool alarm_is(const RunResult& r, int number, int line_no) {
  return r.alarms.size() == 1 && r.alarms[0].number == number && r.alarms[0].line == line_no;
}

// The TRC-CD-3 decisions of a run, with their margins (fast's double; ref's exact text).
std::vector<Decision> crossings(const RunResult& r) {
  std::vector<Decision> out;
  for (const auto& d : r.decisions)
    if (d.clause == "TRC-CD-3") out.push_back(d);
  return out;
}

// A recess exactly 2r wide (x = 10 ... 14, r = 2): its mouth circles about (10,0) and (14,0) meet
// exactly at their ends, (12,0). A point on both pieces, ends included, is a crossing (the
// boundary rule): both engines cut there at margin 0 and skip the recess.
// covers: TRC-CD-3 TRC-CD-4 PROP-BOUNDARY-1
TEST(Collision, ARecessExactly2rWideIsCutWhereItsMouthCirclesEnd) {
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-5 Y8 T1 D1\nN20 G1 G41 CDON X0 Y0 F500\nN30 X10\n"
      "N40 Y-5\nN50 X14\nN60 Y0\nN70 X25\nN80 G40 X30 Y8\nN90 M30\n";
  Runs r = run_both(text);
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-5, 8, 0}), line(K::kApproach, {-5, 8, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), arc({10, 2, 0}, {12, 0, 0}, {10, 0, 0}, false),
                  arc({12, 0, 0}, {14, 2, 0}, {14, 0, 0}, false), line(K::kOffset, {14, 2, 0}, {25, 2, 0}),
                  line(K::kRetraction, {25, 2, 0}, {30, 8, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    std::vector<Decision> c = crossings(*x);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0].branch, "none");  // N60's entry: the floor's corner, off the held pieces
    for (int k : {1, 2}) {
      EXPECT_EQ(c[k].branch, "cut");
      EXPECT_EQ(c[k].margin, 0.0);
      if (x == &r.ref) {
        EXPECT_EQ(c[k].margin_exact, "0");
      }
    }
  }
}

// Collinear pieces do not cross. A loop back onto the first wall (N70 runs along N30's
// equidistant, y = 2, over x = 7 ... 10) overlaps it: traced `overlap`, margin 0, the knife edge
// of crossing; the path is not cut there. Collinear pieces apart along their line miss by the gap.
// covers: TRC-CD-3 PROP-BOUNDARY-1
TEST(Collision, CollinearPiecesThatOverlapAreTheKnifeEdgeNotACrossing) {
  std::string loop =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-5 Y5 Z0 T1 D1\nN20 G41 CDON G1 X0 Y0 F500\nN30 X10\n"
      "N40 Y5\nN50 X5\nN60 Y0\nN70 X20\nN80 G40 X25 Y5\nN90 M30\n";
  MachineData md;
  md.cutcom_maxnum_check_blocks = 5;
  Runs r = run_both(loop, md);
  for (const RunResult* x : {&r.ref, &r.fast}) {
    std::vector<Decision> c = crossings(*x);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[2].branch, "overlap");
    EXPECT_EQ(c[2].margin, 0.0);
    EXPECT_TRUE(x->alarms.empty());
  }
  // The notch's walls, y = 2 before x = 8 and after x = 13 (the mouth circles cross above them),
  // are collinear but 5 mm apart: no knife edge.
  Runs n = run_both(notch("CDON"));
  for (const RunResult* x : {&n.ref, &n.fast})
    for (const Decision& d : crossings(*x)) EXPECT_NE(d.branch, "overlap");
}

// covers: TRC-CD-1 TRC-CD-2 TRC-CD-3 TRC-CD-4 TRC-LOOK-3
TEST(Collision, CdonCutsTheNotchBetweenItsMouthCircles) {
  // The transition circles about (10,0) (corner N30/N40, from (10,2) clockwise) and about (11,0)
  // (N70's entry, from (9,0) clockwise to (11,2)) cross at (10.5, sqrt(4 - 0.25)) = (10.5, sqrt15/2).
  // N70 arrives while the look-ahead over N50 (too short at the inner corner N40/N50) has passed
  // N60; N40's circle is held back (window 3: N40, N50, N60): the earliest block crossed.
  const double y = std::sqrt(15.0) / 2;
  Runs r = run_both(notch("CDON"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-5, 5, 0}), line(K::kApproach, {-5, 5, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), arc({10, 2, 0}, {10.5, y, 0}, {10, 0, 0}, false),
                  arc({10.5, y, 0}, {11, 2, 0}, {11, 0, 0}, false), line(K::kOffset, {11, 2, 0}, {20, 2, 0}),
                  line(K::kRetraction, {20, 2, 0}, {25, 5, 0})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    EXPECT_TRUE(x->alarms.empty());
    EXPECT_TRUE(has_decision(*x, "TRC-CD-3", "cut"));
    EXPECT_TRUE(has_decision(*x, "TRC-LOOK-3", "skipped"));
    EXPECT_EQ(x->path[4].origin.line, 8);  // named as N70's own circle at the corner N60/N70
    EXPECT_EQ(x->path[4].origin.next_line, 9);
  }
  // N60's entry (inner corner N50/N60 from (9,-3), up x = 9) misses what is held: traced `none`
  // before the cut at N70.
  EXPECT_TRUE(has_decision(r.ref, "TRC-CD-3", "none"));
}

// covers: TRC-CD-1 TRC-ELEMENT-1
TEST(Collision, CdofRaisesTheAlarmAtTheNotch) {
  // Without collision detection the look-ahead meets N40's equidistant x = 12 at (12,2) with N70's
  // y = 2, above N40's start (12,0): N40's equidistant would run backwards, alarm 10751 at N70.
  for (const char* mode : {"CDOF", "CDOF2"}) {
    Runs r = run_both(notch(mode));
    EXPECT_TRUE(alarm_is(r.ref, 10751, 9)) << mode;
    EXPECT_TRUE(alarm_is(r.fast, 10751, 9)) << mode;
    EXPECT_FALSE(has_decision(r.ref, "TRC-CD-3", "cut"));
  }
}

// covers: TRC-CD-1
TEST(Collision, TheWindowMustReachTheCrossedBlock) {
  // MD20240 = 2: N70 compares N50 only (N40's circle is out of the window) and the look-ahead
  // over N50 gives up after two examined blocks: alarm 10751 at N60.
  MachineData md;
  md.set("MD20240", "2");
  Runs r = run_both(notch("CDON"), md);
  EXPECT_TRUE(alarm_is(r.ref, 10751, 8));
  EXPECT_TRUE(alarm_is(r.fast, 10751, 8));
}

// covers: TRC-CD-4 TRC-LOOK-3
TEST(Collision, SkippedBlocksRunTheirActionsAndInfeedAtTheCrossing) {
  // M8 in N50 and a Z infeed N55 between the recess's blocks: they run at the crossing, in order;
  // N70's circle then starts at the new depth.
  const double y = std::sqrt(15.0) / 2;
  Runs r = run_both(notch("CDON", "M8", "N55 Z-1\n"));
  expect_both(r, {line(K::kProgrammed, {0, 0, 0}, {-5, 5, 0}), line(K::kApproach, {-5, 5, 0}, {0, 2, 0}),
                  line(K::kOffset, {0, 2, 0}, {10, 2, 0}), arc({10, 2, 0}, {10.5, y, 0}, {10, 0, 0}, false),
                  line(K::kInfeed, {10.5, y, 0}, {10.5, y, -1}), arc({10.5, y, -1}, {11, 2, -1}, {11, 0, -1}, false),
                  line(K::kOffset, {11, 2, -1}, {20, 2, -1}), line(K::kRetraction, {20, 2, -1}, {25, 5, -1})});
  for (const RunResult* x : {&r.ref, &r.fast}) {
    ASSERT_EQ(x->actions.size(), 2u);  // M8, then M30 at the end
    EXPECT_EQ(x->actions[0].line, 7);
    expect_point(x->actions[0].at, {10.5, y, 0}, "M8 at the crossing");
  }
}

// covers: TRC-CD-2 TRC-CD-3
TEST(Collision, AWideRecessIsNotCut) {
  // 5 mm wide (> 2r): the mouth circles about (10,0) and (15,0) do not meet; the path is CDOF's.
  std::string wide =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-5 Y5 Z0 T1 D1\nN20 G41 CDON G1 X0 Y0 F500\n"
      "N30 X10\nN40 Y-5\nN50 X15\nN60 Y0\nN70 X20\nN80 G40 X25 Y5\nN90 M30\n";
  Runs on = run_both(wide);
  std::string off = wide;
  off.replace(off.find("CDON"), 4, "CDOF");
  Runs of = run_both(off);
  ASSERT_EQ(on.ref.path.size(), of.ref.path.size());
  for (std::size_t i = 0; i < on.ref.path.size(); ++i) expect_point(on.ref.path[i].end, of.ref.path[i].end, "same");
  for (const RunResult* x : {&on.ref, &on.fast}) {
    EXPECT_TRUE(has_decision(*x, "TRC-CD-3", "none"));
    EXPECT_FALSE(has_decision(*x, "TRC-CD-3", "cut"));
  }
}

// covers: TRC-CD-3 TRC-CD-4 TRC-EDGE-3 TRC-EDGE-4 TRC-CD-1
TEST(Collision, BundledExampleG461ThenACdonCutThenG462) {
  // examples/bottleneck.mpf: G461 about (0,0) meets N50's equidistant x = -1 at (-1, sqrt3); the
  // recess's mouth circles about (1,10) and (1,11) cross at (1 - sqrt15/2, 10.5); G462 extends
  // N100's equidistant y = 23 to N90's x = -1.
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-10 Y-5 Z2 T1 D1\nN20 G1 Z-3 F200\n"
      "N30 G41 G461 CDOF X0 Y0 F600\nN40 X1\nN50 Y10 CDON\nN60 X6\nN70 Y11\nN80 X1\nN90 Y25\n"
      "N100 X0 CDOF\nN110 G40 G462 X-10 Y30\nN120 G0 Z2\nN130 M30\n";
  const double s3 = std::sqrt(3.0), x = 1 - std::sqrt(15.0) / 2;
  Runs r = run_both(text);
  expect_both(
      r, {line(K::kProgrammed, {0, 0, 0}, {-10, -5, 2}), line(K::kProgrammed, {-10, -5, 2}, {-10, -5, -3}),
          line(K::kApproach, {-10, -5, -3}, {-1, s3, -3}), line(K::kOffset, {-1, s3, -3}, {-1, 10, -3}),
          arc({-1, 10, -3}, {x, 10.5, -3}, {1, 10, -3}, false), arc({x, 10.5, -3}, {-1, 11, -3}, {1, 11, -3}, false),
          line(K::kOffset, {-1, 11, -3}, {-1, 23, -3}), line(K::kRetraction, {-1, 23, -3}, {-10, 30, -3}),
          line(K::kProgrammed, {-10, 30, -3}, {-10, 30, 2})});
}

// covers: TRC-CD-5 TRC-EDGE-4 TRC-EDGE-5
TEST(Collision, RetractionWithCdonSearchesFurtherBack) {
  // G41, r = 2, a pocket corner: N30 along y = 0, N40 up, N50 back to x = 14, N60 down 1 mm (too
  // short at its inner corner). G462 extends N60's equidistant x = 16 downwards from (16,5):
  // CDOF stops at N50's equidistant y = 4 (16,4); CDON searches on and takes N30's y = 2 (16,2),
  // the last found, skipping N40 ... N60 (MD20240 = 4 reaches N30).
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-5 Y5 Z0 T1 D1\nN20 G41 CDON G1 X0 Y0 F500\n"
      "N30 X20\nN40 Y6\nN50 X14\nN60 Y5\nN70 G40 G462 X10 Y-5\nN80 M30\n";
  MachineData md;
  md.set("MD20240", "4");
  Runs on = run_both(text, md);
  expect_both(on, {line(K::kProgrammed, {0, 0, 0}, {-5, 5, 0}), line(K::kApproach, {-5, 5, 0}, {0, 2, 0}),
                   line(K::kOffset, {0, 2, 0}, {16, 2, 0}), line(K::kRetraction, {16, 2, 0}, {10, -5, 0})});
  for (const RunResult* x : {&on.ref, &on.fast}) EXPECT_TRUE(has_decision(*x, "TRC-CD-5", "earlier-block"));
  std::string off = text;
  off.replace(off.find("CDON"), 4, "CDOF");
  Runs of = run_both(off, md);
  expect_both(of, {line(K::kProgrammed, {0, 0, 0}, {-5, 5, 0}), line(K::kApproach, {-5, 5, 0}, {0, 2, 0}),
                   line(K::kOffset, {0, 2, 0}, {18, 2, 0}), line(K::kOffset, {18, 2, 0}, {18, 4, 0}),
                   line(K::kOffset, {18, 4, 0}, {16, 4, 0}), line(K::kRetraction, {16, 4, 0}, {10, -5, 0})});
}

// covers: TRC-CD-6 TRC-EDGE-4 TRC-EDGE-1
TEST(Collision, ApproachWithCdonSearchesFurtherAhead) {
  // The retraction example run backwards (G42): N30 up 1 mm is too short for N40 (inner corner);
  // G462 extends N30's equidistant x = 16 downwards from (16,5). CDOF meets N40's y = 4 at (16,4);
  // CDON searches the later blocks (MD20240 = 4 after the selection) and takes N60's y = 2 at
  // (16,2), the last found: N30 ... N50 lose their plane motion.
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X10 Y15 Z0 T1 D1\n"
      "N20 G42 CDON G462 G1 X14 Y5 F500\nN30 Y6\nN40 X20\nN50 Y0\nN60 X0\nN70 G40 X-5 Y-5\nN80 M30\n";
  MachineData md;
  md.set("MD20240", "4");
  Runs on = run_both(text, md);
  expect_both(on, {line(K::kProgrammed, {0, 0, 0}, {10, 15, 0}), line(K::kApproach, {10, 15, 0}, {16, 2, 0}),
                   line(K::kOffset, {16, 2, 0}, {0, 2, 0}), line(K::kRetraction, {0, 2, 0}, {-5, -5, 0})});
  for (const RunResult* x : {&on.ref, &on.fast}) EXPECT_TRUE(has_decision(*x, "TRC-CD-6", "later-block"));
  std::string off = text;
  off.replace(off.find("CDON"), 4, "CDOF");
  Runs of = run_both(off, md);
  expect_both(of, {line(K::kProgrammed, {0, 0, 0}, {10, 15, 0}), line(K::kApproach, {10, 15, 0}, {16, 4, 0}),
                   line(K::kOffset, {16, 4, 0}, {18, 4, 0}), line(K::kOffset, {18, 4, 0}, {18, 2, 0}),
                   line(K::kOffset, {18, 2, 0}, {0, 2, 0}), line(K::kRetraction, {0, 2, 0}, {-5, -5, 0})});
}

}  // namespace
}  // namespace cutcom::test

namespace cutcom::test {
namespace {

// covers: TRC-CD-4 TRC-LOOK-3
TEST(Collision, ASecondCutRunsTheSkippedBlocksInfeedsAgain) {
  // Found by the SAR differential property: two CDON cuts on the same element (N60, then N80 cut
  // N20's quadrant). The blocks without plane motion after it (N30, N50, N70 move X, the
  // applicate in G19) run at the cut point both times; fast once lost N30's motion at the second
  // cut (its record, run again at the first cut, no longer knew its start and end).
  Runs r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4.986\nN10 G19 G90 G0 Y0 Z0 X0 T1 D1\n"
      "N20 G1 G247 G140 G341 DISR=5.313 FAD=200 G42 NORM G451 G462 CDON Y0 Z0 X0 F500\nN30 G1 X-1\n"
      "N40 G2 Y-2.026 Z-6.754 J2.364 K-4.390 G451\nN50 G1 X-2\nN60 G2 Y-1.026 Z-6.754 CR=-4.987 G451\nN70 G1 X-3\n"
      "N80 G3 Y-1.030 Z-6.752 J0.000 K0.005 G451\nN90 G1 X-4\nN100 G2 Y-1.037 Z-6.750 J0 K0.005 G451 G41\n");
  for (const RunResult* x : {&r.fast, &r.ref}) {
    ASSERT_EQ(x->path.size(), 5u);
    EXPECT_EQ(x->path[2].origin.line, 5);  // N30 at the cut point, from X0 to X-1
    EXPECT_NEAR(x->path[2].start.x, 0, 1e-12);
    EXPECT_NEAR(x->path[2].end.x, -1, 1e-12);
    ASSERT_EQ(x->alarms.size(), 1u);
    EXPECT_EQ(x->alarms[0].number, 10753);
  }
}

}  // namespace
}  // namespace cutcom::test
