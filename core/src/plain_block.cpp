// The common block read in one pass: what CAM programs are made of, N, G0…G3, X Y Z, I J K and
// F with plain decimals, M and H functions ("N120 G1 X12.5 Y-3 F800", "G01X1.Y2.", "X5 M8",
// "g2 x4 y0 i1 j0 ; a comment").
// It fills the block's words exactly as the word lexer does (NC-LEX-*, NC-WORD-*: the same
// values, the same word count), or leaves the line to it: anything else on the line, a word
// twice, a negative feed, a number the lexer rejects or reads in its own way (an expression
// after it) all go to the lexer, which reads or rejects them with its message.
// tests/plain_block_test.cpp holds the two readings equal.
#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

#include "cutcom/line_buffer.hpp"
#include "word_lexer.hpp"

namespace cutcom::lexer {

namespace {
// A number's digits are taken eight at a time (issue "Performance": digit by digit, a sixth of
// the reader's work), so eight bytes after the line must be readable: a LineBuffer's line has
// them; other text is read from a copy with eight zero bytes after it.
constexpr std::size_t kLongestCopied = 256;  // a longer line (not in a LineBuffer) goes to the lexer
constexpr std::size_t kPadding = 8;
static_assert(LineBuffer::kPadding >= kPadding);

// What a character is to the one pass, from a table (chains of comparisons per character cost 80
// instructions a block more): bits of the classes below, and the word a letter begins.
enum CharClass : std::uint8_t {
  kSpace = 1,           // between words
  kValueStart = 2,      // a value's first character: a digit, point or sign
  kAfterValue = 4,      // may follow a value: a space, a comment or the next word's letter
  kNotAfterNumber = 8,  // makes a number the lexer's: a point, sign, '_', '*' or '/'
};
enum class Word : std::uint8_t { kNone, kN, kG, kX, kY, kZ, kI, kJ, kK, kF, kM, kH };
struct CharTable {
  std::uint8_t cls[256] = {};
  Word word[256] = {};
};
constexpr CharTable kChars = [] {
  CharTable t;
  auto set = [&](char c, int bits) { t.cls[static_cast<unsigned char>(c)] |= static_cast<std::uint8_t>(bits); };
  for (char c : {' ', '\t', '\r'}) set(c, kSpace | kAfterValue);
  set(';', kAfterValue);
  for (char c = '0'; c <= '9'; ++c) set(c, kValueStart);
  for (char c : {'.', '+', '-'}) set(c, kValueStart | kNotAfterNumber);
  for (char c : {'_', '*', '/'}) set(c, kNotAfterNumber);
  for (char c = 'A'; c <= 'Z'; ++c) set(c, kAfterValue), set(static_cast<char>(c - 'A' + 'a'), kAfterValue);
  const std::pair<char, Word> words[] = {{'N', Word::kN}, {'G', Word::kG}, {'X', Word::kX}, {'Y', Word::kY},
                                         {'Z', Word::kZ}, {'I', Word::kI}, {'J', Word::kJ}, {'K', Word::kK},
                                         {'F', Word::kF}, {'M', Word::kM}, {'H', Word::kH}};
  for (auto [c, w] : words)  // NC-LEX-1: letters are case-insensitive
    t.word[static_cast<unsigned char>(c)] = t.word[static_cast<unsigned char>(c - 'A' + 'a')] = w;
  return t;
}();
inline std::uint8_t class_of(char c) { return kChars.cls[static_cast<unsigned char>(c)]; }

// The run of digits at p (p padded): its length, up to 8, and the value of those digits. The
// characters become their digit values (XOR '0'); a byte is no digit where the result or the
// result plus 6 reaches 16 (a carry from a byte above 0xf9 only reaches bytes after it). The
// value is made in three steps, pairs of digits, then fours, then eight, each a multiply and
// a shift on all lanes at once; the digits are moved to the high bytes first, so that the bytes
// below them read as leading zeros.
int digit_run(const char* p, std::uint64_t& value) {
  static_assert(std::endian::native == std::endian::little, "the first character is the lowest byte");
  std::uint64_t x;
  std::memcpy(&x, p, 8);
  x ^= 0x3030303030303030u;
  std::uint64_t not_digit = (x | (x + 0x0606060606060606u)) & 0xf0f0f0f0f0f0f0f0u;
  int count = not_digit ? std::countr_zero(not_digit) / 8 : 8;
  if (count == 0) return value = 0, 0;
  x <<= 8 * (8 - count);
  x = (x * 10 + (x >> 8)) & 0x00ff00ff00ff00ffu;    // two digits in each 16-bit lane
  x = (x * 100 + (x >> 16)) & 0x0000ffff0000ffffu;  // four in each 32-bit lane
  value = (x * 10000 + (x >> 32)) & 0xffffffffu;    // all eight
  return count;
}

// A number of eight digits or more before or after the point, by Decimal::read: out of line, so
// that the common number's few instructions are inlined where a word is read.
[[gnu::noinline]] bool long_number(const char*& p, const char* end, Decimal& out) {
  Decimal::ParseError error;
  return Decimal::read(p, end, out, error);
}

// A number at p as WordLexer::number takes it (a sign, then digits and points, valued as
// Decimal::parse values them), its end a word's (not '_', a sign, '*' or '/'); false leaves it to
// the lexer. Up to 7 digits before and after the point from digit runs (p padded), longer ones
// by Decimal::read.
inline bool plain_number(const char*& p, const char* end, Decimal& out) {
  const char* q = p;
  bool negative = *q == '-';
  if (*q == '+' || *q == '-') ++q;
  std::uint64_t integer = 0, fraction = 0;
  int before = digit_run(q, integer), after = 0;
  q += before;
  if (before < 8 && *q == '.') after = digit_run(++q, fraction), q += after;
  if (before == 8 || after == 8) {  // a long number (but a plain one still)
    if (!long_number(p, end, out)) return false;
  } else {
    if (before == 0 && after == 0) return false;                 // a sign or a point alone: the lexer's error
    Int128 units = Decimal::units_of(integer, fraction, after);  // below 10^16: no range check
    out = Decimal::from_units(negative ? -units : units);
    p = q;
  }
  // A second point belongs to the lexer's span (Decimal::parse rejects it there).
  return !(class_of(*p) & kNotAfterNumber);
}

// Digits alone (N, G), as WordLexer::integer reads them directly: at most 12, not followed by a
// digit, point, sign, '*', '/' or '_' (p padded: the zeros after the line end the digits).
bool plain_integer(const char*& p, std::int64_t& out) {
  const char* from = p;
  std::int64_t v = 0;
  for (; is_digit(*p); ++p) {
    if (p - from == 12) return false;
    v = v * 10 + (*p - '0');
  }
  if (p == from || (class_of(*p) & kNotAfterNumber)) return false;
  out = v;
  return true;
}

// The value is written where it belongs: built aside and copied, its two halves were read back as
// one 16-byte load the CPU cannot forward from two 8-byte stores (a fifth of this pass's time). A
// line left to the lexer half read is read anew: the lexer resets the block first.
bool plain_axis(const char*& p, const char* end, AxisWord& slot) {
  if (slot.present) return false;  // twice: the lexer's error
  if (!plain_number(p, end, slot.value)) return false;
  slot.present = true;
  return true;
}

// An M or H function of digits alone (M8, H2), an action as WordLexer::aux adds it (NC-WORD-2).
// The M functions that do more than act are the lexer's: M2, M30 and M17 end the program
// (NC-END-1), M6 changes the tool (TOOL-CHANGE-1); so are M1=3 and the like (an extended
// address: the '=' after the digits is no word's letter) and a seventeenth action (the lexer's
// error).
bool plain_function(const char*& p, char address, BlockWords& out) {
  std::int64_t value = 0;
  if (out.aux_count == BlockWords::kMaxAux || !plain_integer(p, value)) return false;
  if (address == 'M' && (ends_program(value) || changes_tool(value))) return false;
  AuxFunction& a = out.aux[static_cast<std::size_t>(out.aux_count++)];
  a.address = address, a.value = value;
  a.text.clear();  // the slot's text is stale (BlockWords::reset keeps it)
  return true;
}

// [p, end) followed by a '\n' or a zero and at least kPadding readable bytes. The text is read
// where it lies when it can be: eight digits loaded from a copy just written a byte or a word at
// a time wait until those stores are written (the CPU forwards no load from several stores).
bool read_plain(const char* p, const char* end, BlockWords& out) {
  // The '\n' or zeros after the line are no space, value or word: only the tests of p against
  // `end` tell them from such a byte in the line (which leaves the line to the lexer).
  while (true) {
    while (class_of(*p) & kSpace) ++p;
    if (p == end || *p == ';') return true;  // NC-LEX-2: a comment to the end of the line
    Word word = kChars.word[static_cast<unsigned char>(*p++)];
    // A letter of the lexer's other words (H, M, FA, X1=, …) or a space before the value
    if (!(class_of(*p) & kValueStart)) return false;
    switch (word) {
      case Word::kN: {
        std::int64_t n = 0;
        if (out.number || !plain_integer(p, n)) return false;
        out.number = n;
        break;
      }
      case Word::kG: {
        std::int64_t g = 0;
        if (out.motion || !plain_integer(p, g) || g > 3) return false;
        static constexpr Motion kMotion[] = {Motion::kRapid, Motion::kLinear, Motion::kArcCw, Motion::kArcCcw};
        out.motion = kMotion[g];
        break;
      }
      case Word::kX:
      case Word::kY:
      case Word::kZ:
        if (!plain_axis(p, end, out.axis[static_cast<std::size_t>(word) - static_cast<std::size_t>(Word::kX)]))
          return false;
        break;
      case Word::kI:
      case Word::kJ:
      case Word::kK:
        if (!plain_axis(p, end, out.centre[static_cast<std::size_t>(word) - static_cast<std::size_t>(Word::kI)]))
          return false;
        break;
      case Word::kF:  // NC-LEX-5: F is not negative
        if (out.feed || !plain_number(p, end, out.feed.emplace()) || out.feed->sign() < 0) return false;
        break;
      case Word::kM:
        if (!plain_function(p, 'M', out)) return false;
        break;
      case Word::kH:
        if (!plain_function(p, 'H', out)) return false;
        break;
      case Word::kNone:
        return false;
    }
    // What may follow a value: a space, a comment, the line's end or the next word's letter
    // (NC-LEX-1: words without spaces between them, G1X10Y20).
    if (p < end && !(class_of(*p) & kAfterValue)) return false;
    ++out.word_count;
  }
}
}  // namespace

bool read_plain_block(std::string_view text, BlockWords& out, bool in_line_buffer) {
  if (in_line_buffer) return read_plain(text.data(), text.data() + text.size(), out);
  if (text.size() > kLongestCopied) return false;
  char line[kLongestCopied + kPadding];
  std::memcpy(line, text.data(), text.size());
  std::memset(line + text.size(), 0, kPadding);
  return read_plain(line, line + text.size(), out);
}

}  // namespace cutcom::lexer
