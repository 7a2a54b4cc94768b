// Face machining on a lathe under TRANSMIT (spec nc-reader.md, NC-WORD-13): the face's cartesian
// contour compensated as without the transformation, and what the control refuses there.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"
#include "program_runs.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

std::vector<Block> read(const std::string& text) { return testing::read_blocks(text); }

// covers: NC-WORD-13 NC-CYCLE-1
TEST(TransformationWords, UnderTransmitTheFacesCartesianContourIsCompensated) {
  // A flat milled on a lathe's face: the compensated path is the one the same contour gives
  // without the transformation, in both engines.
  const std::string head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=3\nG18 G90 T1 D1\nG0 X60 Z5\nDIAMOF\n";
  const std::string contour =
      "G17 G94\nG0 X30 Y0 Z2\nG1 Z-2 F200\nG1 G41 X20 Y-10\nY10\nX-10\nG3 X-10 Y-10 CR=10\nG1 X20\n"
      "G40 X30 Y-20\nG0 Z20\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_t = false, ok_p = false;
    MachineData md;
    RunResult t = run_engine(engine, head + "TRANSMIT\n" + contour + "TRAFOOF\nG18 G0 X40 Z50\nM30\n", md, &ok_t);
    RunResult p = run_engine(engine, head + contour + "G18 G0 X40 Z50\nM30\n", md, &ok_p);
    ASSERT_TRUE(ok_t && ok_p) << engine;
    ASSERT_EQ(t.path.size(), p.path.size()) << engine;
    for (std::size_t i = 0; i < t.path.size(); ++i) {
      for (auto [a, b] : {std::pair{t.path[i].start, p.path[i].start}, std::pair{t.path[i].end, p.path[i].end}})
        EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z) << engine << " element " << i;
    }
  }
  // The rotary axis' angle decides where the tool is in X, Y after TRANSMIT and in X after
  // TRAFOOF: unknown until programmed (the note says so); compensation needs them first.
  auto b = read("DIAMOF\nG0 X30 Z5\nTRANSMIT\nG17\nG0 Z2\nX20 Y5\nTRAFOOF\nG18 G0 Z10\n");
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(b[2].notice_clause, "NC-WORD-13");
  EXPECT_NE(b[4].notice.find("the position of XY is not known since TRANSMIT in line 3"), std::string::npos)
      << b[4].notice;
  EXPECT_NE(b[7].notice.find("since TRAFOOF in line 7"), std::string::npos) << b[7].notice;
  EXPECT_THROW(read("DIAMOF\nTRANSMIT\nG17 T1 D1\nG1 G41 Y5 F100\nX10\n"), InputError);
  // Diameter programming under TRANSMIT and TRANSMIT under compensation: not simulated.
  EXPECT_THROW(read("DIAMON\nTRANSMIT\n"), InputError);
  EXPECT_THROW(read("DIAMOF\nTRANSMIT\nDIAMON\n"), InputError);
  EXPECT_THROW(read("G17 T1 D1 G1 G41 X10 Y0 F100\nTRANSMIT\n"), InputError);
  // A tool change under compensation: blended without a transformation (TRC-RADIUS-3), an error
  // under TRANSMIT, as the control allows it there only after G40.
  const std::string tools = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n$TC_DP1[2,1]=120\n$TC_DP6[2,1]=3\n";
  const std::string change = "G17 T1 D1 G0 X30 Y0\nG1 G41 X20 Y-10 F100\nY10\nT2 D1 X-10\nY-10\nG40 X30 Y-20\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok = false;
    MachineData md;
    run_engine(engine, tools + "DIAMOF\n" + change, md, &ok);
    EXPECT_TRUE(ok) << engine;
    EXPECT_THROW(run_engine(engine, tools + "DIAMOF\nTRANSMIT\n" + change, md, &ok), InputError) << engine;
  }
}

}  // namespace
}  // namespace cutcom::test
