// Parametric programs (spec nc-parametric.md): expressions evaluated by hand in the comments, and
// parametric programs that must give exactly the path of the plain program written out by hand.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cutcom/interpreter.hpp"
#include "parametric_support.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

double value(const std::string& expression) {
  std::istringstream none;
  Interpreter in(none);
  return in.evaluate(expression).number;
}

// covers: NC-PARAM-EXPR-1 NC-PARAM-EXPR-2 NC-PARAM-EXPR-3 NC-PARAM-VAR-1
TEST(Parametric, ExpressionsFollowTheManualsPriorities) {
  EXPECT_EQ(value("2+3*4"), 14);
  EXPECT_EQ(value("(2+3)*4"), 20);
  EXPECT_EQ(value("-2*3+1"), -5);
  EXPECT_EQ(value("7 DIV 2"), 3);
  EXPECT_EQ(value("7 MOD 4"), 3);
  EXPECT_EQ(value("7/2"), 3.5);
  // Comparisons have the lowest priority: 1 == (1 AND 0) is FALSE; (1==1) AND 0 too.
  EXPECT_EQ(value("1 == 1 AND 0"), 0);
  EXPECT_EQ(value("(1 == 1) AND (2 > 1)"), 1);
  EXPECT_EQ(value("NOT 0 OR 0"), 1);
  EXPECT_EQ(value("5 B_AND 3"), 1);
  EXPECT_EQ(value("5 B_OR 3"), 7);
  EXPECT_EQ(value("5 B_XOR 3"), 6);
  EXPECT_NEAR(value("SIN(30)"), 0.5, 1e-15);
  EXPECT_NEAR(value("COS(60)+TAN(45)"), 1.5, 1e-15);
  EXPECT_NEAR(value("ATAN2(1,1)"), 45, 1e-13);
  EXPECT_NEAR(value("ACOS(0)+ASIN(1)"), 180, 1e-13);
  EXPECT_EQ(value("SQRT(16)+ABS(-2)+POT(3)"), 15);
  EXPECT_EQ(value("TRUNC(-2.7)+ROUND(2.5)+ROUNDUP(1.2)"), -2 + 3 + 2);
  EXPECT_EQ(value("MINVAL(3,4)+MAXVAL(3,4)+BOUND(0,10,12)"), 17);
  EXPECT_NEAR(value("LN(EXP(2))"), 2, 1e-15);
  EXPECT_EQ(value("10EX-1*2"), 2);  // 10 * 10^-1 * 2
  // Relative equality: 0.1 + 0.2 is 0.30000000000000004 in binary64.
  EXPECT_EQ(value("0.1+0.2 == 0.3"), 1);
  EXPECT_EQ(value("0.1+0.2 > 0.3"), 0);
  EXPECT_EQ(value("R7 + R[3+4]"), 0);  // unset R parameters are 0
  std::istringstream none;
  Interpreter in(none);
  EXPECT_EQ(in.evaluate("\"AB\" << 12").text, "AB12");
  EXPECT_EQ(in.evaluate("\"AB\" == \"AB\"").number, 1);
}

// covers: NC-PARAM-ERR-1 NC-PARAM-EXPR-2
TEST(Parametric, ExpressionErrorsNameTheirColumn) {
  auto column = [](const std::string& e) {
    std::istringstream none;
    Interpreter in(none);
    try {
      in.evaluate(e, 7);
    } catch (const InputError& x) {
      EXPECT_EQ(x.line(), 7);
      return x.column();
    }
    ADD_FAILURE() << e << " was evaluated";
    return 0;
  };
  EXPECT_EQ(column("1/0"), 2);
  EXPECT_EQ(column("2+SQRT(-1)"), 3);
  EXPECT_EQ(column("3*XYZ"), 3);          // undefined variable
  EXPECT_EQ(column("FOO(1)"), 1);         // unknown function
  EXPECT_EQ(column("$P_WHATEVER+1"), 1);  // unknown system variable
  EXPECT_EQ(column("1+\"A\""), 2);        // a string where a number is needed
  EXPECT_EQ(column("(1+2"), 5);
}

// The end point of the last block moving, read as written by the interpreter.
// covers: NC-PARAM-GRID-1 NC-PARAM-VAR-2 NC-PARAM-TYPE-1 NC-WORD-3
TEST(Parametric, ComputedValuesBecomeNinePlaceDecimals) {
  EXPECT_EQ(end_x("R1=1/3\nG1 X=R1 F100\n"), "0.333333333");
  EXPECT_EQ(end_x("R1=2/3\nG1 X=R1 F100\n"), "0.666666667");
  EXPECT_EQ(end_x("G1 X=10.123456789 F100\n"), "10.123456789");  // a literal stays as written
  EXPECT_EQ(end_x("DEF INT KK=2.5\nG1 X=KK F100\n"), "3");       // INT rounds halves away from 0
  EXPECT_EQ(end_x("DEF INT KK=-2.5\nG1 X=KK F100\n"), "-3");
  EXPECT_EQ(end_x("DEF REAL AA[3]=SET(1,2,3)\nG1 X=AA[2]*AA[1] F100\n"), "6");
  EXPECT_EQ(end_x("DEF REAL BB[2,2]\nBB[1,0]=7\nG1 X=AC(BB[1,0]-0.5) F100\n"), "6.5");
  EXPECT_EQ(end_x("G91 G1 X5 F100\nR2=1.25\nX=IC(R2*2)\n"), "7.5");
  // M=QU(…): the auxiliary function itself (NC-WORD-3).
  EXPECT_EQ(first_block_actions("R1=4\nG1 X=R1 M=QU(8) H=QU(R1*2) F100\n"), (std::vector<std::string>{"M8", "H8"}));
  // AX[...]: the axis named by an AXIS variable, or written out.
  EXPECT_EQ(end_x("DEF AXIS AA=X\nG1 AX[AA]=4*2 F100\n"), "8");
  EXPECT_EQ(end_x("G1 AX[X]=3 F100\n"), "3");
  EXPECT_EQ(error_line("DEF REAL BB=1\nG1 AX[BB]=3 F100\n", "AX[...]: an axis name or an AXIS variable is expected"),
            2);
}

