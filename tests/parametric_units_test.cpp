// Programs of several units in one file (spec nc-parametric.md, NC-PARAM-SUB-8): a job archive
// "%_N_MAIN_MPF … %_N_CONTOUR_SPF …" calls its own units; a unit's text ends at the next header.
#include "parametric_support.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

const std::string kArchive =
    "%_N_MAIN_MPF\n"
    ";$PATH=/_N_WKS_DIR/_N_JOB_WPD\n"
    "N10 G0 X0 Y0\n"
    "N20 SQUARE(10) P2\n"
    "N30 G0 X50\n"
    "N40 GOTOF DONE\n"
    "N50 X60\n"
    "%_N_SQUARE_SPF\n"
    ";$PATH=/_N_WKS_DIR/_N_JOB_WPD\n"
    "PROC SQUARE(REAL SIDE)\n"
    "N10 G1 X=SIDE F100\n"
    "N20 EDGE(SIDE)\n"
    "DONE: RET\n"
    "%_N_EDGE_SPF\n"
    "PROC EDGE(REAL LEN)\n"
    "N10 Y=LEN\n"
    "M17\n"
    "%_N_OTHER_MPF\n"
    "DONE: G0 X99\n"
    "M30\n";

struct Read {
  std::vector<std::string> ends;     // x,y of each block that moves
  std::vector<std::string> sources;  // where each stands
  std::string error;
};

Read read(const std::string& text, bool files = true) {
  std::istringstream in(text);
  ProgramReader reader(in);
  if (!files) reader.no_subprogram_files();
  Read r;
  Block b;
  try {
    while (reader.next(b)) {
      if (!b.words.motion && !b.words.axis[0].present && !b.words.axis[1].present) continue;
      r.ends.push_back(b.end.x.to_string() + "," + b.end.y.to_string());
      r.sources.push_back(reader.source_text(b.words.source));
    }
  } catch (const InputError& e) {
    r.error = e.what();
  }
  return r;
}

// covers: NC-PARAM-SUB-8 NC-PARAM-SUB-1
TEST(ParametricUnits, AnArchiveCallsItsOwnUnits) {
  // SQUARE runs twice (P2) and calls EDGE, both units of the same text; the main program's
  // GOTOF DONE finds no DONE before its own text ends (the units' labels are not its own), and
  // so does nothing after N30 ... an error naming its line.
  Read r = read(kArchive);
  EXPECT_NE(r.error.find("jump target 'DONE' not found"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("line 6"), std::string::npos) << r.error;
  ASSERT_EQ(r.ends.size(), 6u);
  EXPECT_EQ(r.ends, (std::vector<std::string>{"0,0", "10,0", "10,10", "10,10", "10,10", "50,10"}));
  EXPECT_EQ(r.sources[1], "_N_SQUARE_SPF line 11");
  EXPECT_EQ(r.sources[2], "_N_EDGE_SPF line 16, called from _N_SQUARE_SPF line 12");
  EXPECT_EQ(r.sources[5], "");
  // A program given as text without a folder still has its own units (they are no files).
  EXPECT_EQ(read(kArchive, false).ends.size(), 6u);
}

// covers: NC-PARAM-SUB-8
TEST(ParametricUnits, AUnitEndsAtTheNextHeader) {
  // The main program's text ends at the next unit's header: the unit is not run as its
  // continuation (before, its blocks were read on).
  Read r = read("G0 X1\nG0 X2\n%_N_LATER_SPF\nG0 X3\n");
  EXPECT_EQ(r.ends, (std::vector<std::string>{"1,0", "2,0"}));
  EXPECT_TRUE(r.error.empty()) << r.error;
  // A header before the first block is the program's own; comments and '%' alone are no blocks.
  r = read("; job\n%\n%_N_FIRST_MPF\n;$PATH=/_N_WKS_DIR/_N_A_WPD\nG0 X4\n");
  EXPECT_EQ(r.ends, (std::vector<std::string>{"4,0"}));
  // A unit's error names the unit, its line in the file, and the call.
  r = read("G0 X0\nBAD\nM30\n%_N_BAD_SPF\nG1 X=UNDEF F1\nM17\n");
  EXPECT_NE(r.error.find("in subprogram _N_BAD_SPF line 5, column 6 (called from line 2): undefined variable 'UNDEF'"),
            std::string::npos)
      << r.error;
  // Two units of one name: an error naming both.
  r = read("G0 X0\nTWICE\nM30\n%_N_TWICE_SPF\nG0 X1\n%_N_TWICE_SPF\nG0 X2\n");
  EXPECT_NE(r.error.find("two units named TWICE (lines 4 and 6)"), std::string::npos) << r.error;
  // A unit's backward jump searches its own text from its own start.
  r = read("G0 X0\nLOOP2\nM30\n%_N_LOOP2_SPF\nDEF INT NN=0\nAGAIN: NN=NN+1\nG0 X=NN\nIF NN<2 GOTOB AGAIN\nM17\n");
  EXPECT_EQ(r.ends, (std::vector<std::string>{"0,0", "1,0", "2,0"}));
  EXPECT_TRUE(r.error.empty()) << r.error;
}

}  // namespace
}  // namespace cutcom::test
