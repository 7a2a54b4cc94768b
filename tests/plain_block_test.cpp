// The common block's one-pass reading (core/src/plain_block.cpp) is the word lexer's: on every line
// it takes, the same words, values and word count; every line the lexer rejects, it leaves to it.
// Lines: generated ones near the edges of what it takes, and every line of the repository's
// programs and of the fuzz corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../core/src/word_lexer.hpp"
#include "cutcom/input_error.hpp"
#include "cutcom/interpreter.hpp"
#include "cutcom/line_buffer.hpp"
#include "cutcom/reader.hpp"

namespace {

using cutcom::BlockWords;

struct Reading {
  bool rejected = false;
  BlockWords words;
};

Reading general(const std::string& line) {
  Reading r;
  std::vector<std::string> cycles;
  try {
    cutcom::lexer::WordLexer(line, 7, r.words, cycles).general();
  } catch (const cutcom::InputError&) {
    r.rejected = true;
  }
  return r;
}

// The one pass over `line` as it lies in a LineBuffer: its '\n', then the next line's text (digits
// that must not be read as the line's), then the buffer's padding.
bool read_in_line_buffer(const std::string& line, BlockWords& out) {
  std::string buffer = line + "\n123456789.5 X1" + std::string(cutcom::LineBuffer::kPadding, '\0');
  return cutcom::lexer::read_plain_block(std::string_view(buffer.data(), line.size()), out, true);
}

// The lexer's reading of a line the one pass took, compared.
void expect_lexer_reads(const std::string& line, const BlockWords& plain) {
  Reading g = general(line);
  EXPECT_FALSE(g.rejected) << "taken, but the lexer rejects: " << line;
  if (g.rejected) return;
  EXPECT_TRUE(static_cast<const cutcom::BlockWordFields&>(plain) ==
              static_cast<const cutcom::BlockWordFields&>(g.words))
      << line;
  EXPECT_EQ(g.words.aux_count, plain.aux_count) << line;
  for (int k = 0; k < std::min(g.words.aux_count, plain.aux_count); ++k) {
    const cutcom::AuxFunction &a = plain.aux[static_cast<std::size_t>(k)],
                              &b = g.words.aux[static_cast<std::size_t>(k)];
    EXPECT_TRUE(a.address == b.address && a.value == b.value && a.text == b.text) << line << ": action " << k;
  }
  EXPECT_EQ(g.words.tool_data_count, 0) << line;
  EXPECT_EQ(g.words.tool_names_count, 0) << line;
  EXPECT_FALSE(g.words.contour.has_value()) << line;
  EXPECT_FALSE(g.words.tool_name.has_value()) << line;
  EXPECT_TRUE(g.words.not_simulated.empty()) << line;
}

// Returns whether the one pass took the line, copied or where it lies in a LineBuffer (the same
// lines, but for those longer than the copy holds, which only the second takes).
bool expect_same_reading(const std::string& line) {
  BlockWords plain, in_place;
  plain.reset(7), in_place.reset(7);
  bool taken = cutcom::lexer::read_plain_block(line, plain);
  bool taken_in_place = read_in_line_buffer(line, in_place);
  if (line.size() <= 256) {
    EXPECT_EQ(taken, taken_in_place) << line;
  }
  if (taken) expect_lexer_reads(line, plain);
  if (taken_in_place) expect_lexer_reads(line, in_place);
  return taken || taken_in_place;
}

std::string pick(std::mt19937_64& random, const std::vector<std::string>& from) {
  return from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(random)];
}

std::string digits(std::mt19937_64& random, int count) {
  std::string d;
  for (int k = 0; k < count; ++k) d += static_cast<char>('0' + random() % 10);
  return d;
}

// A value near the edges of the plain decimals: signs, points alone, 0 to 14 integer and 0 to
// 11 fraction digits, trailing zeros.
std::string value(std::mt19937_64& random) {
  std::string v = pick(random, {"", "", "", "-", "+", "--"});
  v += digits(random, std::uniform_int_distribution<int>(0, 14)(random) % (random() % 3 ? 5 : 15));
  if (random() % 2) {
    v += pick(random, {".", ".", ".", "..", "._"});
    v += digits(random, static_cast<int>(random() % 12));
    if (random() % 5 == 0) v += "000";
  }
  return v;
}