// INT is 32 bits: a value beyond it is an error where an INT is needed, and a REAL elsewhere. The
// fuzzer's first findings under -fno-sanitize-recover (undefined conversions) are the last lines.
// covers: NC-PARAM-TYPE-1 NC-PARAM-SYS-1
TEST(Parametric, IntHoldsThirtyTwoBitsAndBeyondItIsAnError) {
  EXPECT_EQ(end_x("DEF INT KK=2147483647\nG1 X=KK F100\n"), "2147483647");
  EXPECT_EQ(end_x("DEF INT KK=-2147483648\nG1 X=KK F100\n"), "-2147483648");
  const std::string range = "outside the range of INT (-2147483648 to 2147483647)";
  EXPECT_EQ(error_line("DEF INT KK\nKK=2147483647.5\n", range), 2);  // rounds to 2^31
  EXPECT_EQ(error_line("DEF INT KK=2147483647\nKK=KK+1\nG1 X1 F100\n", range), 2);
  EXPECT_EQ(error_line("R1=3000000000 B_AND 1\n", range), 1);
  EXPECT_EQ(error_line("R1=B_NOT 1EX12\n", range), 1);
  // Whole results beyond INT are REAL and stay exact where binary64 holds them.
  EXPECT_EQ(end_x("R1=2147483647*2\nG1 X=R1/1000 F100\n"), "4294967.294");
  EXPECT_EQ(end_x("R1=9000000000000 DIV 1000\nG1 X=R1 F100\n"), "9000000000");
  // A constant of 20 digits is a REAL, written as one by <<.
  std::istringstream none;
  Interpreter in(none);
  EXPECT_EQ(in.evaluate("66666666666666666666").type, NcValue::Type::kReal);
  EXPECT_EQ(in.evaluate("\"A\"<<2147483647").text, "A2147483647");
  // A group number or a parameter number of many digits names nothing (no overflow on the way).
  EXPECT_EQ(error_line("R1=$P_GG[49333333333]\n", "$P_GG"), 1);
  EXPECT_EQ(error_line("$TC_DP1[1,1]=120\nR1=$TC_DP36892191099[1,1]\n", "$TC_DP36892191099"), 2);
}

// covers: NC-PARAM-FLOW-1 NC-PARAM-FLOW-2 NC-PARAM-FLOW-3 NC-PARAM-FLOW-4 NC-PARAM-SYS-1 NC-PARAM-VAR-1 NC-PARAM-VAR-2
TEST(Parametric, ParametricProgramGivesThePlainProgramsPath) {
  // A staircase of three steps (FOR), two bumps (WHILE), a branch on the tool radius (IF/ELSE),
  // a counted GOTOB loop and a forward jump over a block; each step written out below.
  const std::string parametric =
      "DEF REAL STEP=2.5, WIDTH\n"
      "DEF INT KK, PASS\n"
      "$TC_DP1[1,1]=120\n"
      "R5=4\n"
      "$TC_DP6[1,1]=R5/2\n"
      "N10 G0 X-10 Y0 T1 D1\n"
      "WIDTH=$P_TOOLR*5\n"           // 2 * 5 = 10
      "N20 G1 G41 X0 Y0 F=R5*100\n"  // F400
      "FOR KK=1 TO 3\n"
      "  X=KK*WIDTH-5\n"  // 5, 15, 25
      "  Y=KK*STEP\n"     // 2.5, 5, 7.5
      "ENDFOR\n"
      "WHILE PASS<2\n"
      "  PASS=PASS+1\n"
      "  G3 X=AC(25+PASS*10) Y=7.5 CR=5\n"  // 35, 45
      "ENDWHILE\n"
      "IF $TC_DP6[1,1] > 3\n"
      "  G1 Y=100\n"
      "ELSE\n"
      "  G1 Y=20\n"
      "ENDIF\n"
      "R10=0\n"
      "AGAIN: R10=R10+1\n"
      "G1 X=45+R10*5\n"  // 50, 55
      "IF R10<2 GOTOB AGAIN\n"
      "GOTOF N90\n"
      "G1 X999\n"
      "N90 G1 G40 X80 Y40\n"
      "M30\n";
  const std::string plain =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F400\n"
      "X5\nY2.5\nX15\nY5\nX25\nY7.5\n"
      "G3 X35 Y7.5 CR=5\nG3 X45 Y7.5 CR=5\n"
      "G1 Y20\nG1 X50\nG1 X55\nN90 G1 G40 X80 Y40\nM30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && p.ref_ok && q.fast_ok && q.ref_ok);
  EXPECT_TRUE(q.fast.alarms.empty());
  EXPECT_GT(q.fast.path.size(), 10u);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
}

// Loop passes and backward jumps read their lines from the line cache; without it (or past its
// budget) they are read from the file again: the same blocks either way.
// covers: NC-PARAM-FLOW-3 NC-PARAM-FLOW-1
TEST(Parametric, LinesReadAgainFromMemoryOrFromTheFileAlike) {
  const std::string program =
      "DEF INT KK\nR1=0\nN10 G1 X0 Y0 F100\nWHILE KK<3\n  KK=KK+1\n  G1 X=KK*10\n  Y=KK\nENDWHILE\n"
      "AGAIN: R1=R1+1\nG1 Y=R1*5\nIF R1<4 GOTOB AGAIN\nFOR KK=1 TO 2\n  X=-KK\nENDFOR\nM30\n";
  auto blocks = [&](std::size_t cache) {
    std::istringstream in(program);
    ProgramReader reader(in);
    InterpreterLimits limits;
    limits.line_cache_bytes = cache;
    reader.set_limits(limits);
    std::vector<std::string> ends;
    Block b;
    while (reader.next(b))
      ends.push_back(std::to_string(b.words.line) + ":" + b.end.x.to_string() + "," + b.end.y.to_string());
    return ends;
  };
  std::vector<std::string> cached = blocks(InterpreterLimits{}.line_cache_bytes), read_again = blocks(0),
                           part = blocks(40);
  EXPECT_EQ(cached.size(), 14u);  // N10, 3 x 2 in WHILE, 4 by GOTOB, 2 in FOR, M30
  EXPECT_EQ(cached, read_again);
  EXPECT_EQ(cached, part);
}

