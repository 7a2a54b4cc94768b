// Parametric programs (spec nc-parametric.md): expressions evaluated by hand in the comments, and
// parametric programs that must give exactly the path of the plain program written out by hand.
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

}  // namespace
}  // namespace cutcom::test
