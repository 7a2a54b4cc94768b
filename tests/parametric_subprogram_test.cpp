// Subprograms of parametric programs (spec nc-parametric.md, NC-PARAM-SUB-*): programs that call
// subprograms from their folder must give exactly the path of the plain program written out by
// hand, and errors inside a subprogram name its file, line and call.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cutcom/interpreter.hpp"
#include "parametric_support.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

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

// covers: NC-PARAM-SUB-4 NC-FRAME-1
TEST(Parametric, SaveBringsBackTheCallersFrameForPlainBlocks) {
  // The caller's TRANS X100 comes back at the return, and the plain blocks after it (X, Y and F
  // only, which change no frame themselves) are shifted again: the subprogram's own plain blocks
  // ran without a frame.
  std::string dir = folder_with("save_frame", {{"BARE.SPF", "PROC BARE SAVE\nN10 TRANS\nN20 G1 X5 Y5\nRET\n"}});
  const std::string main = "N10 G0 X0 Y0 Z0\nN20 TRANS X100\nN30 G1 X1 F100\nN40 BARE\nN50 X20 Y5\nN60 X30\nM30\n";
  const std::string plain = "N10 G0 X0 Y0 Z0\nN30 G1 X101 F100\nN20 G1 X5 Y5\nN50 X120 Y5\nN60 X130\nM30\n";
  for (const char* engine : {"fast", "ref"}) {
    bool ok_p = false, ok_q = false;
    RunResult p = run_in(engine, main, dir, &ok_p), q = run_engine(engine, plain, {}, &ok_q);
    ASSERT_TRUE(ok_p && ok_q) << engine;
    expect_same_path(p, q);
    ASSERT_FALSE(p.path.empty()) << engine;
    EXPECT_EQ(p.path.back().end.x, 130) << engine;
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
  EXPECT_EQ(sub_error("G0 X0\nL99\n", dir, "subprogram L99 not found (L99.SPF or .MPF in the program's folder"), 2);
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