// covers: NC-PARAM-FLOW-3 NC-PARAM-FLOW-1
TEST(Parametric, LoopRepeatAndLabelsAfterTheEnd) {
  // LOOP left by a jump; REPEAT … UNTIL; M30 ends the run although an error handler follows.
  const std::string parametric =
      "R1=0\nLOOP\n  R1=R1+1\n  G1 X=R1 F100\n  IF R1>=3 GOTOF OUT\nENDLOOP\n"
      "OUT: R2=0\nREPEAT\n  R2=R2+2\n  G1 Y=R2\nUNTIL R2>=4\nM30\nERR: G1 X999\nM30\n";
  const std::string plain = "G1 X1 F100\nX2\nX3\nY2\nY4\nM30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && q.fast_ok);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
}

// covers: NC-PARAM-FLOW-1 NC-PARAM-FLOW-2 NC-PARAM-FLOW-3
TEST(Parametric, JumpsOutOfStructures) {
  // A GOTOB out of an IF branch (a depth loop written with a jump), a GOTOF out of a WHILE and of
  // an IF inside a FOR: the structures left end there, nothing is left open at the end.
  const std::string parametric =
      "R1=0\n"
      "N10 G1 X=R1*10 F100\n"
      "R1=R1+1\n"
      "IF R1<3\n"
      "  G1 Y=R1\n"
      "  GOTOB N10\n"
      "ENDIF\n"
      "WHILE 1\n"
      "  G1 Y=-R1\n"
      "  IF R1>=3 GOTOF OUT\n"
      "ENDWHILE\n"
      "OUT: FOR R2=1 TO 5\n"
      "  IF R2==2\n"
      "    GOTOF DONE\n"
      "  ENDIF\n"
      "  G1 X=R2\n"
      "ENDFOR\n"
      "DONE: G1 Y0\n"
      "M30\n";
  const std::string plain = "G1 X0 F100\nY1\nX10\nY2\nX20\nY-3\nX1\nY0\nM30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && p.ref_ok && q.fast_ok && q.ref_ok);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
}

// covers: NC-PARAM-FLOW-5
TEST(Parametric, SectionRepetitionsAndCase) {
  // REPEAT START P=2 runs START…N30 twice more; REPEATB N30 P=2 runs N30 twice; CASE picks by
  // value (CNT is 3 here), then DEFAULT on a value not listed; REPEAT FROM ENDLABEL runs the
  // section between the two labels once more.
  const std::string parametric =
      "DEF INT CNT=0\n"
      "N10 G0 X0 Y0\n"
      "START: G1 X10 F100\n"
      "CNT=CNT+1\n"
      "N20 G1 Y=10*CNT\n"
      "N30 X=-CNT\n"
      "N40 REPEAT START P=2\n"
      "N50 REPEATB N30 P=2\n"
      "CASE (CNT) OF 1 GOTOF ONE 3 GOTOF THREE DEFAULT GOTOF OTHER\n"
      "ONE: G1 X1\n"
      "THREE: G1 X3\n"
      "CASE (CNT+4) OF 1 GOTOF ONE DEFAULT GOTOF OTHER\n"
      "G1 X98\n"
      "OTHER: G1 X7\n"
      "GOTOF AFTER\n"
      "FROM: G1 Y1\n"
      "G1 Y2\n"
      "ENDLABEL: G1 Y3\n"
      "AFTER: REPEAT FROM ENDLABEL P=1\n"
      "G1 X0\n"
      "M30\n";
  const std::string plain =
      "N10 G0 X0 Y0\nG1 X10 F100\nY10\nX-1\n"
      "X10\nY20\nX-2\nX10\nY30\nX-3\n"
      "X-3\nX-3\n"
      "X3\nX7\n"
      "Y1\nY2\nY3\nX0\nM30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && p.ref_ok && q.fast_ok && q.ref_ok);
  EXPECT_GT(q.fast.path.size(), 14u);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
}

// covers: NC-PARAM-SYS-1
TEST(Parametric, GGroupsReadTheModalState) {
  EXPECT_EQ(end_x("G18\nR1=$P_GG[6]\nG17 G1 X=R1 F100\n"), "2");
  EXPECT_EQ(end_x("G91 G451 CDON\nG90 G1 X=$P_GG[18]*10+$P_GG[40] F100\n"), "22");
  EXPECT_EQ(end_x("G55 G2 X0 Y0 I1\nG1 X=$P_GG[8]*10+$P_GG[1] F100\n"), "33");
  EXPECT_EQ(end_x("KONT\nG1 X=$P_GG[17]+$P_GG[14]/10 F100\n"), "2.1");
  EXPECT_EQ(end_x("G1 KONT X=$P_GG[17] F100\n"), "1");  // read before the block's own words
  EXPECT_EQ(error_line("R1=$P_GG[99]\n", "system variable $P_GG is not one cutcom knows"), 1);
}

// covers: NC-PARAM-ERR-1 NC-PARAM-FLOW-6 NC-PARAM-FLOW-1 NC-PARAM-FLOW-3 NC-PARAM-VAR-2
TEST(Parametric, LanguageErrorsNameTheirLine) {
  EXPECT_EQ(error_line("G1 X0 F100\nG1 X=UNKNOWN\n", "undefined variable 'UNKNOWN'"), 2);
  EXPECT_EQ(error_line("G1 X0 F100\nGOTOF NOWHERE\n", "jump target 'NOWHERE' not found"), 2);
  EXPECT_EQ(error_line("LAB1: G1 X0 F100\nGOTOF LAB1\n", "not found after this block"), 2);
  EXPECT_EQ(error_line("DEF REAL AA[2]\nAA[2]=1\n", "outside 0 to 1"), 2);
  EXPECT_EQ(error_line("R1=0\nENDWHILE\n", "ENDWHILE without"), 2);
  EXPECT_EQ(error_line("WHILE 1\nG1 X1 F100\n", "ends inside a loop"), 2);
  EXPECT_EQ(error_line("R1=1\nIF R1>0\nG1 X1 F100\n", "IF without its ENDIF"), 2);
  EXPECT_EQ(error_line("DEF STRING[8] SS\nSS=5\n", "STRING variable is assigned a number"), 2);
  EXPECT_EQ(error_line("DEF REAL X\n", "cannot be a variable name"), 1);
  EXPECT_EQ(error_line("R1=1\nG1 X=R1/(R1-1) F100\n", "division by zero"), 2);
  // An endless loop stops at the limit, naming where it was reached.
  EXPECT_EQ(error_line("LOOP\nR1=R1+1\nENDLOOP\n", "runs away", {1000}), 3);
  EXPECT_EQ(error_line("START: R1=R1+1\nGOTOB START\n", "runs away", {1000}), 2);
  // NC-PARAM-FLOW-5: a section's start must exist (before the block for REPEAT label).
  EXPECT_EQ(error_line("G1 X0 F100\nREPEAT LATER P=2\nLATER: G1 X1\n", "not found before this block"), 2);
  EXPECT_EQ(error_line("AA: G1 X0 F100\nREPEAT AA BB\n", "end 'BB' is not found"), 2);
  EXPECT_EQ(error_line("CASE (1) OF 1 G1 X0\n", "GOTOF or GOTOB"), 1);
  EXPECT_EQ(error_line("CASE (1) OF 2 GOTOF AA\nG1 X1 F1\nCASE (2) OF 2 GOTOF MISSING\n", "'MISSING' not found"), 3);
  EXPECT_EQ(error_line("AA: R1=R1+1\nREPEAT AA P=0\n", "whole number from 1"), 2);
}

