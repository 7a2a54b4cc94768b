// The NC reader and the block model: exact numbers, words, modal state, positions, tool data,
// and a clear error with line and column for everything else.
#include "cutcom/reader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "program_runs.hpp"

namespace cutcom {
namespace {

std::vector<Block> read(const std::string& text) { return testing::read_blocks(text); }

Decimal dec(const char* s) { return *Decimal::parse(s).value; }

// covers: NC-NUM-1
TEST(Decimal, LiteralsAreExact) {
  EXPECT_EQ(dec("0.1") + dec("0.2"), dec("0.3"));  // never through binary floating point
  EXPECT_EQ(dec("-.5").to_string(), "-0.5");
  EXPECT_EQ(dec("5.").to_string(), "5");
  EXPECT_EQ(dec("+12.3400").to_string(), "12.34");
  EXPECT_EQ(dec("0.000000001").units(), 1);
  EXPECT_EQ(dec("1.0000000000000").to_string(), "1");  // zeros beyond nine places change nothing
  EXPECT_EQ(Decimal::parse("0.0000000001").error, Decimal::ParseError::kTooManyDecimals);
  EXPECT_EQ(Decimal::parse("10000000000000").error, Decimal::ParseError::kOutOfRange);
  EXPECT_FALSE(Decimal::parse("1e5").value);
  EXPECT_FALSE(Decimal::parse(".").value);
  EXPECT_DOUBLE_EQ(dec("123.456").to_double(), 123.456);  // correctly rounded
  EXPECT_EQ(dec("-0.000000001").to_double(), -1e-9);
  // The division shortcut below 2^53 units gives the correctly rounded double, as strtod of the
  // exact text does: checked on values spread over the whole range, and at its edges.
  std::uint64_t x = 88172645463325252ULL;
  for (int i = 0; i < 200000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;  // xorshift64
    std::int64_t units = static_cast<std::int64_t>(x >> (11 + i % 40)) * (i % 2 == 0 ? 1 : -1);
    std::string text = std::to_string(units) + "e-9";
    ASSERT_EQ(Decimal::from_units(units).to_double(), std::strtod(text.c_str(), nullptr)) << units;
  }
  for (std::int64_t units : {(std::int64_t(1) << 53), (std::int64_t(1) << 53) + 1, -(std::int64_t(1) << 53) - 1})
    EXPECT_EQ(Decimal::from_units(units).to_double(), std::strtod((std::to_string(units) + "e-9").c_str(), nullptr));
}

// covers: NC-LEX-1 NC-LEX-2 NC-LEX-3 NC-LEX-5
TEST(Reader, WordsOfABlock) {
  auto b = read("N10 G1 G41 X10.5 Y=-3 Z=AC(2) F1000 ; comment X99\n");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(*b[0].words.number, 10);
  EXPECT_EQ(b[0].state.motion, Motion::kLinear);
  EXPECT_EQ(b[0].state.side, Side::kLeft);
  EXPECT_EQ(b[0].end.x, dec("10.5"));
  EXPECT_EQ(b[0].end.y, dec("-3"));
  EXPECT_EQ(b[0].end.z, dec("2"));
  EXPECT_EQ(b[0].state.feed, dec("1000"));
  auto k = read("g1x1y2 kont cdof2 g451 g462 OFFN = 0.5 M 30\n");
  EXPECT_EQ(k[0].end.y, dec("2"));
  EXPECT_EQ(k[0].state.approach, ApproachMode::kKont);
  EXPECT_EQ(k[0].state.collision, CollisionMode::kCdof2);
  EXPECT_EQ(k[0].state.corner, CornerMode::kG451);
  EXPECT_EQ(k[0].state.offn, dec("0.5"));
  EXPECT_TRUE(k[0].words.program_end);
}

// covers: NC-LEX-1 TOOL-FILE-1 NC-PARAM-VAR-3
TEST(Reader, AByteOrderMarkAndWindowsLineEndsAreNotText) {
  auto b = read("\xEF\xBB\xBF; saved on Windows\r\nN10 G1 X5 F100\r\nN20 Y2\r\n");
  ASSERT_EQ(b.size(), 2u);  // (a comment line is no block)
  EXPECT_EQ(b[0].end.x.to_string(), "5");
  EXPECT_EQ(b[1].end.y.to_string(), "2");
  ToolTable tools;
  std::istringstream table("\xEF\xBB\xBF$TC_DP1[1,1]=120\r\n$TC_DP6[1,1]=2.5\r\n");
  tools.load(table, "TO_INI.INI");
  ASSERT_NE(tools.find(1, 1), nullptr);
  EXPECT_EQ(tools.find(1, 1)->radius.to_string(), "2.5");
  std::istringstream program("G1 X=LIMIT F100\n"), gud("\xEF\xBB\xBF"
                                                       "DEF NCK REAL LIMIT=4\r\n");
  ProgramReader reader(program);
  reader.load_definitions(gud);
  Block x;
  ASSERT_TRUE(reader.next(x));
  EXPECT_EQ(x.end.x.to_string(), "4");
}

// covers: NC-LEX-4
TEST(Reader, SarAndCornerParameters) {
  auto b = read("G1 G41 G147 G340 G143 DISR=13 DISCL=AC(5) DISRP=2 FAD=PM(500) DISC=0 X1\nG248 DISCL=3 FAD=200\n");
  EXPECT_EQ(*b[0].words.sar_contour, SarContour::kG147);
  EXPECT_EQ(b[0].state.sar_side, SarSide::kG143);
  EXPECT_EQ(*b[0].words.disr, dec("13"));
  EXPECT_EQ(b[0].words.discl.mode, ValueMode::kAbsolute);
  EXPECT_EQ(b[0].words.fad_mode, FadMode::kPm);
  EXPECT_EQ(b[1].words.discl.mode, ValueMode::kModal);
  EXPECT_EQ(*b[1].words.fad, dec("200"));
}

// covers: NC-POS-1 NC-POS-2 NC-MODAL-1
TEST(Reader, AbsoluteIncrementalAndModalCompletion) {
  auto b = read("G90 X10 Y10\nG91 X5\nY=AC(1)\nG90 X=IC(2)\nZ7\n");
  EXPECT_EQ(b[1].end.x, dec("15"));
  EXPECT_EQ(b[1].end.y, dec("10"));  // not programmed: kept
  EXPECT_EQ(b[2].end.y, dec("1"));   // AC() inside G91
  EXPECT_EQ(b[3].end.x, dec("17"));  // IC() inside G90
  EXPECT_EQ(b[4].start, b[3].end);
  EXPECT_EQ(b[4].end.z, dec("7"));
  EXPECT_EQ(b[0].state.motion, Motion::kRapid);  // initial G0
  EXPECT_EQ(b[4].state.plane, Plane::kG17);
}

// covers: NC-ARC-1
TEST(Reader, ArcCentreIsIncrementalUnlessAc) {
  auto b = read("G0 X10 Y0\nG2 X0 Y-10 I-10 J0\nG3 X10 Y0 I=AC(0) J=AC(0)\n");
  ASSERT_TRUE(b[1].centre.has_value());
  EXPECT_EQ(b[1].centre->x, dec("0"));
  EXPECT_EQ(b[1].centre->y, dec("0"));
  EXPECT_EQ(b[2].centre->x, dec("0"));
}

// covers: TOOL-DATA-1 TOOL-EDGE-1 TOOL-EDGE-2 TRC-RADIUS-1
TEST(Reader, ToolDataAndEffectiveRadius) {
  auto b = read("$TC_DP1[1,1]=120 $TC_DP6[1,1]=7\n$TC_DP15[1,1]=-0.1\nT1 D1 OFFN=0.5\n$TC_DP6[1,1]=9\nX1\nD1\n");
  EXPECT_EQ(b[2].state.effective_radius(), dec("7.4"));
  EXPECT_EQ(b[4].state.effective_radius(), dec("7.4"));  // a later $TC_DP6 acts only from the next T/D
  EXPECT_EQ(b[5].state.effective_radius(), dec("9.4"));
  EXPECT_TRUE(b[2].state.edge_defined);
  auto u = read("T2 D1\n");
  EXPECT_FALSE(u[0].state.edge_defined);
}

struct BadLine {
  std::string text;
  int line, column;
  std::string contains;
};

// covers: NC-LEX-2 NC-LEX-3 NC-LEX-6 NC-ERR-1 NC-ERR-3 NC-END-1 NC-PARAM-ERR-1
TEST(Reader, BadInputNamesLineAndColumn) {
  const BadLine cases[] = {
      {"G1 X10\nG1 Q5\n", 2, 4, "'Q' is not a SINUMERIK word cutcom knows"},
      {"G1 X10 X20\n", 1, 8, "X programmed twice"},
      {"G1 G2 X1\n", 1, 4, "two G codes of the motion group"},
      {"G5 X1\n", 1, 1, "'G5' is SINUMERIK NC that cutcom does not simulate"},
      {"R1000=5\n", 1, 1, "R parameter R1000 does not exist"},
      {"G1 R_T=5\n", 1, 4, "'R_T' is not a SINUMERIK word cutcom knows"},
      {"G1 X=R1+XYZ\n", 1, 9, "undefined variable 'XYZ'"},
      {"N10 GOTOF END\n", 1, 5, "jump target 'END' not found after this block"},
      {"G1 X10 ASPLINE\n", 1, 8, "'ASPLINE' is SINUMERIK NC that cutcom does not simulate (splines)"},
      {"G1 X10 Y=5+\n", 1, 12, "a value is missing"},
      {"PROC CONTOUR SAVE XX\n", 1, 19, "unexpected 'XX' after the parameters of PROC"},
      {"CASE R1 OF 0 GOTOF AA\n", 1, 20, "jump target 'AA' not found after this block"},
      {"MSG(\"open\n", 1, 5, "the string has no closing '\"'"},
      {"$P_BFRAME=CTRANS(X,1)\n", 1, 1, "system variable '$P_BFRAME' is SINUMERIK NC that cutcom does not simulate"},
      {"X1.2.3\n", 1, 2, "X"},
      {"X0.0000000001\n", 1, 2, "more than 9 decimal places"},
      {"OFFN 5\n", 1, 6, "OFFN needs '='"},
      {"X=AC(5\n", 1, 7, "')' expected"},
      {"$TC_DP26[1,1]=5\n", 1, 1, "'$TC_DP26' is not a tool edge parameter"},
      {"$TC_DP6[1.1]=5\n", 1, 10, "',' expected"},
      {"N10 X1 M30\nN20 X2\n", 2, 1, "after the end of the program"},
      {"G2 X10 Y0\n", 1, 1, "G2/G3 needs the centre"},
      {"G1 I5 X1\n", 1, 1, "without G2/G3"},
      {"X#1\n", 1, 2, "X needs a number"},
      {"N10 X1 / 2\n", 1, 8, "unexpected character '/'"},
      {"N10 G0 X0 (RAPID)\n", 1, 11, "a comment in parentheses is ISO dialect (G291)"},
      {"G0 X0\nG43 H1 Z5\n", 2, 1, "'G43' is a G code of the ISO dialect (G291)"},
      {"G0 G999 X0\n", 1, 4, "'G999' is SINUMERIK NC that cutcom does not simulate"},
      // A byte no terminal shows is named by its value; a whole UTF-8 character is shown.
      {std::string("G1 X1 \0Y2\n", 11), 1, 7, "unexpected character byte 0x00"},
      {"G1 X1 \x01Y2\n", 1, 7, "unexpected character byte 0x01"},
      {"G1 X1 \xC3\xA9Y2\n", 1, 7, "unexpected character '\xC3\xA9' (not ASCII)"},
      {"G1 X1 \xC3Y2\n", 1, 7, "unexpected character byte 0xC3"},
      {"R1=2*\x7F\n", 1, 6, "unexpected character byte 0x7F"},
      {"T1.5\n", 1, 2, "T needs a whole number"},
  };
  for (const BadLine& c : cases) {
    try {
      read(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), c.line) << c.text << " -> " << e.what();
      EXPECT_EQ(e.column(), c.column) << c.text << " -> " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.contains), std::string::npos) << c.text << " -> " << e.what();
    }
  }
}

