// The words real part programs carry around their contours: headers, actions, dwell, units,
// work offsets, frames (tool tables and names, and cycles: program_tools_cycles_test.cpp).
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
using words_test::error_of;
using words_test::pt;
using words_test::read;

// covers: NC-WORD-1 NC-WORD-2
TEST(ProgramWords, HeadersSkipBlocksMainBlocksAndLabels) {
  auto b = read("%_N_PART_MPF\n;$PATH=/_N_MPF_DIR\n%\n/N10 X1\n/3 N20 X2\n:30 X3\nSTART: N40 X4\nONLY_A_LABEL:\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(*b[0].words.number, 10);
  EXPECT_EQ(b[0].end.x, dec("1"));  // skip levels are off: the block runs
  EXPECT_EQ(*b[1].words.number, 20);
  EXPECT_EQ(*b[2].words.number, 30);
  EXPECT_EQ(*b[3].words.number, 40);
  EXPECT_EQ(b[3].end.x, dec("4"));
}

// covers: NC-WORD-2
TEST(ProgramWords, SkipLevelsSwitchedOnLeaveTheirBlocksOut) {
  // Levels 0 and 3 on: `/` (level 0) and `/3` blocks are not there at all, statements included;
  // `/1` runs. A label on a skipped line stays a jump target: GOTOB BACK finds it (and its block
  // is skipped again).
  std::istringstream in(
      "G0 X0 Y0\n/G0 X10\n/3 R1=5\n/1 G0 Y10\nG0 X=R1+1\n/0 BACK: G0 Y20\nR2=R2+1\n"
      "IF R2<2 GOTOB BACK\nM30\n");
  ProgramReader r(in, {});
  r.set_skip_levels((1u << 0) | (1u << 3));
  std::vector<Block> b;
  for (Block k; r.next(k);) b.push_back(k);
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[1].words.line, 4);  // /1 G0 Y10
  EXPECT_EQ(b[1].end, pt("0", "10", "0"));
  EXPECT_EQ(b[2].end, pt("1", "10", "0"));  // R1 was never set
  EXPECT_EQ(b[3].words.line, 9);            // M30
}

// covers: NC-WORD-3 NC-WORD-5 NC-WORD-6 NC-LEX-5
TEST(ProgramWords, SetUpWordsAreActionsKeptAsWritten) {
  auto b = read(
      "G642 SOFT FFWON CFTCP COMPCAD G601 ADIS=0.5 G96 LIMS=3000\n"
      "S447 M3 M1=4 S1=800 SPOS=DC(90) H2 E5\n"
      "MSG(\"Roughing; first pass\") WORKPIECE(,\"\",,\"BOX\",0,0,-20,-80,0,0,100,100)\n"
      "GROUP_BEGIN(0,\"Contour\",0,0) CYCLE832(0.01,_ORI_ROUGH,1)\nG9 G1 X10 F100\n");
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"G642", "SOFT", "FFWON", "CFTCP", "COMPCAD", "G601", "ADIS=0.5",
                                                     "G96", "LIMS=3000"}));
  EXPECT_EQ(b[0].state.feed_type, FeedType::kG95);  // G96: feed per revolution
  EXPECT_EQ(b[0].state.path_mode, PathMode::kG64);
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"S447", "M3", "M1=4", "S1=800", "SPOS=DC(90)", "H2", "E5"}));
  // Names are read in capitals as the control reads them; quoted text keeps its case.
  auto lower = read("s1200 m3 g642 msg(\"Außen; pass 1\")\n");
  EXPECT_EQ(actions(lower[0]), (std::vector<std::string>{"S1200", "M3", "G642", "MSG(\"Außen; pass 1\")"}));
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"MSG(\"Roughing; first pass\")",
                                                     "WORKPIECE(,\"\",,\"BOX\",0,0,-20,-80,0,0,100,100)"}));
  EXPECT_EQ(actions(b[3]).size(), 2u);
  EXPECT_EQ(actions(b[4]), (std::vector<std::string>{"G9"}));
  EXPECT_FALSE(b[1].moves_in_plane());
  EXPECT_THROW(read("G64 G642\n"), InputError);  // one group, twice
  EXPECT_EQ(actions(read("COMPSURF\nG1 X1 F100\n")[0]), (std::vector<std::string>{"COMPSURF"}));
}