// A folder of subprogram files for one test.
std::string folder_with(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("cutcom-" + name);
  std::filesystem::create_directories(dir);
  for (const auto& [file, text] : files) std::ofstream(dir / file) << text;
  return dir.string();
}

// covers: NC-PARAM-SYS-3
TEST(Parametric, RunModeActiveEdgeAndGivenParameters) {
  // A normal run: the block-search branch is not taken.
  EXPECT_EQ(end_x("IF $P_SEARCH OR $P_ISTEST OR $P_DRYRUN OR $P_SEARCHL GOTOF SKIP\nG1 X7 F100\nSKIP: G1 Y1\n"), "7");
  EXPECT_EQ(end_x("IF $P_SIM GOTOF SKIP\nG1 X8 F100\nSKIP: G1 Y1\n"), "8");
  EXPECT_EQ(end_x("T4\nG1 X=$P_TOOLP F100\n"), "4");
  // $P_AD[6]: the radius of the edge in force (T2 D3), 0 with D0.
  EXPECT_EQ(end_x("$TC_DP6[2,3]=4.5\nT2 D3\nG1 X=$P_AD[6]*2 F100\nD0\nX=$P_AD[6]+1\n"), "1");
  EXPECT_EQ(end_x("$TC_DP6[2,3]=4.5\n$TC_DP1[2,3]=120\nT2 D3\nG1 X=$P_AD[6]*2+$P_AD[1] F100\n"), "129");
  EXPECT_EQ(error_line("G1 X0 F100\nT5 D1\nR1=$P_AD[6]\n", "$P_AD is not one cutcom knows"), 3);
  // $P_SUBPAR: which arguments the call gave.
  std::string dir = folder_with("subpar", {{"GIVEN.SPF",
                                            "PROC GIVEN(REAL AA, REAL BB)\n"
                                            "G1 X=$P_SUBPAR[1]*10+$P_SUBPAR[2] F100\nRET\n"}});
  for (auto [call, x] : {std::pair{"GIVEN(1, 2)", "11"}, std::pair{"GIVEN(, 2)", "1"}, std::pair{"GIVEN(1)", "10"}}) {
    std::istringstream in(std::string(call) + "\nM30\n");
    ProgramReader reader(in);
    reader.set_search_path({dir});
    Block b, last;
    while (reader.next(b)) last = b;
    EXPECT_EQ(last.end.x.to_string(), x) << call;
  }
  EXPECT_EQ(end_x("G1 X=$P_SUBPAR[1]+3 F100\n"), "3");
  EXPECT_EQ(error_line("R1=$P_SUBPAR[0]\n", "$P_SUBPAR takes one index"), 1);
}

// covers: NC-PARAM-EXPR-6 NC-PARAM-VAR-1
TEST(Parametric, AxisNamesAsValues) {
  // AXNAME gives an AXIS value (also as a DEF's initial value), AXSTRING its name back.
  EXPECT_EQ(end_x("DEF AXIS AA=AXNAME(\"x\")\nG1 AX[AA]=7 F100\n"), "7");
  EXPECT_EQ(end_x("DEF AXIS AA\nDEF STRING[8] SS\nAA=AXNAME(\"X\")\nSS=AXSTRING(AA)<<\"1\"\n"
                  "IF SS==\"X1\"\nG1 X4 F100\nENDIF\n"),
            "4");
  // The three geometry axes exist.
  EXPECT_EQ(end_x("IF ISAXIS(1) AND ISAXIS(3) AND NOT ISAXIS(4)\nG1 X2 F100\nENDIF\n"), "2");
  EXPECT_EQ(error_line("G1 X1 F1\nR1=AXNAME(5)\n", "AXNAME: argument 1 must be a string"), 2);
  EXPECT_EQ(error_line("DEF AXIS AA=AXNAME(\"1X\")\n", "'1X' is not an axis name"), 1);
  EXPECT_EQ(error_line("R1=AXSTRING(1)\n", "AXSTRING: argument 1 must be an axis"), 1);
}