TEST(Reader, BlankAndCommentLinesAreNotBlocks) {
  auto b = read("\n   \n; only a comment\nX1\n\n");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].words.line, 4);
}

// reset_fields clears a block's words to zero bytes: every field's empty value must be zero, and
// a block full of words must come back empty (a default made non-zero fails here).
TEST(Reader, AResetBlockIsAnEmptyBlock) {
  static const BlockWordFields kEmpty{};
  const auto* bytes = reinterpret_cast<const unsigned char*>(&kEmpty);
  for (std::size_t i = 0; i < sizeof kEmpty; ++i) ASSERT_EQ(bytes[i], 0u) << "byte " << i << " of an empty block";
  BlockWords w;
  parse_block_words(
      "N7 G91 G3 X1 Y=IC(2) Z3 I4 J5 CR=6 F7 G42 G451 CDON KONT G461 G142 G341 G248 DISR=1 DISCL=AC(2) FAD=3 "
      "OFFN=0.5 DL=2 T2 D3 M6 G95 G54 G18 G700 DIAMON STOPRE",
      3, w, {}, false);
  ASSERT_FALSE(static_cast<const BlockWordFields&>(w) == kEmpty);
  reset_fields(w);
  EXPECT_TRUE(static_cast<const BlockWordFields&>(w) == kEmpty);
}

}  // namespace
}  // namespace cutcom