// covers: NC-WORD-7
TEST(ProgramWords, ChannelToleranceAndDynamicsWordsAreActions) {
  auto b = read(
      "WAITM(1,1,2) SETM(3) CLEARM(3) WAITE(2) WAITS SBLOF DISPLOF CP FNORM\n"
      "CTOL=0.01 OTOL=0.1 ACC[X]=50 VELOLIM[Z]=80 JERKLIM[1]=60 SPCON TOWSTD PAROTOF\n"
      "FGROUP(X,Y) SETPIECE(1) WAITS(1,2) SBLON DISPLON G1 X10 F100\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"WAITM(1,1,2)", "SETM(3)", "CLEARM(3)", "WAITE(2)", "WAITS",
                                                     "SBLOF", "DISPLOF", "CP", "FNORM"}));
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"CTOL=0.01", "OTOL=0.1", "ACC[X]=50", "VELOLIM[Z]=80",
                                                     "JERKLIM[1]=60", "SPCON", "TOWSTD", "PAROTOF"}));
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"FGROUP(X,Y)", "SETPIECE(1)", "WAITS(1,2)", "SBLON", "DISPLON"}));
  EXPECT_EQ(b[2].end.x.to_string(), "10");
  // An indexed address word's value may be an expression (NC-PARAM-GRID-1); its index stays.
  auto p = read("R1=5\nACC[ X ]=R1*2 SPOS[1]=DC(R1)\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(actions(p[0]), (std::vector<std::string>{"ACC[X]=10", "SPOS[1]=DC(5)"}));
  // Writes to the PLC interface and synchronized-action variables: actions; reads: errors.
  auto o = read("R1=2\n$A_DBB[3]=1 $A_OUT[2]=R1*2 $AC_MARKER[1]=0\n");
  ASSERT_EQ(o.size(), 1u);
  EXPECT_EQ(actions(o[0]), (std::vector<std::string>{"$A_DBB[3]=1", "$A_OUT[2]=4", "$AC_MARKER[1]=0"}));
  EXPECT_THROW(read("R1=$A_IN[1]\n"), InputError);
  EXPECT_THROW(read("$A_DBB[3]\n"), InputError);
  // The workpiece counters: written as actions; read back once written.
  auto parts = read("$AC_ACTUAL_PARTS=3 $AC_TOTAL_PARTS=7\nR1=$AC_ACTUAL_PARTS+1\n$AC_ACTUAL_PARTS=R1\nG1 X=R1 F100\n");
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(actions(parts[0]), (std::vector<std::string>{"$AC_ACTUAL_PARTS=3", "$AC_TOTAL_PARTS=7"}));
  EXPECT_EQ(actions(parts[1]), (std::vector<std::string>{"$AC_ACTUAL_PARTS=4"}));
  EXPECT_EQ(parts[2].end.x.to_string(), "4");
  EXPECT_THROW(read("R1=$AC_REQUIRED_PARTS\n"), InputError);  // the machine's value, not given
  auto g = read("G26 S3000\nG25 S20\n");
  EXPECT_EQ(actions(g[0]), (std::vector<std::string>{"G26", "S3000"}));
  EXPECT_THROW(read("X1 G26 Y100\n"), InputError);  // the working area's axes come after G26
  EXPECT_THROW(read("ACC[X]\n"), InputError);       // a value needs '='
  EXPECT_THROW(read("WAITM 1\n"), InputError);      // a call needs its arguments in (…)
}

// covers: NC-WORD-7 NC-ERR-3
TEST(ProgramWords, MotionEndRepositioningAndRetractionWordsAreActions) {
  auto b = read(
      "FINEA COARSEA[C] IPOENDA[Z] IPOBRKA(X,100) ADISPOSA(Z,1,0.5) FPR(C) FPRAON(C,S1) FPRAOF\n"
      "ORISON STOPREOF RMB DISPR=2 POLF[X]=10 POLFMASK(X) CORROF(X,\"DRF\") CLGON(10) CLGOF ORISOF\n"
      "WRTPR(\"START\") EXTCLOSE(\"/_N_WKS_DIR/LOG.MPF\") G1 X10 F100\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"FINEA", "COARSEA[C]", "IPOENDA[Z]", "IPOBRKA(X,100)",
                                                     "ADISPOSA(Z,1,0.5)", "FPR(C)", "FPRAON(C,S1)", "FPRAOF"}));
  EXPECT_EQ(actions(b[1]),
            (std::vector<std::string>{"ORISON", "STOPREOF", "RMB", "DISPR=2", "POLF[X]=10", "POLFMASK(X)",
                                      "CORROF(X,\"DRF\")", "CLGON(10)", "CLGOF", "ORISOF"}));
  EXPECT_EQ(b[2].end.x.to_string(), "10");
  EXPECT_THROW(read("FINEA[1]\n"), InputError);  // an axis in the brackets
  // Words that move or switch what cutcom follows: named, not simulated.
  for (const char* text : {"FXS[Z]=1\n", "GEOAX(1,X)\n", "TCA(\"DRILL\",1)\n", "REPOSA\n", "DELDL(1,1)\n",
                           "TRAANG(45)\n", "TRACON(1)\n", "TRACYL(40)\n"})
    EXPECT_NE(error_of(text).find("SINUMERIK NC that cutcom does not simulate ("), std::string::npos) << text;
}