// covers: NC-PARAM-SUB-1
TEST(Parametric, AProgramWithoutAFolderCallsNoFile) {
  std::string dir = folder_with("nofiles", {{"LONGWAY.SPF", "G1 X5 F100\nM17\n"}});
  auto read = [&](bool files) {
    std::istringstream in("LONGWAY\nM30\n");
    ProgramReader reader(in);
    if (files)
      reader.set_search_path({dir});
    else
      reader.no_subprogram_files();
    Block b;
    try {
      while (reader.next(b)) {
      }
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return b.end.x.to_string();
  };
  EXPECT_EQ(read(true), "5");
  EXPECT_NE(read(false).find("'LONGWAY' is not a SINUMERIK word"), std::string::npos) << read(false);
}

// covers: NC-PARAM-EXPR-4
TEST(Parametric, RecordedLinesRunAsTheirText) {
  // Loop passes and calls run their lines from what the first run recorded: the same blocks, in a
  // subprogram called with other arguments and repeated (P), as when every line is read again.
  std::string dir = folder_with("recorded", {{"STEP.SPF",
                                              "PROC STEP(REAL WW, INT NN)\nDEF INT KS\nDEF REAL HH=WW/2\n"
                                              "WHILE KS<NN\n  KS=KS+1\n  HH=HH*(-1)\n  G1 X=AC(WW*KS) Y=HH+KS MOD 2\n  "
                                              "R5=R5-KS DIV 2\nENDWHILE\nRET\n"}});
  const std::string program =
      "DEF INT KK\nDEF REAL XX=0.1\nDEF BOOL BB\nN10 G1 X0 Y0 F100\n"
      "WHILE KK<4\n  KK=KK+1.5\n  XX=XX+0.2\n  BB=XX>=0.5\n  G1 X=-XX*3 Y=KK Z=BB ; comment\n"
      "  Y=R5\nENDWHILE\nSTEP(2.5, 3)\nSTEP(4, 2) P2\nFOR KK=1 TO 3\n  X=KK*KK-1\nENDFOR\nM30\n";
  auto blocks = [&](const std::string& text, std::size_t cache) {
    std::istringstream in(text);
    ProgramReader reader(in);
    InterpreterLimits limits;
    limits.line_cache_bytes = cache;
    reader.set_limits(limits);
    reader.set_search_path({dir});
    std::vector<std::string> ends;
    Block b;
    try {
      while (reader.next(b))
        ends.push_back(std::to_string(b.words.line) + ":" + b.end.x.to_string() + "," + b.end.y.to_string() + "," +
                       b.end.z.to_string());
    } catch (const InputError& e) {
      ends.push_back(std::string("error ") + e.what());
    }
    return ends;
  };
  std::vector<std::string> recorded = blocks(program, InterpreterLimits{}.line_cache_bytes);
  // N10; two WHILE passes (INT KK: 1.5 and 3.5 round to 2 and 4) of two blocks; STEP three times;
  // STEP twice, run twice (P2); three FOR passes; M30.
  EXPECT_EQ(recorded.size(), 1u + 2 * 2 + 3 + 2 * 2 + 3 + 1);
  EXPECT_EQ(recorded[3], "9:-1.5,4,1");  // XX = 0.5 exactly: BB TRUE
  EXPECT_EQ(recorded[7], "12:7.5,-0.25,1");
  EXPECT_EQ(recorded, blocks(program, 0));
  // An error in a later pass is the error of the text: a division by zero in the third pass.
  const std::string failing = "DEF INT KK\nWHILE KK<5\n  KK=KK+1\n  G1 X=10/(3-KK) F100\nENDWHILE\nM30\n";
  std::vector<std::string> stopped = blocks(failing, InterpreterLimits{}.line_cache_bytes);
  ASSERT_EQ(stopped.size(), 3u);
  EXPECT_NE(stopped.back().find("division by zero"), std::string::npos) << stopped.back();
  EXPECT_EQ(stopped, blocks(failing, 0));
}

RunResult run_in(const std::string& engine, const std::string& text, const std::string& dir, bool* ok) {
  std::istringstream in(text);
  MachineData md;
  ProgramReader reader(in, md.initial_state());
  reader.set_search_path({dir});
  CollectingSink sink;
  *ok = engine == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink);
  return sink.result;
}

// covers: NC-PARAM-SUB-1 NC-PARAM-SUB-2 NC-PARAM-SUB-3
TEST(Parametric, SubprogramsGiveThePlainProgramsPath) {
  // SQUARE(10, 20, AREA) mills a 10 x 20 rectangle with G41 and returns its area through a VAR
  // parameter; L77 P2 moves 5 mm in Y twice (G91); the IF checks the returned area.
  std::string dir = folder_with("subprograms", {{"SQUARE.SPF",
                                                 "PROC SQUARE(REAL XS, REAL YS, VAR REAL RESULT) DISPLOF\n"
                                                 "N10 G41 G1 X0 Y0 F300\nN20 X=XS\nN30 Y=YS\nN40 X0\nN50 Y0\n"
                                                 "N60 G40 X-20 Y0\nRESULT=XS*YS\nRET\n"},
                                                {"L77.SPF", "N10 G91 G1 Y5\nN20 G90\nM17\n"}});
  const std::string main =
      "DEF REAL AREA\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G0 X-20 Y0 Z5 T1 D1\nN20 G1 Z-1 F200\n"
      "N30 SQUARE(10, 20, AREA)\nN40 L77 P2\nIF AREA <> 200 GOTOF BAD\nN50 G0 Z5\nM30\nBAD: G1 X999\nM30\n";
  const std::string plain =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G0 X-20 Y0 Z5 T1 D1\nN20 G1 Z-1 F200\n"
      "N10 G41 G1 X0 Y0 F300\nN20 X10\nN30 Y20\nN40 X0\nN50 Y0\nN60 G40 X-20 Y0\n"
      "N10 G91 G1 Y5\nN20 G90\nN10 G91 G1 Y5\nN20 G90\nN50 G0 Z5\nM30\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_p = false, ok_q = false;
    RunResult p = run_in(engine, main, dir, &ok_p), q = run_engine(engine, plain, {}, &ok_q);
    ASSERT_TRUE(ok_p && ok_q) << engine;
    EXPECT_EQ(p.path.size(), 11u);
    expect_same_path(p, q);
    // Everything a subprogram produces carries the main program's calling line.
    for (const PathElement& e : p.path) {
      if (e.origin.kind == OriginKind::kOffset) {
        EXPECT_EQ(e.origin.line, 6) << engine;
      }
    }
  }
}

// covers: NC-PARAM-SUB-4
TEST(Parametric, SaveRestoresTheCallersModalState) {
  // KEEP switches to G91, G3 and a TRANS; after its return the caller's G90, G1 and frame hold
  // again; DRIFT has no SAVE, so its G91 stays.
  std::string dir = folder_with("save", {{"KEEP.SPF",
                                          "PROC KEEP(REAL DX) SAVE DISPLOF\nN10 G91 G1 X=DX\nN20 TRANS X100\n"
                                          "N30 G3 X10 Y0 CR=5\nRET\n"},
                                         {"DRIFT.SPF", "PROC DRIFT\nN10 G91 G1 X2\nRET\n"},
                                         {"kont.mpf", "G1 X999\n"},
                                         {"G17.SPF", "G1 X999\n"}});
  // Files named as words the reader knows (KONT, G17) are never called.
  const std::string main =
      "N10 G0 X0 Y0 Z0\nKONT\nG17\nN20 G1 X5 F100\nN30 KEEP(5)\nN40 X20 Y5\nN50 DRIFT\nN60 X1\nM30\n";
  const std::string plain =
      "N10 G0 X0 Y0 Z0\nKONT\nG17\nN20 G1 X5 F100\nN10 G91 G1 X5\nN30 G3 X10 Y0 CR=5\nN40 G90 G1 X20 Y5\n"
      "N10 G91 G1 X2\nN60 X1\nM30\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_p = false, ok_q = false;
    RunResult p = run_in(engine, main, dir, &ok_p), q = run_engine(engine, plain, {}, &ok_q);
    ASSERT_TRUE(ok_p && ok_q) << engine;
    expect_same_path(p, q);
    ASSERT_EQ(p.path.size(), 6u) << engine;        // N10 does not move
    EXPECT_EQ(p.path.back().end.x, 23) << engine;  // DRIFT's G91 stays: 22 + 1
  }
}

