// Turning tools with a cutting edge position: the path the program positions is the tool tip's.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "cutcom/output.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

// An outside contour in G18 with a cylinder, an arc, a face and a second cylinder.
std::string turning_program(const std::string& position, const std::string& type = "500",
                            const std::string& radius = "0.8") {
  return "$TC_DP1[1,1]=" + type + " $TC_DP2[1,1]=" + position + " $TC_DP6[1,1]=" + radius +
         "\n"
         "N10 G18 G90 G0 X60 Z5 T1 D1\n"
         "N20 G1 G42 X20 Z2 F0.2\n"
         "N30 Z-20\n"
         "N40 G3 X25 Z-25 CR=5\n"
         "N50 G1 X40\n"
         "N60 Z-50\n"
         "N70 G40 X70 Z-52\n"
         "N80 M30\n";
}

PathPoint moved(PathPoint p, double dz, double dx) { return {p.x + dx, p.y, p.z + dz}; }

// covers: TOOL-TURN-1
TEST(TurningTool, ThePathIsTheTipsTheCentresPathMovedAlongTheEdgePosition) {
  // Tip minus edge centre in (Z, X) for positions 1 … 8 (G18: Z abscissa, X ordinate).
  constexpr std::array<std::array<double, 2>, 8> kDirection{
      {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
  Runs centre = run_both(turning_program("9"));
  ASSERT_TRUE(centre.fast_ok && centre.ref_ok);
  for (int p = 1; p <= 8; ++p) {
    Runs tip = run_both(turning_program(std::to_string(p)));
    for (const RunResult* r : {&tip.fast, &tip.ref}) {
      ASSERT_EQ(r->path.size(), centre.fast.path.size()) << "position " << p;
      double dz = 0.8 * kDirection[static_cast<std::size_t>(p - 1)][0];
      double dx = 0.8 * kDirection[static_cast<std::size_t>(p - 1)][1];
      for (std::size_t i = 0; i < r->path.size(); ++i) {
        const PathElement& want = centre.fast.path[i];
        const PathElement& got = r->path[i];
        std::string what = "position " + std::to_string(p) + " element " + std::to_string(i);
        // The move before compensation, the approach's start and the retraction's end are the
        // programmed positions of the tip; everything between is the moved centre path.
        bool before = want.origin.kind == OriginKind::kProgrammed && i == 0;
        bool fixed_start = before || want.origin.kind == OriginKind::kApproach;
        bool fixed_end = before || want.origin.kind == OriginKind::kRetraction;
        expect_point(got.start, fixed_start ? want.start : moved(want.start, dz, dx), what + " start");
        expect_point(got.end, fixed_end ? want.end : moved(want.end, dz, dx), what + " end");
        if (want.type == ElementType::kArc) expect_point(got.center, moved(want.center, dz, dx), what + " centre");
      }
      ASSERT_EQ(r->notices.size(), 1u);
      EXPECT_EQ(r->notices[0].clause, "TOOL-TURN-1");
    }
  }
}

// covers: TOOL-TURN-1
TEST(TurningTool, AnOutsideToolsTipRunsOnTheCylindersAndTheFace) {
  // Position 3 (edges facing -Z and -X, an outside tool turning towards the chuck): the tip lies on
  // every cylinder and on the face it turns, 0.8 mm behind in Z (hand-derived).
  Runs r = run_both(turning_program("3"));
  expect_both(r, {
                     line(OriginKind::kProgrammed, {0, 0, 0}, {60, 0, 5}),
                     line(OriginKind::kApproach, {60, 0, 5}, {20, 0, 1.2}),
                     line(OriginKind::kOffset, {20, 0, 1.2}, {20, 0, -25.8 + std::sqrt(5.8 * 5.8 - 0.8 * 0.8)}),
                     {OriginKind::kOffset,
                      {20, 0, -25.8 + std::sqrt(5.8 * 5.8 - 0.8 * 0.8)},
                      {19.2 + std::sqrt(5.8 * 5.8 - 0.8 * 0.8), 0, -25},
                      {19.2, 0, -25.8},
                      true,
                      true},
                     line(OriginKind::kOffset, {19.2 + std::sqrt(5.8 * 5.8 - 0.8 * 0.8), 0, -25}, {39.2, 0, -25}),
                     arc({39.2, 0, -25}, {40, 0, -25.8}, {39.2, 0, -25.8}, true),
                     line(OriginKind::kOffset, {40, 0, -25.8}, {40, 0, -50.8}),
                     line(OriginKind::kRetraction, {40, 0, -50.8}, {70, 0, -52}),
                 });
  ASSERT_EQ(r.fast.notices.size(), 1u);
  EXPECT_NE(r.fast.notices[0].text.find("0.8 mm -Z -X of the edge centre"), std::string::npos)
      << r.fast.notices[0].text;
}

// covers: TOOL-TURN-1
TEST(TurningTool, PicturesDrawTheContourAsProgrammed) {
  // The reader moves the compensated contour by the tip's offset; the picture subtracts it again.
  std::istringstream in(turning_program("3"));
  ProgramReader reader(in, {});
  ProgrammedContour contour;
  std::vector<ProgrammedSegment> drawn;
  Block b;
  while (reader.next(b))
    if (auto s = contour.add(b)) drawn.push_back(*s);
  ASSERT_EQ(drawn.size(), 7u);  // N10 … N70
  expect_point(drawn[1].start, {60, 0, 5}, "N20 start");
  expect_point(drawn[1].end, {20, 0, 2}, "N20 end");
  expect_point(drawn[2].end, {20, 0, -20}, "N30 end");
  expect_point(drawn[3].end, {25, 0, -25}, "N40 end");
  expect_point(drawn[6].start, {40, 0, -50}, "N70 start");
  expect_point(drawn[6].end, {70, 0, -52}, "N70 end");
}

// covers: TOOL-TURN-1
TEST(TurningTool, SelectionAndDeselectionWithoutAPlaneAxis) {
  // G42 in a block without a plane axis selects at the next one (TRC-SEL-4); G40 without a plane
  // axis leaves the tool where it is (TRC-DESEL-3): the tip's moves around them are the same as
  // with the selection and deselection in the moving blocks.
  std::string tools = "$TC_DP1[1,1]=500 $TC_DP2[1,1]=3 $TC_DP6[1,1]=0.8\n";
  Runs apart = run_both(tools + "G18 G0 X60 Z5 T1 D1\nG42 F0.2\nG1 X20 Z2\nZ-20\nX40\nG40\nG0 X70 Z-22\nM30\n");
  ASSERT_TRUE(apart.fast_ok && apart.ref_ok);
  const PathElement& approach = apart.fast.path[1];
  expect_point(approach.start, {60, 0, 5}, "approach start");
  expect_point(approach.end, {20, 0, 1.2}, "approach end");
  const PathElement& last = apart.fast.path.back();
  expect_point(last.end, {70, 0, -22}, "the move after G40 ends at the programmed point");
  for (std::size_t i = 0; i < apart.fast.path.size(); ++i) {
    expect_point(apart.ref.path[i].start, apart.fast.path[i].start, "ref start");
    expect_point(apart.ref.path[i].end, apart.fast.path[i].end, "ref end");
  }
}

// covers: TOOL-TURN-1
TEST(TurningTool, EdgePositionsThatAreNoneOrWrong) {
  // A milling tool's $TC_DP2 and positions 0 and 9 leave the edge centre as reference.
  for (const char* plain : {"0", "9"}) EXPECT_TRUE(run_both(turning_program(plain)).fast.notices.empty());
  EXPECT_TRUE(run_both(turning_program("3", "120")).fast.notices.empty());
  for (const char* bad : {"2.5", "10", "-1"}) {
    bool ok = false;
    try {
      run_engine("fast", turning_program(bad), {}, &ok);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 2) << e.what();
      EXPECT_NE(std::string(e.what()).find("is not a whole number 0"), std::string::npos) << e.what();
    }
  }
  bool ok = false;
  EXPECT_THROW(run_engine("fast", turning_program("3", "500", "-0.8"), {}, &ok), InputError);
}

// covers: TOOL-TURN-1 TOOL-NAME-1
TEST(TurningTool, TheNoticeNamesANamedToolByItsName) {
  // A tool named in the program gets a number of cutcom's own: the notice names it as written.
  std::string named = "$TC_TP2[7]=\"FINISH 35\"\n" + turning_program("3");
  for (std::size_t at = named.find("T1"); at != std::string::npos; at = named.find("T1", at + 1))
    named.replace(at, 2, "T=\"FINISH 35\"");
  for (std::size_t at = named.find("[1,1]"); at != std::string::npos; at = named.find("[1,1]", at + 1))
    named.replace(at, 5, "[7,1]");
  Runs r = run_both(named);
  ASSERT_TRUE(r.fast_ok && r.ref_ok);
  ASSERT_EQ(r.fast.notices.size(), 1u);
  EXPECT_NE(r.fast.notices[0].text.find("T=\"FINISH 35\" D1 is a turning tool"), std::string::npos)
      << r.fast.notices[0].text;
  // A numbered tool keeps its number.
  Runs numbered = run_both(turning_program("3"));
  ASSERT_EQ(numbered.fast.notices.size(), 1u);
  EXPECT_NE(numbered.fast.notices[0].text.find("T1 D1 is a turning tool"), std::string::npos);
}

}  // namespace
}  // namespace cutcom::test