// covers: NC-WORD-7
TEST(ProgramWords, FeedProfileOrientationAndDialectWordsAreActions) {
  auto b = read(
      "FLIN FCUB FENDNORM G62 CPRECON ORIAXES LFON DRFOF\n"
      "OVR=50 FGREF[C]=10 WAITP(Z) BRISKA(X,Y) SOFTA G290 G621 CPRECOF LFOF\n"
      "G1 X10 F100\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(actions(b[0]),
            (std::vector<std::string>{"FLIN", "FCUB", "FENDNORM", "G62", "CPRECON", "ORIAXES", "LFON", "DRFOF"}));
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"OVR=50", "FGREF[C]=10", "WAITP(Z)", "BRISKA(X,Y)", "SOFTA",
                                                     "G290", "G621", "CPRECOF", "LFOF"}));
  EXPECT_EQ(b[2].end.x.to_string(), "10");
  EXPECT_THROW(read("G62 G621\n"), InputError);  // one group
  EXPECT_NE(error_of("G291\n").find("ISO dialect"), std::string::npos) << error_of("G291\n");
}

// covers: NC-WORD-7
TEST(ProgramWords, WorkingAreaTangentialControlAndFileWordsAreActions) {
  auto b = read(
      "WALIMON FL[X]=100 TANG(C,X,Y,1) TANGON(C,0)\nWRITE(R1,\"LOG\",\"A\") CALLPATH(\"/_N_WKS_DIR\")\n"
      "TANGOF(C) WALIMOF\nG1 X10 F100\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"WALIMON", "FL[X]=100", "TANG(C,X,Y,1)", "TANGON(C,0)"}));
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"WRITE(R1,\"LOG\",\"A\")", "CALLPATH(\"/_N_WKS_DIR\")"}));
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"TANGOF(C)", "WALIMOF"}));
  EXPECT_EQ(b[3].end.x.to_string(), "10");
  // G25/G26 with axis words: the working area's limits, no motion; grinding, spline and
  // orientation settings.
  auto w = read(
      "G0 X5 Y5\nR1=100\nG25 X-10 Y=-20 Z-30\nG26 X=R1+2 Z5 WALCS1\nGWPSON(1) TMON DIAMCYCOF ORIC BTAN EAUTO\n"
      "G1 X10 F100\n");
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(actions(w[1]), (std::vector<std::string>{"G25", "X-10", "Y=-20", "Z-30"}));
  EXPECT_EQ(actions(w[2]), (std::vector<std::string>{"G26", "X=102", "Z5", "WALCS1"}));
  EXPECT_FALSE(w[1].moves_in_plane());
  EXPECT_EQ(w[2].end, pt("5", "5", "0"));
  EXPECT_EQ(actions(w[3]), (std::vector<std::string>{"GWPSON(1)", "TMON", "DIAMCYCOF", "ORIC", "BTAN", "EAUTO"}));
  EXPECT_EQ(w[4].start, pt("5", "5", "0"));
  EXPECT_NE(error_of("X1 G26 Y100\n").find("names its axes after G26"), std::string::npos) << error_of("X1 G26 Y100\n");
}

// covers: NC-WORD-12
TEST(ProgramWords, ThreadCuttingAndTappingAreStraightMoves) {
  auto b = read(
      "G18 G0 X20 Z5\nG33 Z-20 K1.5 SF=45\nZ-30 K1.5 DITE=2\nG0 X30\nG17 G0 X50 Y50 Z5\n"
      "G331 Z-10 K1.5 S500\nR1=$P_GG[1]\nG332 Z5 K1.5\nG1 X=R1 F100\n");
  ASSERT_EQ(b.size(), 8u);  // (R1=… alone is no block)
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"G33", "SF=45", "K1.5"}));
  EXPECT_NE(b[1].notice.find("G33: thread cutting"), std::string::npos) << b[1].notice;
  EXPECT_EQ(b[1].state.motion, Motion::kLinear);
  EXPECT_FALSE(b[1].is_arc());
  EXPECT_EQ(b[1].end.z.to_string(), "-20");
  EXPECT_EQ(b[1].end.x.to_string(), "20");
  // Modal: the next block is a thread too, its K a pitch; G0 ends it.
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"DITE=2", "K1.5"}));
  EXPECT_TRUE(b[2].notice.empty()) << b[2].notice;
  EXPECT_EQ(b[3].state.motion, Motion::kRapid);
  EXPECT_NE(b[5].notice.find("G331: tapping"), std::string::npos) << b[5].notice;
  EXPECT_EQ(b[5].end.z.to_string(), "-10");
  EXPECT_EQ(b[7].end.x.to_string(), "11");  // $P_GG[1] read under G331
  // G63 moves its own block in a line; the motion in force before it comes back.
  auto g63 = read("G0 X10 Y10 Z5\nG63 Z-10 F200\nX20\n");
  ASSERT_EQ(g63.size(), 3u);
  EXPECT_EQ(g63[1].state.motion, Motion::kLinear);
  EXPECT_NE(g63[1].notice.find("compensating chuck"), std::string::npos) << g63[1].notice;
  EXPECT_EQ(g63[2].state.motion, Motion::kRapid);
  // After G1 a K is a circle's word again; a thread under compensation is not simulated.
  EXPECT_NE(error_of("G33 Z-5 K1\nG1 Z-10 K1\n").find("without G2/G3"), std::string::npos);
  EXPECT_NE(error_of("$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nG1 G41 X10 F100\nG33 Z-5 K1\n").find("not simulate"),
            std::string::npos);
}

