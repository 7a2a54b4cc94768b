// The words real part programs carry around their contours (program_words_test.cpp): here tool
// changes, tool tables and names, and cycles that are not simulated.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "cutcom/fast/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/ref/engine.hpp"
#include "cutcom/sink.hpp"
#include "program_runs.hpp"
#include "program_words_support.hpp"
#include "support.hpp"

namespace cutcom {
namespace {

using testing::Both;
using testing::run_both;
using words_test::actions;
using words_test::dec;
using words_test::pt;
using words_test::read;

// covers: TOOL-CHANGE-1 TOOL-CHANGE-2 TOOL-NAME-1 TOOL-DATA-1
TEST(ProgramWords, ToolChangeEdgeDefaultAndNames) {
  const char* table = "$TC_TP2[3]=\"CUTTER 10\"\n$TC_DP1[3,1]=120 $TC_DP6[3,1]=5\n$TC_DP6[3,2]=4\n";
  auto b = read(std::string(table) + "T=\"CUTTER 10\"\nD2\nT3\nT0\n");
  EXPECT_EQ(b[3].state.tool, 3);
  EXPECT_EQ(b[3].state.edge, 1);  // MD20270 = 1: a tool change activates D1
  EXPECT_EQ(b[3].state.effective_radius(), dec("5"));
  EXPECT_EQ(b[4].state.edge, 2);
  EXPECT_EQ(b[5].state.edge, 1);
  EXPECT_EQ(b[6].state.edge, 0);  // T0: no tool, no edge
  ModalState m6;
  m6.md_change_on_m6 = true;
  auto c = read(std::string(table) + "T3\nM6\nT5 D2\n", m6);
  EXPECT_EQ(c[3].state.tool, 0);  // MD22550 = 1: T only preselects
  EXPECT_EQ(c[4].state.tool, 3);
  EXPECT_EQ(c[4].state.edge, 1);
  EXPECT_EQ(c[5].state.tool, 3);
  EXPECT_EQ(c[5].state.edge, 2);
  ModalState keep;
  keep.md_edge_default = -1;
  auto d = read(std::string(table) + "T3 D2\nT3\n", keep);
  EXPECT_EQ(d[4].state.edge, 2);  // MD20270 = -1: the D number stays
  EXPECT_THROW(read("T=\"NO SUCH\"\n"), InputError);
  EXPECT_THROW(read("M6\n", m6), InputError);
}

// covers: TOOL-FILE-1 MD-FILE-1
TEST(ProgramWords, ToolArchiveFile) {
  ToolTable t;
  std::istringstream file(
      "%_N_TO_INI\nCHANDATA(1)\n$TC_TP1[1]=1\n$TC_TP2[1]=\"FRAES_12\"\n$TC_TP8[1]=2\n$TC_DP1[1,1]=120\n"
      "$TC_DP3[1,1]=80.5\n$TC_DP6[1,1]=6\n$TC_DP15[1,1]=-0.01\n$TC_MOP1[1,1]=0\n"
      // Edge data beside the parameters $TC_DPn: the edge's number, its H number, OEM parameters.
      "$TC_DPCE[1,1]=1\n$TC_DPH[1,1]=0\n$TC_DPC1[1,1]=0.5\n$TC_DPV[1,1]=0\n; end\nM17\n");
  t.load(file, "TO_INI.INI");
  ASSERT_NE(t.find(1, 1), nullptr);
  EXPECT_EQ(t.find(1, 1)->radius, dec("6"));
  EXPECT_EQ(t.find(1, 1)->wear, dec("-0.01"));
  EXPECT_EQ(*t.number_of("FRAES_12"), 1);
  // A second channel's data: refused, naming the line (MD-FILE-1).
  std::istringstream two("CHANDATA(1)\n$TC_DP6[1,1]=6\nCHANDATA(2)\n$TC_DP6[1,1]=7\n");
  try {
    ToolTable u;
    u.load(two, "TO_INI.INI");
    ADD_FAILURE() << "two channels accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("more than one channel"), std::string::npos) << e.what();
  }
  std::istringstream bad("$TC_DP6[1,1]=6\nG1 X10\n");
  try {
    ToolTable u;
    u.load(bad, "TO_INI.INI");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("TO_INI.INI"), std::string::npos);
  }
}

// covers: TOOL-FILE-2
TEST(ProgramWords, ToolEdgeFromTheCommandLine) {
  ToolTable t;
  std::istringstream file("$TC_TP2[7]=\"ROUGH\"\n$TC_DP1[7,1]=140\n$TC_DP6[7,1]=8\n");
  t.load(file, "TO_INI.INI");
  t.define("3=5");
  t.define("\"FLAT 10\"/2=4.98");
  t.define("ROUGH=7.5");  // a name in the table: its number, its type kept
  ASSERT_NE(t.find(3, 1), nullptr);
  EXPECT_EQ(t.find(3, 1)->radius, dec("5"));
  EXPECT_EQ(t.find(3, 1)->type, dec("120"));
  auto flat = t.number_of("FLAT 10");
  ASSERT_TRUE(flat);
  EXPECT_NE(*flat, 3);
  EXPECT_NE(*flat, 7);
  ASSERT_NE(t.find(*flat, 2), nullptr);
  EXPECT_EQ(t.find(*flat, 2)->radius, dec("4.98"));
  EXPECT_EQ(t.find(7, 1)->radius, dec("7.5"));
  EXPECT_EQ(t.find(7, 1)->type, dec("140"));
  // RADIUS,POSITION: a turning tool with its cutting edge position (TOOL-TURN-1).
  t.define("4=0.4,3");
  ASSERT_NE(t.find(4, 1), nullptr);
  EXPECT_EQ(t.find(4, 1)->type, dec("500"));
  EXPECT_EQ(t.find(4, 1)->position, dec("3"));
  EXPECT_EQ(t.find(4, 1)->radius, dec("0.4"));
  for (const char* bad : {"4=0.4,", "4=0.4,10", "4=0.4,2.5", "4=0.4,x"}) {
    try {
      t.define(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cutting edge position"), std::string::npos) << bad << ": " << e.what();
    }
  }
  // The program selects the named tool by that name.
  std::istringstream program("T=\"FLAT 10\" D2\nG1 G41 X10 Y0 F100\n");
  ProgramReader reader(program);
  reader.tools() = t;
  Block b;
  while (reader.next(b)) {
  }
  for (const char* bad : {"5", "x=", "0=5", "3/0=5", "=5", "3=five"}) {
    try {
      t.define(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_GE(e.column(), 1) << bad;
    }
  }
}

// covers: NC-CYCLE-1 NC-CYCLE-2
TEST(ProgramWords, CyclesAreNotSimulatedAndLeaveThePositionUnknown) {
  auto b = read(
      "G0 X10 Y10 Z5\nCYCLE81(5,0,1,-10,,0)\nG0 Z50\nX20 Y20\nSUPA G0 Z0\nG0 X1 Y1\n"
      "MCALL CYCLE82(5,0,1,-10,,1)\nX30 Y30\nX40\nMCALL\n");
  EXPECT_EQ(b[1].notice_clause, "NC-CYCLE-1");
  EXPECT_FALSE(b[1].moves_in_plane());
  EXPECT_TRUE(b[2].notice.empty());            // a drilling cycle leaves only Z unknown, and N3 programs it
  EXPECT_EQ(b[2].start, pt("10", "10", "5"));  // starts where the tool was before the cycle
  EXPECT_TRUE(b[3].notice.empty());
  EXPECT_FALSE(b[4].words.programs_any_axis());  // SUPA's Z is not a move
  EXPECT_EQ(b[4].end, pt("20", "20", "50"));
  EXPECT_NE(b[5].notice.find("Z is not known since SUPA"), std::string::npos) << b[5].notice;
  EXPECT_EQ(b[6].notice_clause, "NC-CYCLE-2");
  EXPECT_NE(b[7].notice.find("Z is not known since MCALL CYCLE82 in line 7"), std::string::npos) << b[7].notice;
  EXPECT_TRUE(b[8].notice.empty());  // one notice for the whole modal call
  auto p = read("G0 X10 Y10 Z5\nPOCKET3(5,0,1)\nG0 Z50\n");
  EXPECT_NE(p[2].notice.find("the position of XY is not known since POCKET3"), std::string::npos) << p[2].notice;
  EXPECT_THROW(read("G41 T1 D1 X1 Y1\nCYCLE81(5,0,1,-10)\n"), InputError);
  EXPECT_THROW(read("POCKET3(5,0,1,-10)\nG1 G41 T1 D1 X5\n"), InputError);  // Y unknown under G41
  // G74/G75 name their axes with the extension 1 (and G75 its fixed point): actions of the block.
  auto home = read("G0 X10 Y10 Z5\nG74 X1=0 Y1=0 Z1=0\nG75 FP=2 Z1=0 A1=0\nG0 X1 Y1 Z1\n");
  EXPECT_EQ(home[1].words.not_simulated, "G74");
  EXPECT_EQ(actions(home[2]), (std::vector<std::string>{"FP=2", "Z1=0", "A1=0"}));
  EXPECT_THROW(read("G1 X1=0 F100\n"), InputError);  // only after G74/G75
}

// A machine's own tool change (L6, TC(2)) read as a standard cycle once named (NC-CYCLE-3);
// without the name the call stays an error that says how to name it.
std::vector<Block> read_with_machine_cycles(const std::string& text, std::vector<std::string> names) {
  std::istringstream in(text);
  ProgramReader reader(in);
  reader.no_subprogram_files();
  reader.set_machine_cycles(std::move(names));
  std::vector<Block> out;
  Block b;
  while (reader.next(b)) out.push_back(b);
  return out;
}

// covers: NC-CYCLE-3
TEST(ProgramWords, MachineCyclesNamedOnTheCommandLineAreNotSimulated) {
  const std::string program = "G0 X10 Y10 Z5\nL6\nTC(2)\nG0 X20 Y20 Z50\nWZW\nG0 X1\n";
  auto b = read_with_machine_cycles(program, {"L6", "TC", "WZW"});
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[1].words.not_simulated, "L6");
  EXPECT_EQ(b[1].notice_clause, "NC-CYCLE-1");
  EXPECT_FALSE(b[1].moves_in_plane());
  EXPECT_EQ(b[2].words.not_simulated, "TC");
  EXPECT_EQ(b[3].start, pt("10", "10", "5"));  // where the tool was before: nothing programmed since
  EXPECT_TRUE(b[3].notice.empty());            // every axis programmed absolutely again
  EXPECT_NE(b[5].notice.find("YZ is not known since WZW"), std::string::npos) << b[5].notice;
  EXPECT_EQ(b[5].start, pt("20", "20", "50"));
  // Not named: the errors say how to name them.
  for (const char* call : {"L6\n", "TC(2)\n"}) {
    try {
      read_with_machine_cycles(std::string("G0 X1\n") + call, {});
      ADD_FAILURE() << call;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--machine-cycle"), std::string::npos) << e.what();
    }
  }
  // CALL, PCALL and EXTCALL of one (a path and an extension are not part of the name).
  auto c = read_with_machine_cycles("CALL \"TC\"\nPCALL TC(3)\nEXTCALL \"/_N_SPF_DIR/tc.spf\"\n", {"TC"});
  ASSERT_EQ(c.size(), 3u);
  for (const Block& x : c) EXPECT_EQ(x.words.not_simulated, "TC");
  EXPECT_THROW(read_with_machine_cycles("CALL \"OTHER\"\n", {"TC"}), InputError);
  // Under G41/G42, as a standard cycle: a reading error.
  EXPECT_THROW(read_with_machine_cycles("G41 T1 D1 X1 Y1\nTC(2)\n", {"TC"}), InputError);
  // The name alone, not a misspelling of it.
  EXPECT_THROW(read_with_machine_cycles("G0 X1\nTC2\n", {"TC"}), InputError);
}

// covers: NC-CYCLE-1 PATH-ACTION-1
TEST(ProgramWords, BothEnginesPassTheReadersNotices) {
  Both r = run_both("G0 X10 Y10 Z5\nCYCLE83(5,0,1,-10)\nG0 X20 Y20 Z50\n");
  ASSERT_EQ(r.fast.notices.size(), 1u);
  ASSERT_EQ(r.ref.notices.size(), 1u);
  EXPECT_EQ(r.fast.notices[0].text, r.ref.notices[0].text);
  EXPECT_EQ(r.fast.path.size(), 2u);
}

}  // namespace
}  // namespace cutcom