// covers: NC-PARAM-SUB-6 NC-PARAM-ERR-2
TEST(Parametric, ModalCallRunsAfterEveryMove) {
  // MCALL HOLE(2) runs HOLE after each block that moves in this level (not after its own moves,
  // not after a frame), until MCALL alone; SETAL stops the run with the program's alarm.
  std::string dir = folder_with("modal", {{"HOLE.SPF", "PROC HOLE(REAL DEPTH)\nN10 G1 Z=-DEPTH F50\nN20 G0 Z2\nRET\n"},
                                          {"CHECK.SPF",
                                           "PROC CHECK(REAL WIDTH)\nIF WIDTH<=0\n  SETAL(61101)\nENDIF\n"
                                           "G1 X=WIDTH\nRET\n"}});
  const std::string main =
      "N10 G0 X0 Y0 Z2\nN20 MCALL HOLE(2)\nN30 X10\nN40 TRANS X0\nN50 Y10 F100\nN60 MCALL\nN70 X20\nM30\n";
  const std::string plain =
      "N10 G0 X0 Y0 Z2\nN30 X10\nN10 G1 Z-2 F50\nN20 G0 Z2\nN50 Y10 F100\nN10 G1 Z-2 F50\nN20 G0 Z2\nN70 X20\n"
      "M30\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_p = false, ok_q = false;
    RunResult p = run_in(engine, main, dir, &ok_p), q = run_engine(engine, plain, {}, &ok_q);
    ASSERT_TRUE(ok_p && ok_q) << engine;
    expect_same_path(p, q);
    EXPECT_EQ(p.path.size(), 8u) << engine;
  }
  EXPECT_EQ(error_line("G0 X0\nCHECK(5)\nCHECK(0)\n", "the program raises alarm 61101 (SETAL)", {}, dir), 3);
  EXPECT_EQ(error_line("MCALL NOSUCH(1)\n", "neither a standard cycle nor a subprogram found", {}, dir), 1);
}

// A rounding or chamfer in a subprogram that cannot be made names the subprogram's file and lines,
// as every other error there does (it stopped naming the calling line as "line 2/line 2").
// covers: NC-PARAM-SUB-3 NC-CONTOUR-1
TEST(Parametric, AContourDefinitionErrorInASubprogramNamesItsPlace) {
  std::string dir = folder_with("contour-in-sub", {{"SLOT.SPF",
                                                    "PROC SLOT(REAL WW)\nG1 X0 Y0 F100\nG1 X40 CHF=1\n"
                                                    "G3 X40 Y=WW CR=WW/3\nG1 X0\nRET\n"}});
  EXPECT_EQ(error_line("G0 X-5 Y0\nSLOT(30)\nM30\n",
                       "in subprogram SLOT.SPF line 3: the chamfer of SLOT.SPF line 3/SLOT.SPF line 4", {}, dir),
            2);
}

// covers: NC-PARAM-SUB-3 TRC-END-1
TEST(Parametric, ElementsNameWhereInASubprogramTheyStand) {
  std::string dir = folder_with(
      "provenance", {{"OUTER.SPF", "N10 G1 X5 F100\nN20 INNER\nRET\n"}, {"INNER.SPF", "; inner\nN30 G1 Y5\nM17\n"}});
  for (const char* engine : {"fast", "ref"}) {
    std::istringstream in("N10 G0 X0 Y0\nN20 OUTER\nN30 X0\nM30\n");
    MachineData md;
    ProgramReader reader(in, md.initial_state());
    reader.set_search_path({dir});
    CollectingSink sink;
    ASSERT_TRUE(std::string(engine) == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink));
    const auto& path = sink.result.path;
    ASSERT_EQ(path.size(), 3u) << engine;
    EXPECT_EQ(reader.source_text(path[0].origin.source), "OUTER.SPF line 1") << engine;
    EXPECT_EQ(reader.source_text(path[1].origin.source), "INNER.SPF line 2, called from OUTER.SPF line 2") << engine;
    EXPECT_EQ(path[1].origin.line, 2) << engine;  // the main program's calling line
    EXPECT_EQ(path[2].origin.source, 0u) << engine;
  }
  // An alarm at a subprogram's block names that block's place too: an inner half circle smaller
  // than the tool in INNER2 (10751 at its N20), an arc selecting G41 in ARCSEL (10753).
  std::string alarms = folder_with("provenance-alarms", {{"OUTER2.SPF", "N10 G0 X0 Y0\nN20 INNER2\nRET\n"},
                                                         {"INNER2.SPF",
                                                          "N10 G1 G41 X10 Y0 F100\n"
                                                          "N20 G3 X10 Y1 CR=0.5\nN30 G1 X0\nM17\n"},
                                                         {"ARCSEL.SPF", "N50 G41 G2 X10 Y0 CR=20 F100\nM17\n"}});
  const std::string tool = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nT1 D1\n";
  for (const char* engine : {"fast", "ref"}) {
    for (auto [main, where, number] :
         {std::tuple{tool + "N20 OUTER2\nM30\n", "INNER2.SPF line 2, called from OUTER2.SPF line 2", 10751},
          std::tuple{tool + "G0 X0 Y0\nARCSEL\nM30\n", "ARCSEL.SPF line 1", 10753}}) {
      std::istringstream in(main);
      MachineData md;
      ProgramReader reader(in, md.initial_state());
      reader.set_search_path({alarms});
      CollectingSink sink;
      EXPECT_FALSE(std::string(engine) == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink));
      ASSERT_EQ(sink.result.alarms.size(), 1u) << engine;
      EXPECT_EQ(sink.result.alarms[0].number, number) << engine;
      EXPECT_EQ(reader.source_text(sink.result.alarms[0].source), where) << engine;
    }
    // So does a notice: compensation still active at the end, its last block in LAST.SPF.
    std::string notices = folder_with("provenance-notices", {{"LAST.SPF", "N10 G1 X20 Y0\nN20 Y10\nM17\n"}});
    std::istringstream in(tool + "G0 X0 Y0\nG1 G41 X10 F100\nLAST\nM30\n");
    MachineData md;
    ProgramReader reader(in, md.initial_state());
    reader.set_search_path({notices});
    CollectingSink sink;
    EXPECT_TRUE(std::string(engine) == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink));
    ASSERT_EQ(sink.result.notices.size(), 1u) << engine;
    EXPECT_EQ(sink.result.notices[0].clause, "TRC-END-1") << engine;
    EXPECT_EQ(reader.source_text(sink.result.notices[0].source), "LAST.SPF line 2") << engine;
  }
}