// covers: NC-WORD-10
TEST(ProgramWords, ProgrammedToolLengthOffsetsAreActions) {
  auto b = read("TOFFON(Z,1.5) TOFFL=2 TOFF[X]=0.5\nG1 X10 F100\nTOFFOF() TOFFOF\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"TOFFON(Z,1.5)", "TOFFL=2", "TOFF[X]=0.5"}));
  EXPECT_EQ(b[1].end.x.to_string(), "10");  // the tip stays on the programmed point
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"TOFFOF()", "TOFFOF"}));
  EXPECT_NE(error_of("TOFFR=0.1\n").find("not simulate"), std::string::npos) << error_of("TOFFR=0.1\n");
}

// covers: TOOL-SUM-1 TRC-UNSUP-1
TEST(ProgramWords, SumOffsetsLeaveTheRadiusAlone) {
  const std::string head = "$TC_DP1[1,1]=120 $TC_DP6[1,1]=5\n$TC_SCP13[1,1]=0.2 $TC_ECP23[1,1]=0.1 $TC_SCP16[1,1]=0\n";
  auto b = read(head + "T1 D1 DL=1\nG0 X0 Y0\nDL=2\nD1\n");
  ASSERT_EQ(b.size(), 6u);  // (the two lines of tool data are blocks too)
  EXPECT_EQ(b[2].state.sum_offset, 1);
  EXPECT_EQ(b[2].state.effective_radius(), dec("5"));
  EXPECT_EQ(b[4].state.sum_offset, 2);
  EXPECT_EQ(b[5].state.sum_offset, 0);  // a new D brings MD20272 (0)
  MachineData md;
  md.set("MD20272", "3");
  auto m = read(head + "T1 D1\nD0\nDL=4\n", md.initial_state());
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[2].state.sum_offset, 3);
  EXPECT_EQ(m[3].state.sum_offset, 0);  // D0: no sum offset
  EXPECT_EQ(m[4].state.sum_offset, 0);
  EXPECT_THROW(read("$TC_SCP16[1,1]=0.05\n"), InputError);  // a radius part: not simulated
  EXPECT_THROW(read("$TC_SCP12[1,1]=1\n"), InputError);     // no such parameter
  EXPECT_THROW(read("DL=7\n"), InputError);
  EXPECT_THROW(md.set("MD20272", "7"), MachineDataError);
  // The same path with and without DL; a DL while compensation is active is a D change: refused.
  const std::string contour = "G0 X0 Y0\nG41 G1 X10 F100\nX20\nX20 Y10\nG40 X0 Y20\nM30\n";
  Both with = run_both(head + "T1 D1 DL=1\n" + contour), without = run_both(head + "T1 D1\n" + contour);
  ASSERT_EQ(with.ref.path.size(), 4u);  // approach, two offsets, retraction
  for (const auto& [w, o] : {std::pair{&with.fast, &without.fast}, std::pair{&with.ref, &without.ref}}) {
    ASSERT_EQ(w->path.size(), o->path.size());
    for (std::size_t k = 0; k < w->path.size(); ++k) {
      EXPECT_EQ(w->path[k].start.x, o->path[k].start.x);
      EXPECT_EQ(w->path[k].end.y, o->path[k].end.y);
    }
  }
  EXPECT_EQ(with.ref.path[1].start.y, 5);  // offset by the radius of $TC_DP6 alone
  EXPECT_THROW(run_both(head + "T1 D1\nG0 X0 Y0\nG41 G1 X10 F100\nX20 DL=1\nX20 Y10\nG40 X0 Y20\nM30\n"),
               UnsupportedError);
}