// covers: NC-LEX-1 NC-LEX-2 NC-LEX-5
TEST(PlainBlock, GeneratedLinesReadAsTheLexerReadsThem) {
  std::mt19937_64 random(20261129);
  const std::vector<std::string> letters = {"N",   "G", "X", "Y", "Z",  "I",  "J",   "K",   "F",   "n",   "g", "x",
                                            "y",   "z", "i", "j", "k",  "f",  "X",   "Y",   "G",   "M",   "H", "S",
                                            "T",   "D", "A", "R", "L",  "P",  "E",   "FA",  "X1=", "I1=", "$", "/",
                                            "CR=", "M", "m", "H", "M2", "M6", "M17", "M30", "M1="};
  const std::vector<std::string> between = {" ", " ", "", "\t", "  ", " ;x", "=", "*", "\r", "(", ":", " = "};
  long taken = 0, lines = 0;
  for (int k = 0; k < 200000; ++k) {
    std::string line = random() % 8 == 0 ? pick(random, {" ", "/", ":1 ", "LABEL: ", ";"}) : "";
    int words = static_cast<int>(random() % 7);
    for (int w = 0; w < words; ++w) {
      std::string letter = pick(random, letters);
      line += letter;
      if (letter == "G" || letter == "g")
        line += random() % 4 ? std::to_string(random() % 5) : pick(random, {"01", "03", "0", "4", "17", "1.0", " 1"});
      else if (letter == "M" || letter == "m" || letter == "H")
        line += random() % 2 ? std::to_string(random() % 40) : value(random);
      else
        line += value(random);
      line += pick(random, between);
    }
    line += pick(random, {"", "", "; comment with X1 = ( and $", "\r", " ", "=", "*2", "$A", "_"});
    ++lines;
    taken += expect_same_reading(line);
    if (HasFailure()) return;
  }
  // The generator reaches both sides: a good share taken, and many left to the lexer.
  EXPECT_GT(taken, lines / 20);
  EXPECT_LT(taken, lines - lines / 20);
}

// covers: NC-LEX-1 NC-LEX-2 NC-LEX-5
TEST(PlainBlock, TakesTheCommonBlocks) {
  for (const char* line : {"N120 G1 X12.5 Y-3 F800", "G01X1.Y2.", "g2 x4 y0 i1 j0 ; a comment", "X-.5", "",
                           "; only a comment", "G0 Z+5.000000000", "N999999999999 X999999999999.999999999", "F-0",
                           "X5 M8", "G1X1M3H2", "m08 m9 H12 ; three actions", "M999999999999"}) {
    EXPECT_TRUE(expect_same_reading(line)) << line;
  }
  // Left to the lexer: other words, a space before the value, a word twice, a tenth decimal
  // place, a 13th integer digit, a negative feed, an expression, a label, the M functions that end
  // the program or change the tool, an extended address.
  for (const char* line : {"G4 F2",
                           "X 10",
                           "X1 X2",
                           "X1.1234567891",
                           "X1234567890123",
                           "F-5",
                           "X1+2",
                           "G1 X=5",
                           "LABEL: X1",
                           "X1 MSG",
                           "G1.0 X1",
                           "M2",
                           "X1 M30",
                           "M17",
                           "M06",
                           "M1=3",
                           "M1 =3",
                           "H2.5",
                           "M-1",
                           "M 8",
                           "N1.5",
                           "X1.2.3",
                           "X1_",
                           "X.",
                           "X"}) {
    BlockWords out, in_place;
    out.reset(1), in_place.reset(1);
    EXPECT_FALSE(cutcom::lexer::read_plain_block(line, out)) << line;
    EXPECT_FALSE(read_in_line_buffer(line, in_place)) << line;
  }
  // Sixteen actions are taken; a seventeenth is the lexer's error.
  std::string actions;
  for (int k = 0; k < 16; ++k) actions += "M" + std::to_string(k + 40) + " ";
  EXPECT_TRUE(expect_same_reading(actions));
  BlockWords seventeen;
  seventeen.reset(1);
  EXPECT_FALSE(cutcom::lexer::read_plain_block(actions + "H1", seventeen));
  EXPECT_TRUE(general(actions + "H1").rejected);
  // A line longer than the copy holds is read where it lies in a LineBuffer.
  std::string longer = "G1 X1.5" + std::string(300, ' ') + "Y-2 ; a long gap";
  BlockWords in_place;
  in_place.reset(7);
  EXPECT_TRUE(read_in_line_buffer(longer, in_place));
  EXPECT_TRUE(expect_same_reading(longer));
}