int sub_error(const std::string& main, const std::string& dir, const std::string& words) {
  return error_line(main, words, {}, dir);
}

// covers: NC-PARAM-SUB-3 NC-PARAM-SUB-2 NC-PARAM-SUB-1 NC-PARAM-ERR-1
TEST(Parametric, SubprogramErrorsNameFileLineAndCall) {
  std::string dir =
      folder_with("broken", {{"BROKEN.SPF", "PROC BROKEN(REAL AA)\nG1 X=AA+UNDEF F100\nRET\n"},
                             {"DEEP.SPF", "PROC DEEP\nDEEP\nRET\n"},
                             {"WORDS.SPF", "G1 X1 F100\nQQ5\n"},
                             {"SHIFT.SPF", "PROC SHIFT SAVE\nTRANS X5\nG41 G1 X10 Y0 F100 T1 D1\nRET\n"}});
  EXPECT_EQ(sub_error("G0 X0\nN20 BROKEN(5)\n", dir,
                      "in subprogram BROKEN.SPF line 2, column 9 (called from line 2): undefined variable 'UNDEF'"),
            2);
  EXPECT_EQ(sub_error("WORDS\n", dir, "in subprogram WORDS.SPF line 2, column 1"), 1);
  EXPECT_EQ(sub_error("G0 X0\nDEEP\n", dir, "more than 16 program levels"), 2);
  EXPECT_EQ(sub_error("G0 X0\nL99\n", dir, "subprogram L99 not found"), 2);
  EXPECT_EQ(sub_error("BROKEN(1, 2)\n", dir, "2 arguments given, the PROC has 1 parameters"), 1);
  EXPECT_EQ(sub_error("G0 X0 Y0\nSHIFT\n", dir, "puts back another frame"), 2);
}

// An array passed to a PROC's VAR array parameter: the PROC reads the caller's corners and
// writes one back; sizes left open take the caller's; wrong arrays are errors naming the PROC line.
// covers: NC-PARAM-SUB-2 NC-PARAM-ERR-1
TEST(Parametric, ArrayParametersWorkOnTheCallersArray) {
  std::string dir = folder_with(
      "arrays", {{"OUTLINE.SPF",
                  "PROC OUTLINE(VAR REAL PTS[,2], INT COUNT, VAR INT SEEN)\nDEF INT KK\n"
                  "G1 G41 X=PTS[0,0] Y=PTS[0,1]\nFOR KK=1 TO COUNT-1\n  X=PTS[KK,0] Y=PTS[KK,1]\n"
                  "  SEEN=SEEN+1\nENDFOR\nX=PTS[0,0] Y=PTS[0,1]\nPTS[1,0]=PTS[1,0]*3\nG40 X-10 Y-10\nM17\n"},
                 {"FIXED.SPF", "PROC FIXED(VAR REAL PTS[3,2])\nG1 X=PTS[2,0] F100\nM17\n"},
                 {"BYVALUE.SPF", "PROC BYVALUE(REAL PTS[3])\nM17\n"},
                 {"SCALAR.SPF", "PROC SCALAR(REAL AA)\nM17\n"}});
  const std::string head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nG17 G90 T1 D1 F200\nG0 X-10 Y-10\n";
  const std::string main = head +
                           "DEF REAL CORNERS[4,2]=SET(0,0, 30,0, 30,20, 0,20)\nDEF INT NN\n"
                           "OUTLINE(CORNERS, 4, NN)\nG0 X=CORNERS[1,0]+NN Y-10\nM30\n";
  const std::string plain = head + "G1 G41 X0 Y0\nX30 Y0\nX30 Y20\nX0 Y20\nX0 Y0\nG40 X-10 Y-10\nG0 X93 Y-10\nM30\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_p = false, ok_q = false;
    RunResult p = run_in(engine, main, dir, &ok_p), q = run_engine(engine, plain, {}, &ok_q);
    ASSERT_TRUE(ok_p && ok_q) << engine;
    EXPECT_EQ(p.path.size(), 8u);
    expect_same_path(p, q);
  }
  EXPECT_EQ(sub_error("DEF REAL AA[2,2]\nFIXED(AA)\n", dir, "has 2 elements in index 1, the PROC declares 3"), 2);
  EXPECT_EQ(sub_error("DEF INT AA[3,2]\nFIXED(AA)\n", dir, "another type or number of indices"), 2);
  EXPECT_EQ(sub_error("FIXED(5)\n", dir, "needs an array variable as its argument"), 1);
  EXPECT_EQ(sub_error("DEF REAL AA[3]\nBYVALUE(AA)\n", dir, "must be a VAR parameter"), 2);
  EXPECT_EQ(sub_error("DEF REAL AA[3]\nSCALAR(AA)\n", dir, "AA is an array: the parameter AA is not"), 2);
}