// covers: NC-WORD-11
TEST(ProgramWords, UnderTraoriTheToolTipFollowsTheProgram) {
  auto b = read(
      "TRAORI(1)\nG0 X0 Y0 Z5 A0 C0\nG1 X10 Y5 A30 C10 F100\nX20 A3=0 B3=0.5 C3=1\nLEAD=10 TILT=0\n"
      "G41 T1 D1 X30\nC20\nG40 X40\nTRAFOOF\n");
  ASSERT_EQ(b.size(), 9u);
  EXPECT_EQ(actions(b[0]), (std::vector<std::string>{"TRAORI(1)"}));
  EXPECT_EQ(b[2].end, pt("10", "5", "5"));
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"A30", "C10"}));
  EXPECT_EQ(b[2].notice_clause, "NC-WORD-11");
  EXPECT_EQ(actions(b[3]), (std::vector<std::string>{"A3=0", "B3=0.5", "C3=1"}));
  EXPECT_EQ(b[3].end.x.to_string(), "20");
  EXPECT_FALSE(b[6].moves_in_plane());  // an orientation change between compensated blocks
  EXPECT_EQ(actions(b[8]), (std::vector<std::string>{"TRAFOOF"}));
  // Tilting along a compensated contour, TRAORI under compensation, orientation without TRAORI,
  // and simultaneous rotary motion after TRAFOOF: errors.
  EXPECT_THROW(read("TRAORI\nG41 T1 D1 G1 X10 F100\nX20 A3=1\n"), InputError);
  EXPECT_THROW(read("G41 T1 D1 G1 X10 F100\nTRAORI\n"), InputError);
  EXPECT_THROW(read("G1 X10 A3=1 F100\n"), InputError);
  EXPECT_THROW(read("$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nTRAORI\nTRAFOOF\nG1 G41 X10 A30 F100\n"), InputError);
}

// covers: NC-WORD-8 NC-ERR-3
TEST(ProgramWords, RotaryAxesPositionAsActions) {
  auto b = read("R1=45\nG0 X0 Y0\nA90 C=ACP(R1)\nB=IC(-5) POS[A]=0 POSA[C]=R1*2 FA[A]=1000\nG1 X10 F100\n");
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"A90", "C=ACP(45)"}));
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"B=IC(-5)", "POS[A]=0", "POSA[C]=90", "FA[A]=1000"}));
  EXPECT_FALSE(b[1].moves_in_plane());
  EXPECT_EQ(b[3].end.x.to_string(), "10");
  // With X, Y or Z in a rapid move without compensation: positioned during it (a 3+2 set-up), noted.
  auto rapid = read("G0 X0 Y0 Z10 A0 C=ACP(30)\nG1 X5 F100\n");
  ASSERT_EQ(rapid.size(), 2u);
  EXPECT_EQ(actions(rapid[0]), (std::vector<std::string>{"A0", "C=ACP(30)"}));
  EXPECT_EQ(rapid[0].end.z.to_string(), "10");
  EXPECT_NE(rapid[0].notice.find("positions during this rapid move"), std::string::npos) << rapid[0].notice;
  // In G1/G2/G3 without compensation X, Y, Z move as programmed while the axis turns, noted.
  auto turning = read("G0 X0 Y0 Z0\nG1 X10 A30 F100\nG3 C=IC(90) X0 Y10 CR=10\nTRANS X5 B10\n");
  ASSERT_EQ(turning.size(), 4u);
  EXPECT_EQ(actions(turning[1]), (std::vector<std::string>{"A30"}));
  EXPECT_EQ(turning[1].end.x.to_string(), "10");
  EXPECT_EQ(turning[2].state.motion, Motion::kArcCcw);
  EXPECT_EQ(actions(turning[2]), (std::vector<std::string>{"C=IC(90)"}));
  for (int k : {1, 2})
    EXPECT_NE(turning[k].notice.find("turns while X, Y and Z move"), std::string::npos) << turning[k].notice;
  EXPECT_NE(turning[3].notice.find("the frame's value for the rotary axis B"), std::string::npos) << turning[3].notice;
  // With compensation (4/5-axis motion along a compensated contour), or POS of a plane axis: not simulated.
  for (const char* bad : {"$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nG1 G41 X10 A30 F100\n", "POS[X]=10\n",
                          "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nG0 G41 X10 A30\n",
                          "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1\nT1 D1\nG1 G41 X10 F100\nA30 Y5\n"}) {
    try {
      read(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("not simulate"), std::string::npos) << e.what();
    }
  }
  auto orientation = read("ORIRESET(0, 90)\nG1 X5 F100\n");
  EXPECT_EQ(actions(orientation[0]), (std::vector<std::string>{"ORIRESET(0, 90)"}));
  // Interrupts, coupled motion, measuring, frame rotations, tool holders: named with their family.
  for (const char* w :
       {"SETINT(1) PRIO=1 ABHEB\n", "TRAILON(Y,X)\n", "MEAS=1 G1 X10\n", "TOROT\n", "PAROT\n", "TCARR=1 TCOFR\n"}) {
    try {
      read(w);
      ADD_FAILURE() << "accepted: " << w;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is SINUMERIK NC that cutcom does not simulate ("), std::string::npos)
          << e.what();
    }
  }
}