// covers: NC-LEX-1
TEST(PlainBlock, EveryLineOfTheRepositorysProgramsReadsAlike) {
  long lines = 0;
  for (const char* dir :
       {CUTCOM_SOURCE_DIR "/tests", CUTCOM_SOURCE_DIR "/examples", CUTCOM_SOURCE_DIR "/fuzz/corpus"}) {
    if (!std::filesystem::exists(dir)) continue;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
      if (!e.is_regular_file()) continue;
      std::ifstream in(e.path(), std::ios::binary);
      std::string line;
      while (std::getline(in, line)) {
        expect_same_reading(line);
        ++lines;
      }
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(lines, 1000);
}

// The interpreter reads a plain line into the block's words itself (Interpreter::next with
// words): the same words as the lexer reading the text the interpreter gives without them, in a
// loop's passes (lines from the line cache), after a macro and beside skipped blocks.
// covers: NC-LEX-1 NC-PARAM-SUB-7 NC-WORD-2
TEST(PlainBlock, TheInterpreterReadsPlainLinesAsTheLexerDoes) {
  std::mt19937_64 random(20261202);
  std::string body = "FAST X1 Y2\n/G1 X5\n/1 G1 X6\nX=R1 Y2\n";  // a macro, skip levels, a parameter
  int lines = 4;
  for (int k = 0; k < 300; ++k) {  // plain lines of the generator's kind, and now and then others
    std::string line = pick(random, {"G1 X", "g2 x", "N5 G0 Y", "X", "G01X", "Z+"}) + value(random) +
                       pick(random, {"", "", "", " M8", " M9 H3", "m07"});
    BlockWords probe;
    probe.reset(1);
    if (!cutcom::lexer::read_plain_block(line, probe)) continue;
    body += line + pick(random, {"\n", "\n", " ; note\n", "\r\n"});
    ++lines;
    if (k % 17 == 0)
      body += pick(random, {"R2=R1*2\n", "X=R1 Y2\n", "FAST X1 Y2\n", "/G1 X5\n", "/1 G1 X6\n"}), ++lines;
  }
  std::string program = "DEFINE FAST AS G0\nR1=0\nWHILE R1<2\n" + body + "R1=R1+1\nENDWHILE\nM30\n";
  std::istringstream a_in(program), b_in(program);
  cutcom::Interpreter a(a_in), b(b_in);
  a.set_skip_levels(1u << 0), b.set_skip_levels(1u << 0);  // "/" skipped, "/1" not
  std::vector<std::string> cycles;
  std::string a_text, b_text;
  int a_line = 0, b_line = 0;
  long plain = 0, blocks = 0;
  BlockWords words;
  while (true) {
    bool a_read = a.next(a_text, a_line, &words), b_read = b.next(b_text, b_line);
    ASSERT_EQ(a_read, b_read);
    if (!a_read) break;
    ++blocks;
    ASSERT_EQ(a_line, b_line);
    if (!words.plain) {
      ASSERT_EQ(a_text, b_text) << "line " << b_line;
      continue;
    }
    ++plain;
    BlockWords lexed;
    cutcom::parse_block_words(b_text, b_line, lexed, cycles);
    ASSERT_TRUE(lexed.plain) << b_text;
    ASSERT_TRUE(static_cast<const cutcom::BlockWordFields&>(words) ==
                static_cast<const cutcom::BlockWordFields&>(lexed))
        << "line " << b_line << ": " << b_text;
    ASSERT_EQ(words.aux_count, lexed.aux_count) << "line " << b_line << ": " << b_text;
    for (std::size_t k = 0; k < static_cast<std::size_t>(lexed.aux_count); ++k)
      ASSERT_TRUE(words.aux[k].address == lexed.aux[k].address && words.aux[k].value == lexed.aux[k].value &&
                  words.aux[k].text == lexed.aux[k].text)
          << "line " << b_line << ": " << b_text;
  }
  EXPECT_GT(plain, lines);       // in both passes of the loop (the second from the line cache)
  EXPECT_GE(blocks - plain, 2);  // and X=R1 given as text in each
}

}  // namespace