// A frame assigned to $P_PFRAME, built in a FRAME variable, chained and read back, gives the path
// of the same frame programmed with TRANS/AROT/AMIRROR/ASCALE blocks.
// covers: NC-PARAM-EXPR-5 NC-PARAM-SYS-1 NC-PARAM-EXPR-2
TEST(Parametric, StringFunctionsAndMoreSystemVariables) {
  EXPECT_EQ(end_x("G1 X=STRLEN(\"ABC\") F100\n"), "3");
  EXPECT_EQ(end_x("DEF STRING[10] S1=\"ABCD\"\nDEF STRING[10] S2\nS2=SUBSTR(S1,1,2)\n"
                  "G1 X=STRLEN(S2)*10+INDEX(S2,\"C\") F100\n"),
            "21");
  EXPECT_EQ(end_x("G1 X=RINDEX(\"ABAB\",\"A\")+MINDEX(\"XYZ\",\"ZY\")*10+MATCH(\"ABC\",\"Q\")*100 F100\n"), "-88");
  EXPECT_EQ(end_x("DEF STRING[9] S1\nS1=TOUPPER(\"ab\")<<TOLOWER(\"CD\")\nG1 X=MATCH(S1,\"Bc\") F100\n"), "1");
  EXPECT_EQ(end_x("G1 X=NUMBER(\" -1.5EX2 \")+ISNUMBER(\"12\")+ISNUMBER(\"1A\")*10 F100\n"), "-149");
  EXPECT_EQ(error_line("R1=NUMBER(\"x\")\n", "NUMBER: \"x\" is not a number"), 1);
  EXPECT_EQ(error_line("R1=INDEX(\"ABC\",\"BC\")\n", "argument 2 must be one character"), 1);
  EXPECT_EQ(error_line("R1=STRLEN(5)\n", "argument 1 must be a string"), 1);
  EXPECT_EQ(error_line("R1=SUBSTR(\"A\")\n", "takes 2 to 3 arguments"), 1);
  // $PI, $P_F, $P_OFFN; $TC_DPn gives what was assigned, also the lengths.
  EXPECT_EQ(end_x("G1 X=ROUND($PI*1000) F100\n"), "3142");
  EXPECT_EQ(end_x("G1 F250\nOFFN=0.5\nG1 X=$P_F+$P_OFFN\n"), "250.5");
  EXPECT_EQ(end_x("$TC_DP3[1,1]=150\n$TC_DP6[1,1]=4\nG1 X=$TC_DP3[1,1]+$TC_DP6[1,1]+$TC_DP12[1,1] F100\n"), "154");
  EXPECT_EQ(error_line("R1=$TC_DP3[7,1]\n", "tool 7 has no edge 1"), 1);
  // $TC_TP2[t]: the tool's name, a STRING.
  EXPECT_EQ(
      end_x(
          "$TC_TP2[3]=\"ROUGH_D16\"\nT3\nIF $TC_TP2[$P_TOOLNO]==\"ROUGH_D16\"\nG1 X=STRLEN($TC_TP2[3]) F100\nENDIF\n"),
      "9");
  EXPECT_EQ(error_line("R1=STRLEN($TC_TP2[4])\n", "tool 4 has no name"), 1);
  // $P_TOOLL[n]: the active edge's length n with its wear; ISVAR; SPRINT.
  EXPECT_EQ(end_x("$TC_DP1[1,1]=120\n$TC_DP3[1,1]=150\n$TC_DP12[1,1]=-0.25\nT1 D1\nG1 X=$P_TOOLL[1] F100\n"), "149.75");
  EXPECT_EQ(end_x("DEF REAL AA\nG1 X=ISVAR(\"AA\")+ISVAR(\"R7\")*2+ISVAR(\"$P_TOOLR\")*4+ISVAR(\"BB\")*8 F100\n"), "7");
  EXPECT_EQ(first_block_actions("R1=2.5\nMSG(SPRINT(\"R=%.2F N=%D %S %%\", R1, 7.9, \"OK\"))\n"),
            (std::vector<std::string>{"MSG(\"R=2.50 N=7 OK %\")"}));
  EXPECT_EQ(error_line("R1=STRLEN(SPRINT(\"%D %D\", 1))\n", "more formats than values"), 1);
}

// covers: NC-PARAM-SUB-7
TEST(Parametric, ExternDeclarationsAndDefineMacros) {
  EXPECT_EQ(end_x("EXTERN CONTOUR(REAL, VAR REAL, INT)\nEXTERN HOME\nG1 X4 F100\n"), "4");
  // A macro's name becomes its text, outside strings and comments; a later DEFINE replaces it.
  std::istringstream in(
      "DEFINE M_COOL AS M8\nDEFINE FIN AS G1 F=R1*2 ; a feed\nR1=150\nM_COOL MSG(\"M_COOL\") ; M_COOL\n"
      "FIN X5\nDEFINE FIN AS G0\nFIN X7\n");
  ProgramReader reader(in);
  std::vector<Block> b;
  for (Block k; reader.next(k);) b.push_back(k);
  ASSERT_EQ(b.size(), 3u);
  ASSERT_EQ(b[0].words.aux_count, 2);  // M8 and the MSG, whose string keeps M_COOL
  EXPECT_EQ(b[0].state.feed.to_string(), "0");
  EXPECT_EQ(b[1].state.feed.to_string(), "300");
  EXPECT_EQ(b[1].end.x.to_string(), "5");
  EXPECT_EQ(b[2].state.motion, Motion::kRapid);
  EXPECT_EQ(error_line("DEFINE M_COOL M8\n", "DEFINE is written DEFINE name AS text"), 1);
  EXPECT_EQ(error_line("DEFINE M_COOL AS ; nothing\n", "the macro's text is missing"), 1);
  EXPECT_EQ(error_line("EXTERN SUB(REAL\n", "')' expected"), 1);
  EXPECT_EQ(error_line("EXTERN SUB(REAL) X1\n", "unexpected text after the EXTERN declaration"), 1);
}

// covers: NC-CYCLE-1 NC-PARAM-SUB-1
TEST(Parametric, TheProgramsOwnSubprogramWithACyclesPrefixIsCalled) {
  std::string dir = folder_with("fprefix", {{"F_PROFILE.SPF", "PROC F_PROFILE(REAL AA)\nG1 X=AA*2 F100\nRET\n"}});
  std::istringstream in("F_PROFILE(4)\nM30\n");
  ProgramReader reader(in);
  reader.set_search_path({dir});
  Block b, last;
  while (reader.next(b)) last = b;
  EXPECT_EQ(last.end.x.to_string(), "8");
  // Without the file the name stays a ShopMill cycle: not simulated, noted.
  std::istringstream cycle("F_PROFILE(4)\nM30\n");
  ProgramReader without(cycle);
  without.set_search_path({dir + "-none"});
  ASSERT_TRUE(without.next(b));
  EXPECT_EQ(b.words.not_simulated, "F_PROFILE");
}

}  // namespace
}  // namespace cutcom::test