// covers: NC-WORD-9
TEST(ProgramWords, SynchronizedActionsAreActionsUnlessTheyMoveThePath) {
  auto b = read(
      "G1 X0 Y0 F100\nN5 WHEN $AA_IW[X]>10 DO $A_OUT[1]=1 M7 ; coolant\n"
      "ID=1 WHENEVER $AA_IW[Z]<-5 DO $AA_OVR[X]=50 POS[A]=90\nR1=2\nG1 X=R1\nCANCEL(1)\nDO $R2=1\n");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"WHEN $AA_IW[X]>10 DO $A_OUT[1]=1 M7"}));
  EXPECT_NE(b[1].notice.find("synchronized action"), std::string::npos) << b[1].notice;
  EXPECT_EQ(actions(b[2]), (std::vector<std::string>{"ID=1 WHENEVER $AA_IW[Z]<-5 DO $AA_OVR[X]=50 POS[A]=90"}));
  EXPECT_EQ(b[3].end.x.to_string(), "2");
  EXPECT_EQ(actions(b[4]), (std::vector<std::string>{"CANCEL(1)"}));
  EXPECT_EQ(actions(b[5]), (std::vector<std::string>{"DO $R2=1"}));
  // One that moves a plane axis, offsets the path or deletes the distance to go: not simulated.
  for (const char* bad : {"WHEN $AA_IW[X]>5 DO POS[Y]=3 FA[Y]=100\n", "ID=2 WHENEVER TRUE DO $AA_OFF[X]=0.1\n",
                          "WHEN $A_IN[1]==1 DO DELDTG\n", "WHEN $A_IN[1]==1\n"}) {
    try {
      read(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 1) << bad;
    }
  }
}

// covers: NC-PARAM-FLOW-7
TEST(ProgramWords, GotosEndsTheRunAfterOnePass) {
  for (const char* program : {"G1 X1 F100\nGOTOS\nM30\n", "G1 X1 F100\nIF 1 GOTOS\nG1 X9\nM30\n"}) {
    auto b = read(program);
    ASSERT_EQ(b.size(), 2u) << program;
    EXPECT_TRUE(b[1].words.program_end);
    EXPECT_NE(b[1].notice.find("one pass"), std::string::npos) << b[1].notice;
  }
  auto not_taken = read("G1 X1 F100\nIF 0 GOTOS\nG1 X9\nM30\n");
  ASSERT_EQ(not_taken.size(), 3u);
  EXPECT_EQ(not_taken[1].end.x.to_string(), "9");
}

// covers: NC-WORD-4
TEST(ProgramWords, DwellTakesItsFAsTimeNotFeed) {
  auto b = read("G1 X10 F300\nG4 F2\nX20\n");
  EXPECT_EQ(actions(b[1]), (std::vector<std::string>{"G4 F2"}));
  EXPECT_EQ(b[1].state.feed, dec("300"));
  EXPECT_EQ(b[2].state.feed, dec("300"));
  EXPECT_THROW(read("G4 F2 X10\n"), InputError);
  // S in a G4 block counts spindle revolutions: part of the dwell, not a speed of its own.
  auto c = read("S1000 M3\nG4 S10\nM5 G4 S=2.5\n");
  EXPECT_EQ(actions(c[0]), (std::vector<std::string>{"S1000", "M3"}));
  EXPECT_EQ(actions(c[1]), (std::vector<std::string>{"G4 S10"}));
  EXPECT_EQ(actions(c[2]), (std::vector<std::string>{"M5", "G4 S=2.5"}));
}

// covers: NC-UNIT-1 NC-UNIT-2
TEST(ProgramWords, InchIsConvertedOntoTheGrid) {
  auto b = read("G70 X1 Y0.5 F10\nG700 X2 F10\nG71 X10\nG70 G91 X0.000000001\n");
  EXPECT_EQ(b[0].end.x, dec("25.4"));
  EXPECT_EQ(b[0].end.y, dec("12.7"));
  EXPECT_EQ(b[0].state.feed, dec("10"));  // G70: the feed stays in the basic system
  EXPECT_EQ(b[1].end.x, dec("50.8"));
  EXPECT_EQ(b[1].state.feed, dec("254"));  // G700: the feed too
  EXPECT_EQ(b[2].end.x, dec("10"));
  EXPECT_EQ(b[3].end.x, dec("10.000000025"));  // 0.0000000254 mm rounded to the grid
  auto c = read("G70 G2 X2 Y0 CR=1\n");
  EXPECT_EQ(*c[0].words.cr, dec("25.4"));
  EXPECT_EQ(Decimal(dec("-0.0000000005")).scaled(1, 1), dec("-0.0000000005").scaled(1, 1));
  EXPECT_EQ(dec("0.000000003").scaled(1, 2), dec("0.000000002"));    // 1.5 units: half away from zero
  EXPECT_EQ(dec("-0.000000003").scaled(1, 2), dec("-0.000000002"));  // symmetric
}

