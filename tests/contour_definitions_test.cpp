// Contour definitions, polar coordinates and rotated frames, resolved by the reader onto the grid
// (NC-CONTOUR-*, NC-POLAR-*, NC-FRAME-4, NC-GRID-1). Every expected value is worked out by hand
// in the comment above it.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "cutcom/fast/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/ref/engine.hpp"
#include "cutcom/sink.hpp"
#include "program_runs.hpp"

namespace cutcom {
namespace {

std::vector<Block> read(const std::string& text) { return testing::read_blocks(text); }
using testing::Both;
using testing::run_both;

Decimal dec(const char* s) { return *Decimal::parse(s).value; }

void expect_point(const Point3& p, const char* x, const char* y, const std::string& what) {
  EXPECT_EQ(p.x, dec(x)) << what << ": x = " << p.x.to_string();
  EXPECT_EQ(p.y, dec(y)) << what << ": y = " << p.y.to_string();
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

void expect_same_path(const RunResult& a, const RunResult& b, double tolerance = 1e-9) {
  ASSERT_EQ(a.path.size(), b.path.size());
  ASSERT_EQ(a.alarms.size(), b.alarms.size());
  for (std::size_t k = 0; k < a.path.size(); ++k) {
    const PathElement &p = a.path[k], &q = b.path[k];
    EXPECT_EQ(p.type, q.type) << k;
    EXPECT_NEAR(p.end.x, q.end.x, tolerance) << k;
    EXPECT_NEAR(p.end.y, q.end.y, tolerance) << k;
    EXPECT_NEAR(p.start.x, q.start.x, tolerance) << k;
    EXPECT_NEAR(p.start.y, q.start.y, tolerance) << k;
  }
}

// covers: NC-CONTOUR-1 NC-GRID-1
TEST(ContourDefinitions, RoundingBetweenTwoLines) {
  // Up the Y axis, then right: a right turn of 90°. RND=5: centre (5, 15), tangent points (0, 15)
  // and (5, 20), clockwise.
  auto b = read("G0 X0 Y0\nN20 G1 Y20 RND=5 F100\nN30 X20\n");
  ASSERT_EQ(b.size(), 4u);
  expect_point(b[1].end, "0", "15", "N20 ends at the tangent point");
  EXPECT_EQ(b[2].insert.kind, InsertKind::kRounding);
  EXPECT_EQ(b[2].insert.next_line, 3);
  EXPECT_EQ(*b[2].words.number, 20);
  EXPECT_TRUE(b[2].is_arc());
  EXPECT_EQ(b[2].state.motion, Motion::kArcCw);
  expect_point(*b[2].centre, "5", "15", "rounding centre");
  expect_point(b[2].end, "5", "20", "rounding end");
  expect_point(b[3].start, "5", "20", "N30 starts at the tangent point");
  expect_point(b[3].end, "20", "20", "N30 end unchanged");
}

// covers: NC-CONTOUR-1 NC-GRID-1
TEST(ContourDefinitions, ChamfersByLegAndByLength) {
  // CHR=3 at the same corner: (0, 17) to (3, 20).
  auto b = read("G0 X0 Y0\nG1 Y20 CHR=3 F100\nX20\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[2].insert.kind, InsertKind::kChamfer);
  EXPECT_FALSE(b[2].is_arc());
  expect_point(b[2].start, "0", "17", "chamfer start");
  expect_point(b[2].end, "3", "20", "chamfer end");
  // CHF=c at 90°: legs c / (2 cos 45°) = c / √2; c = 4.242640687 gives 2.99999999975…: the
  // points round to (0, 17.000000000) and (2.999999999|75 → 3.000000000, 20).
  b = read("G0 X0 Y0\nG1 Y20 CHF=4.242640687 F100\nX20\n");
  ASSERT_EQ(b.size(), 4u);
  expect_point(b[2].start, "0", "17", "CHF start");
  expect_point(b[2].end, "3", "20", "CHF end");
}

// covers: NC-CONTOUR-1 NC-GRID-1
TEST(ContourDefinitions, RoundingBetweenALineAndACircle) {
  // Along +X into (0,0), then G2 about (10,0) (radius 10, leaving upwards): a left turn. The
  // centre F is at distance 2.5 from the line (y = 2.5) and 12.5 from (10,0) (outside the cw
  // circle): (x − 10)² = 12.5² − 2.5² = 150, x = 10 − √150 = −2.2474487139… → −2.247448714.
  // Tangent points: (x, 0) and (10,0) + 10/12.5·(F − C) = (10 − 0.8√150, 2) = (0.2020410288…, 2).
  auto b = read("G0 X-20 Y0\nG1 X0 RND=2.5 F100\nG2 X20 Y0 I10 J0\n");
  ASSERT_EQ(b.size(), 4u);
  expect_point(b[1].end, "-2.247448714", "0", "line ends at the tangent point");
  expect_point(*b[2].centre, "-2.247448714", "2.5", "rounding centre");
  EXPECT_EQ(b[2].state.motion, Motion::kArcCcw);
  expect_point(b[2].end, "0.202041029", "2", "rounding ends on the circle");
  expect_point(b[3].start, "0.202041029", "2", "circle starts there");
  expect_point(*b[3].centre, "10", "0", "circle centre kept");
}

// A rounding lies on the grid, tangent to its neighbours only to within it. With the tool outside
// it, N60's offset and the rounding's cross by 1e-21 mm at the corner the rounding leaves, which
// double shows as a miss: fast raised alarm 10751 on this ordinary program. Both run it through.
// covers: NC-CONTOUR-1 TRC-ARC-CORNER-1
TEST(ContourDefinitions, RoundingWithTheToolOutsideRunsInBothEngines) {
  Both r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nG17 G90 G0 X-15 Y-15 T1 D1\nG1 G41 X0 Y0 F800\nY60\n"
      "G2 X20 Y80 CR=20\nG1 X100 Y80\nY20\nX80 Y0 RND=5\nX0\nG40 X-15 Y-15\nM30\n");
  EXPECT_TRUE(r.ref.alarms.empty());
  EXPECT_TRUE(r.fast.alarms.empty());
  expect_same_path(r.ref, r.fast, 1e-6);  // the crossing of nearly tangent carriers: sqrt(u) of the size
}

// covers: NC-CONTOUR-1
TEST(ContourDefinitions, TooLargeIsReducedToTheLargestThatFits) {
  // Line (0,0)->(0,2), then X20: a right angle, tangent length = r, so RND=5 becomes r = 2 and
  // touches N20 at its start: N20 keeps no motion in the plane, the rounding runs (0,0)->(2,2).
  auto b = read("G0 X0 Y0\nN20 G1 Y2 RND=5 F100\nN30 X20\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_FALSE(b[1].moves_in_plane());
  EXPECT_NE(b[1].notice.find("reduced to 2 mm"), std::string::npos) << b[1].notice;
  expect_point(*b[2].centre, "2", "0", "reduced rounding centre");
  expect_point(b[2].end, "2", "2", "reduced rounding end");
  // CHR=20 on N40 (8 long) into a line of 20: legs of 8, from (20,2) to (12,10).
  b = read("G0 X20 Y2\nN40 G1 Y10 CHR=20 F100\nN50 X0\n");
  ASSERT_EQ(b.size(), 4u);
  expect_point(b[2].start, "20", "2", "reduced chamfer start");
  expect_point(b[2].end, "12", "10", "reduced chamfer end");
  // Line (0,-2)->(0,0), then cw circle about (0,-10), R 10: a right turn. The rounding of radius r
  // has its centre at (r, y) with r² + (y+10)² = (10-r)²; its foot on the line must stay at y >= -2,
  // so r = (100 - 64) / 20 = 1.8 at y = -2, and it meets the circle at C + 10/8.2·(1.8, 8).
  b = read("G0 X0 Y-2\nN20 G1 Y0 RND=5 F100\nN30 G2 X10 Y-10 I0 J-10\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_NE(b[1].notice.find("reduced to 1.8 mm"), std::string::npos) << b[1].notice;
  expect_point(*b[2].centre, "1.8", "-2", "rounding centre");
  expect_point(b[2].end, "2.195121951", "-0.243902439", "rounding meets the circle");
  EXPECT_EQ(b[2].state.motion, Motion::kArcCw);
  // Under compensation the emptied N20 is a block without plane motion (TRC-CORNER-7 counts it)
  // and both engines run the reduced rounding alike: offset by 0.5 it runs (-0.5,0)->(2,2.5).
  Both r = run_both(
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.5\nG0 X-10 Y-5\nT1 D1\nG41 G1 X0 Y0 F100\nN20 Y2 RND=5\n"
      "N30 X20\nG40 G1 X30 Y-5\n");
  ASSERT_GE(r.ref.path.size(), 3u);
  EXPECT_NEAR(r.ref.path[2].start.x, -0.5, 1e-12);
  EXPECT_NEAR(r.ref.path[2].end.y, 2.5, 1e-12);
  expect_same_path(r.ref, r.fast);
}

// covers: NC-CONTOUR-1
TEST(ContourDefinitions, BoundaryRulesAndWhatIsNotInserted) {
  // Tangent corner (line along +X into a cw circle about (0,-10)): nothing inserted.
  auto b = read("G0 X-20 Y0\nG1 X0 RND=2 F100\nG2 X10 Y-10 I0 J-10\n");
  EXPECT_EQ(b.size(), 3u);
  EXPECT_NE(b[1].notice.find("meet tangentially"), std::string::npos) << b[1].notice;
  // The same with CHF: said too; with a modal RNDM the tangent corner passes without a word.
  b = read("G0 X-20 Y0\nG1 X0 CHF=2 F100\nG2 X10 Y-10 I0 J-10\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_NE(b[1].notice.find("chamfer of"), std::string::npos) << b[1].notice;
  b = read("G0 X-20 Y0\nG1 X0 RNDM=2 F100\nG2 X10 Y-10 I0 J-10\nRNDM=0\n");
  ASSERT_GE(b.size(), 3u);
  EXPECT_EQ(b[1].notice.find("meet tangentially"), std::string::npos) << b[1].notice;
  // A reversal: error.
  EXPECT_NE(error_of("G0 X0 Y0\nG1 Y20 RND=1 F100\nY0\n").find("reverses"), std::string::npos);
  // Three blocks without plane motion between the elements: still rounded, they run after it.
  b = read("G0 X0 Y0\nG1 Y20 RND=5 F100\nM8\nZ-1\nS100\nX20\n");
  ASSERT_EQ(b.size(), 7u);
  EXPECT_EQ(b[2].insert.kind, InsertKind::kRounding);
  expect_point(b[3].start, "5", "20", "M8 runs at the end of the rounding");
  // Four: not inserted, with a notice.
  b = read("G0 X0 Y0\nG1 Y20 RND=5 F100\nM8\nM9\nZ-1\nS100\nX20\n");
  ASSERT_EQ(b.size(), 7u);
  EXPECT_NE(b[1].notice.find("not inserted"), std::string::npos);
  // At the end of the program: a notice.
  b = read("G0 X0 Y0\nG1 Y20 RND=5 F100\nM30\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_NE(b[1].notice.find("no element follows"), std::string::npos);
  // RND in a block without plane motion.
  EXPECT_NE(error_of("G1 Z5 RND=2 F100\n").find("without motion in the plane"), std::string::npos);
  // A turn of 1e-7 rad and RND=0.001: the tangent points lie 5e-11 from the corner, both on the
  // grid point (10, 0). A rounding from there to there would read as a full circle: nothing is
  // inserted, with a notice (found by Differential.FastAgreesWithRefOnContourDefinitions).
  b = read("G0 X0 Y0\nG1 X10 RND=0.001 F100\nX20 Y0.000001\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_NE(b[1].notice.find("shorter than 10^-9 mm"), std::string::npos);
  expect_point(b[1].end, "10", "0", "the corner stays");
}

// covers: NC-CONTOUR-2 NC-UNIT-1
TEST(ContourDefinitions, ModalRoundingAndItsFeed) {
  // A square corner path, RNDM=2 from the first block: both corners rounded; RNDM=0 ends it.
  auto b = read("G0 X0 Y0\nG1 Y10 RNDM=2 F100 FRCM=40\nX10\nY0 RNDM=0\nX0\n");
  int roundings = 0;
  for (const Block& k : b)
    if (k.insert.kind == InsertKind::kRounding) {
      ++roundings;
      EXPECT_EQ(k.state.feed, dec("40"));  // FRCM
    }
  EXPECT_EQ(roundings, 2);
  // FRC in the block: that feed for the element it inserts only.
  b = read("G0 X0 Y0\nG1 Y10 RND=2 FRC=25 F100\nX10\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[2].state.feed, dec("25"));
  EXPECT_EQ(b[3].state.feed, dec("100"));
  // G700: FRC and FRCM are feeds in inch/min, converted like F (NC-UNIT-1); RND a length.
  b = read("G700 G0 X0 Y0\nG1 Y10 RND=0.1 FRC=2 F10\nX10 RND=0.1 FRCM=1\nY0\n");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[2].state.feed, dec("50.8"));
  EXPECT_EQ(b[4].state.feed, dec("25.4"));
  EXPECT_EQ(b[5].state.feed, dec("254"));
  // After G0: the chamfer is rapid.
  b = read("G0 X0 Y0\nY10 CHR=1\nX10\n");
  EXPECT_EQ(b[2].state.motion, Motion::kRapid);
}

// covers: NC-CONTOUR-3 NC-GRID-1
TEST(ContourDefinitions, LinesByAngle) {
  // From (10,10), ANG=60 to X20: Y = 10 + 10·tan 60° = 27.3205080756… → 27.320508076.
  auto b = read("G0 X10 Y10\nG1 ANG=60 X20 F100\n");
  expect_point(b[1].end, "20", "27.320508076", "one coordinate and the angle");
  // ANG=45 to Y20: X = 10 + 10 = 20 (cos/sin 45° cancel exactly up to rounding).
  b = read("G0 X10 Y10\nG1 ANG=45 Y20 F100\n");
  expect_point(b[1].end, "20", "20", "ordinate given");
  // Two blocks: leaving (28,90) at 180°, arriving at (-20,0) at 270°: corner (-20, 90).
  b = read("G0 X28 Y90\nG1 ANG=180 F100\nX-20 Y0 ANG=270\n");
  ASSERT_EQ(b.size(), 3u);
  expect_point(b[1].end, "-20", "90", "corner");
  expect_point(b[2].start, "-20", "90", "second line starts at the corner");
  // With a rounding at the corner of the two-block form.
  b = read("G0 X28 Y90\nG1 ANG=180 RND=3 F100\nX-20 Y0 ANG=270\n");
  ASSERT_EQ(b.size(), 4u);
  expect_point(*b[2].centre, "-17", "87", "rounding at the computed corner");
  // Boundary rules: parallel lines, an angle parallel to the given axis, the second block missing.
  EXPECT_NE(error_of("G0 X0 Y0\nG1 ANG=0 F100\nX10 Y5 ANG=180\n").find("parallel"), std::string::npos);
  EXPECT_NE(error_of("G0 X0 Y0\nG1 ANG=90 X5 F100\n").find("vertical"), std::string::npos);
  EXPECT_NE(error_of("G0 X0 Y0\nG1 ANG=30 F100\nM30\n").find("two-block"), std::string::npos);
  EXPECT_NE(error_of("G0 X0 Y0\nG1 ANG=30 X1 Y1 F100\n").find("given twice"), std::string::npos);
  // Nearly parallel: a corner beyond the range of values is a reading error, not an internal one.
  EXPECT_NE(error_of("G0 X0 Y0\nG1 ANG=0.000000001 F100\nX10 Y999999999 ANG=0\n").find("out of range"),
            std::string::npos);
}

// covers: NC-CONTOUR-4
TEST(ContourDefinitions, CirclesThroughAPointAndTangential) {
  // CIP from (0,0) through (10,10) to (20,0): centre (10,0), clockwise.
  auto b = read("G0 X0 Y0\nCIP X20 Y0 I1=10 J1=10 F100\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_TRUE(b[1].is_arc());
  EXPECT_EQ(b[1].state.motion, Motion::kArcCw);
  expect_point(*b[1].centre, "10", "0", "CIP centre");
  // CT after it: the tangent at (20,0) points down; to (40,0): centre (30,0), counter-clockwise.
  b = read("G0 X0 Y0\nCIP X20 Y0 I1=10 J1=10 F100\nCT X40 Y0\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[2].state.motion, Motion::kArcCcw);
  expect_point(*b[2].centre, "30", "0", "CT centre");
  // CT after a line along +X from (0,0) to (10,0), to (20,10): centre (10,10), ccw.
  b = read("G0 X0 Y0\nG1 X10 F100\nCT X20 Y10\n");
  expect_point(*b[2].centre, "10", "10", "CT after a line");
  EXPECT_EQ(b[2].state.motion, Motion::kArcCcw);
  EXPECT_NE(error_of("G0 X0 Y0\nCIP X20 Y0 I1=10 J1=0 F100\n").find("one line"), std::string::npos);
  EXPECT_NE(error_of("G0 X0 Y0\nG1 X10 F100\nCT X20 Y0\n").find("tangent"), std::string::npos);
}

// covers: NC-CONTOUR-5
TEST(ContourDefinitions, CirclesByOpeningAngle) {
  // G2 from (40,0) to (60,0) with AR=90: centre m − cot 45°/2·perp(20,0) = (50,0) − (0,10).
  auto b = read("G0 X40 Y0\nG2 X60 Y0 AR=90 F100\n");
  expect_point(*b[1].centre, "50", "-10", "AR with end point");
  // G3 about (70,0) from (60,0) by 270°: ends at (70,10).
  b = read("G0 X60 Y0\nG3 I10 J0 AR=270 F100\n");
  expect_point(b[1].end, "70", "10", "AR with centre");
  // AR=180: the centre is the chord's midpoint.
  b = read("G0 X0 Y0\nG3 X10 Y0 AR=180 F100\n");
  expect_point(*b[1].centre, "5", "0", "half circle");
  EXPECT_NE(error_of("G0 X0 Y0\nG3 X10 Y0 I5 J0 AR=90 F100\n").find("not both"), std::string::npos);
  EXPECT_NE(error_of("G0 X0 Y0\nG3 X10 Y0 AR=360 F100\n").find("between 0 and 360"), std::string::npos);
}

// covers: NC-CONTOUR-6 NC-GRID-1
TEST(ContourDefinitions, HelixWithExtraTurns) {
  // A full circle with TURN=2 and 10 mm infeed: three turns, levels -10/3 → -3.333333333 and
  // -20/3 → -6.666666667.
  auto b = read("G0 X100 Y0 Z0\nN60 G3 X100 Y0 Z-10 I10 J0 TURN=2 F100\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[1].insert.kind, InsertKind::kTurn);
  EXPECT_EQ(b[1].insert.turn, 1);
  EXPECT_EQ(b[1].end.z, dec("-3.333333333"));
  EXPECT_EQ(b[2].end.z, dec("-6.666666667"));
  EXPECT_EQ(b[3].start.z, dec("-6.666666667"));
  EXPECT_EQ(b[3].end.z, dec("-10"));
  EXPECT_EQ(b[3].insert.kind, InsertKind::kNone);
  // A half circle with TURN=1: 360 of 540 degrees of the infeed in the first turn: -6 of -9.
  b = read("G0 X0 Y0 Z0\nG3 X20 Y0 Z-9 I10 J0 TURN=1 F100\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[1].end.z, dec("-6"));
  EXPECT_NE(error_of("G0 X0 Y0\nG3 X20 Y0 CR=10 TURN=1 F100\n").find("centre"), std::string::npos);
}

// covers: NC-POLAR-1 NC-POLAR-2 NC-GRID-1
TEST(ContourDefinitions, PolarCoordinates) {
  // Pole (10,10); AP=30 RP=20: (10 + 20 cos 30°, 10 + 20 sin 30°) = (27.3205080756…, 20).
  auto b = read("G0 X0 Y0\nG111 X10 Y10\nG1 AP=30 RP=20 F100\nAP=IC(30)\nG3 AP=150\n");
  ASSERT_EQ(b.size(), 5u);
  expect_point(b[2].end, "27.320508076", "20", "AP=30");
  expect_point(b[3].end, "20", "27.320508076", "AP=IC(30): 60°, RP kept");
  expect_point(*b[4].centre, "10", "10", "a polar circle turns about the pole");
  expect_point(b[4].end, "-7.320508076", "20", "AP=150");
  // G110 from the last position, G112 from the last pole.
  b = read("G0 X5 Y5\nG110 X1 Y1\nG1 AP=90 RP=2 F100\nG112 X10\nG1 AP=0 RP=1\n");
  expect_point(b[2].end, "6", "8", "pole (6,6)");
  expect_point(b[4].end, "17", "6", "pole (16,6)");
  // Without a pole: the workpiece zero. RP=1e-9 at AP=30: y = 5e-10 is a tie: away from zero.
  b = read("G1 AP=30 RP=0.000000001 F100\nAP=210\n");
  expect_point(b[0].end, "0.000000001", "0.000000001", "tie rounds away from zero");
  expect_point(b[1].end, "-0.000000001", "-0.000000001", "negative tie");
  EXPECT_NE(error_of("G1 X1 AP=30 RP=2 F100\n").find("either polar or Cartesian"), std::string::npos);
}

// covers: NC-FRAME-4 NC-GRID-1
TEST(ContourDefinitions, RotatedFrames) {
  // TRANS X50, AROT RPL=30: X10 Y0 goes to (50 + 10 cos 30°, 10 sin 30°) = (58.660254038, 5).
  auto b = read("TRANS X50\nAROT RPL=30\nG1 X10 Y0 F100\n");
  ASSERT_EQ(b.size(), 3u);
  expect_point(b[2].end, "58.660254038", "5", "rotated point");
  // ROT Z90, then G91 X10 moves along +Y; a lone Y keeps the frame's X.
  b = read("G0 X10 Y10\nROT Z90\nG91 X10\nG90 Y5\n");
  expect_point(b[2].end, "10", "20", "incremental along the rotated X");
  expect_point(b[3].end, "-5", "20", "frame X = 20 kept, Y = 5");
  // AROT after MIRROR X turns the other way: mirror then +90° acts as −90° on the output.
  b = read("MIRROR X0\nAROT RPL=90\nG1 X1 Y0 F100\n");
  expect_point(b[2].end, "0", "1", "mirrored (-1,0) turned by −90°·(−1)... lands on (0,1)");
  // ROT X180 mirrors Y and Z exactly; circles swap sense.
  b = read("ROT X180\nG2 X10 Y10 I5 J5 F100\n");
  expect_point(b[1].end, "10", "-10", "half turn about X");
  EXPECT_EQ(b[1].state.motion, Motion::kArcCcw);
  EXPECT_NE(error_of("ROT X30\nG1 X1 F100\n").find("tilts"), std::string::npos);
  EXPECT_NE(error_of("SCALE X2 Y1\nAROT RPL=10\n").find("shear"), std::string::npos);
  EXPECT_NE(error_of("G41 D0 G1 X1 F100\nROT RPL=10\n").find("G40"), std::string::npos);
}

// covers: NC-FRAME-4 NC-CONTOUR-1 PROP-DIFF-1
TEST(ContourDefinitions, ARotatedCompensatedContourEqualsTheRotatedProgram) {
  // A square with roundings and a chamfer, once under ROT RPL=90 and once written rotated by
  // hand ((x, y) → (−y, x)); both engines give the same path, and fast agrees with ref.
  const std::string tool = "$TC_DP6[1,1]=2\nT1 D1\n";
  const std::string framed = tool +
                             "ROT RPL=90\nG0 X-10 Y0\nG1 G41 X0 Y0 F100\nY30 RND=5\nX30 CHR=3\nY0 RND=2\nX0\nG40 "
                             "G0 X-10\nM30\n";
  const std::string by_hand =
      tool + "G0 X0 Y-10\nG1 G41 X0 Y0 F100\nX-30 RND=5\nY30 CHR=3\nX0 RND=2\nY0\nG40 G0 Y-10\nM30\n";
  Both a = run_both(framed), h = run_both(by_hand);
  expect_same_path(a.fast, a.ref);
  expect_same_path(a.ref, h.ref);
  EXPECT_TRUE(a.ref.alarms.empty());
  EXPECT_GE(a.ref.path.size(), 8u);
}

}  // namespace
}  // namespace cutcom