namespace cutcom {
namespace {

// covers: NC-ARC-2
TEST(Reader, BlockWithoutAxesUnderG2IsNoCircle) {
  auto b = read("G0 X10\nG2 X0 Y-10 I-10 J0\nM8\nF200\nX10 Y0 I0 J10\n");
  EXPECT_TRUE(b[1].is_arc());
  EXPECT_FALSE(b[2].is_arc());
  EXPECT_FALSE(b[3].is_arc());
  EXPECT_TRUE(b[4].is_arc());                                   // G2 still modal
  EXPECT_THROW(read("G2 X0 Y-10 I-10 J0\nZ-5\n"), InputError);  // an axis but no circle data
}

// A stream that reads forward only, as a pipe: it cannot be sought.
class ForwardOnly : public std::streambuf {
 public:
  explicit ForwardOnly(std::string text) : text_(std::move(text)) {
    setg(text_.data(), text_.data(), text_.data() + text_.size());
  }

 protected:
  pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override { return pos_type(-1); }
  pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(-1); }

 private:
  std::string text_;
};

// The reader's path for a plain line of the main program (Interpreter::next_plain) gives every
// other line back to the general one: a line that starts with a blank, an empty line, an
// assignment, a skip block, a unit's header (which ends the main program's text); in the file
// and from a stream that cannot be sought, the blocks and their lines are the same.
// covers: NC-LEX-1 NC-PARAM-SUB-8
TEST(Reader, ThePlainLinesPathGivesBackEveryOtherLine) {
  const std::string text =
      "N10 G0 X0 Y0\n"
      "N20 G1 X1 Y1 F100\n"
      "\n"
      "  N30 X2 Y2\n"
      "N40 X3 Y3\n"
      "N50 R1=5\n"
      "N60 X=R1 Y4\n"
      "/N70 X6 Y6\n"
      "N80 X7 Y7 ; a comment\n"
      "\tN90 X8 Y8\n"
      "N100 X9 Y9\n"
      "%_N_SUB_SPF\n"
      "N10 X99 Y99\n";
  const std::vector<std::string> expected = {"4:0,0",  "5:1,1",  "7:2,2",  "8:3,3", "10:5,4",
                                             "11:6,6", "12:7,7", "13:8,8", "14:9,9"};
  auto blocks_of = [](std::istream& in) {
    ProgramReader reader(in, ModalState{});
    std::vector<std::string> got;
    Block b;
    while (reader.next(b))
      if (b.words.axis[0].present)
        got.push_back(std::to_string(b.words.line) + ":" + b.end.x.to_string() + "," + b.end.y.to_string());
    return got;
  };
  std::istringstream file("; header\n;\n;\n" + text);
  EXPECT_EQ(blocks_of(file), expected);
  ForwardOnly pipe("; header\n;\n;\n" + text);
  std::istream piped(&pipe);
  EXPECT_EQ(blocks_of(piped), expected);
}

}  // namespace
}  // namespace cutcom