// covers: NC-DIAM-1
TEST(ProgramWords, DiameterProgramming) {
  auto b =
      read("G18 DIAMON X40 Z0\nG91 X-10\nG90 DIAM90 X30\nG91 X2\nG90 DIAMOF X30\nDIAMON G3 X20 Z-5 I=AC(10) K-5\n");
  EXPECT_EQ(b[0].end.x, dec("20"));
  EXPECT_EQ(b[1].end.x, dec("15"));  // incremental diameter: half of it
  EXPECT_EQ(b[2].end.x, dec("15"));
  EXPECT_EQ(b[3].end.x, dec("17"));  // DIAM90: incremental values are radii
  EXPECT_EQ(b[4].end.x, dec("30"));
  EXPECT_EQ(b[5].end.x, dec("10"));
  EXPECT_EQ(b[5].centre->x, dec("5"));
}

// covers: NC-OFFSET-1 NC-OFFSET-2
TEST(ProgramWords, SettableOffsetsRelativeToTheFirst) {
  OffsetTable t;
  std::istringstream file(
      "%_N_UFR_INI\nCHANDATA(1)\n$P_UIFR[1]=CTRANS(X,100,Y,50,Z,-20)\n$P_UIFR[2,X,TR]=300\n$P_UIFR[2,Y,TR]=50\n"
      "$P_UIFR[2,X,FI]=0.5\n$P_UIFR[2,Z,RT]=0\nM17\n");
  t.load(file, "UFR.INI");
  auto b = read("G54 G0 X10 Y10\nG55 X10\nY10\nG500 X0 Y0\n", {}, &t);
  EXPECT_EQ(b[0].end, pt("10", "10", "0"));  // the output is in G54's workpiece system
  EXPECT_EQ(b[0].notice_clause, "NC-OFFSET-1");
  EXPECT_EQ(b[1].end, pt("210.5", "10", "0"));  // only the programmed axis moves into G55
  EXPECT_EQ(b[2].end, pt("210.5", "10", "0"));
  EXPECT_EQ(b[3].end, pt("-100", "-50", "0"));
  std::istringstream rotated("$P_UIFR[1,Z,RT]=30\n");
  try {
    OffsetTable u;
    u.load(rotated, "UFR.INI");
    ADD_FAILURE() << "a rotation was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("UFR.INI: a rotation"), std::string::npos) << e.what();
  }
}

// covers: NC-OFFSET-2
TEST(ProgramWords, SettableOffsetsAsTheControlArchivesThem) {
  // Every frame whole, joined by ':', G500's frame at zero, the rotary axis A listed with the
  // geometry axes, a fine offset adding to the coarse one.
  OffsetTable t;
  std::istringstream file(
      "%_N_UFR_INI\nCHANDATA(1)\n"
      "$P_UIFR[0]=CTRANS(X,0,Y,0,Z,0,A,0):CROT(X,0,Y,0,Z,0):CMIRROR():CSCALE(X,1,Y,1,Z,1,A,1)\n"
      "$P_UIFR[1]=CTRANS(X,100,Y,50,Z,-20,A,90,C1,0,SP1,0):CFINE(X,0.25,Y,0,Z,0):CROT(Z,0):CMIRROR():CSCALE(X,1,Y,1,Z,"
      "1)\n"
      "$P_UIFR[2,A,TR]=45\n$P_UIFR[2,X,TR]=300\nM17\n");
  t.load(file, "UFR.INI");
  EXPECT_EQ(t.translation(1), pt("100.25", "50", "-20"));
  EXPECT_EQ(t.translation(2), pt("300", "0", "0"));
  EXPECT_EQ(t.translation(0), pt("0", "0", "0"));
  auto b = read("G54 G0 X10 Y10\nG55 X10\n", {}, &t);
  EXPECT_EQ(b[1].end, pt("209.75", "10", "0"));
  // What the control would do otherwise is not simulated: a rotation, a mirror, a scale, a G500
  // frame other than zero; each an error naming the file, line and column.
  const std::pair<const char*, const char*> refused[] = {
      {"$P_UIFR[1]=CTRANS(X,1):CROT(Z,30)\n", "a rotation"},
      {"$P_UIFR[1]=CTRANS(X,1):CMIRROR(X)\n", "a mirror"},
      {"$P_UIFR[1]=CTRANS(X,1):CSCALE(X,2)\n", "a scale"},
      {"$P_UIFR[0]=CTRANS(X,5)\n", "G500 selects, other than zero"},
      {"$P_UIFR[0,Y,TR]=5\n", "G500 selects, other than zero"},
      {"$P_UIFR[1]=CTRANS(X,1):CSHIFT(X,1)\n", "'CSHIFT': a settable offset is CTRANS"},
  };
  for (const auto& [text, want] : refused) {
    std::istringstream in(text);
    try {
      OffsetTable u;
      u.load(in, "UFR.INI");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 1);
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << text << " -> " << e.what();
    }
  }
}

// covers: NC-FRAME-1 NC-FRAME-2
TEST(ProgramWords, TranslationScaleAndMirrorFrames) {
  auto b = read(
      "TRANS X10 Y20\nG1 X5 Y5\nATRANS X1\nX0\nSCALE X2 Y2\nX3 Y1\nG91 X1\nG90 TRANS\nX3 Y1\nMIRROR X0\nX3\n"
      "AMIRROR X0\nX3\nMIRROR X0\nATRANS X10\nX3\n");
  EXPECT_EQ(b[1].end, pt("15", "25", "0"));
  EXPECT_FALSE(b[0].moves_in_plane());  // the frame block moves nothing
  EXPECT_EQ(b[3].end, pt("11", "25", "0"));
  EXPECT_EQ(b[5].end, pt("6", "2", "0"));  // SCALE replaces the translation
  EXPECT_EQ(b[6].end, pt("8", "2", "0"));  // incremental values are scaled too
  EXPECT_EQ(b[8].end, pt("3", "1", "0"));
  EXPECT_EQ(b[10].end.x, dec("-3"));
  EXPECT_EQ(b[12].end.x, dec("3"));                                 // mirrored twice
  EXPECT_EQ(b[15].end.x, dec("-13"));                               // ATRANS acts in the mirrored system
  EXPECT_THROW(read("SCALE X2 Y3\nG2 X10 Y0 CR=5\n"), InputError);  // an ellipse
  EXPECT_THROW(read("TRANS X10 G1 Y5\n"), InputError);
  EXPECT_THROW(read("G41 T1 D1\nTRANS X10\n"), InputError);
  // An accumulated frame beyond the range of values is a reading error at its block, never a crash.
  std::string grown;
  for (int i = 0; i < 12; ++i) grown += "ASCALE X1000 Y1000\n";
  for (const std::string& p : {grown, std::string("SCALE X1000\nASCALE X1000\nASCALE X1000\nATRANS X900000000\n")}) {
    try {
      read(p);
      ADD_FAILURE() << "no error for " << p;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the frame is out of range"), std::string::npos) << e.what();
    }
  }
  // And one shrunk below the grid (reader_fuzz: ASCALE Y0.49 in a subprogram called 280 times):
  // a factor of 0 would divide the positions by 0.
  std::string shrunk = "G0 X1 Y1\n";
  for (int i = 0; i < 30; ++i) shrunk += "ASCALE Y0.49\nY.9\n";
  try {
    read(shrunk);
    ADD_FAILURE() << "no error for a scale factor shrunk to 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Y: the scale factors together come to less than 1e-9"), std::string::npos)
        << e.what();
  }
}

// covers: NC-FRAME-3
TEST(ProgramWords, MirroringSwapsCircleSenseAndSide) {
  auto b = read(
      "MIRROR X0\nG1 G41 X10 Y0\nG2 X0 Y10 CR=10\nG1 G40 X0 Y20\nMIRROR Y0 Z0\nG2 X0 Y10 CR=10\nMIRROR X0 Y0\n"
      "G3 X1 Y1 CR=5\n");
  EXPECT_EQ(b[1].state.side, Side::kRight);
  EXPECT_EQ(b[2].state.motion, Motion::kArcCcw);
  EXPECT_EQ(b[5].state.motion, Motion::kArcCcw);  // Y mirrored (Z is not a plane axis)
  EXPECT_EQ(b[7].state.motion, Motion::kArcCcw);  // both plane axes: a rotation, no swap
}

// covers: NC-FRAME-3 TRC-RADIUS-2
TEST(ProgramWords, AMirroredFrameEqualsTheMirroredProgram) {
  const char* tools = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n";
  std::string framed = std::string(tools) +
                       "T1 D1\nMIRROR X0\nG0 X-10 Y-5\nG1 G41 X0 Y0 F100\nX20\nG2 X30 Y10 CR=10\nG1 Y20\nG40 X40 Y30\n";
  std::string mirrored =
      std::string(tools) + "T1 D1\nG0 X10 Y-5\nG1 G42 X0 Y0 F100\nX-20\nG3 X-30 Y10 CR=10\nG1 Y20\nG40 X-40 Y30\n";
  Both a = run_both(framed), b = run_both(mirrored);
  ASSERT_EQ(a.ref.path.size(), b.ref.path.size());
  for (std::size_t i = 0; i < a.ref.path.size(); ++i) {
    EXPECT_EQ(a.ref.path[i].end.x, b.ref.path[i].end.x) << i;
    EXPECT_EQ(a.ref.path[i].end.y, b.ref.path[i].end.y) << i;
    EXPECT_NEAR(a.fast.path[i].end.x, a.ref.path[i].end.x, 1e-9) << i;
    EXPECT_NEAR(a.fast.path[i].end.y, a.ref.path[i].end.y, 1e-9) << i;
  }
}

}  // namespace
}  // namespace cutcom
