// The common block read in one pass: what CAM programs are made of, N, G0…G3, X Y Z, I J K and
// F with plain decimals ("N120 G1 X12.5 Y-3 F800", "G01X1.Y2.", "g2 x4 y0 i1 j0 ; a comment").
// It fills the block's words exactly as the word lexer does (NC-LEX-*, NC-WORD-*: the same
// values, the same word count), or leaves the line to it: anything else on the line, a word
// twice, a negative feed, a number the lexer rejects or reads in its own way (an expression
// after it) all go to the lexer, which reads or rejects them with its message.
// tests/plain_block_test.cpp holds the two readings equal.
#include <cstdint>

#include "word_lexer.hpp"

namespace cutcom::lexer {

namespace {
constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// A number at p as WordLexer::number takes it (a sign, then digits and points, valued as
// Decimal::parse values them), its end a word's (not '_', a sign, '*' or '/'); false leaves it to
// the lexer.
bool plain_number(const char*& p, const char* end, Decimal& out) {
  Decimal::ParseError error;
  if (!Decimal::read(p, end, out, error)) return false;
  // A second point belongs to the lexer's span (Decimal::parse rejects it there).
  return !(p < end && (*p == '.' || *p == '_' || *p == '+' || *p == '-' || *p == '*' || *p == '/'));
}

// Digits alone (N, G), as WordLexer::integer reads them directly: at most 12, not followed by a
// digit, point, sign, '*', '/' or '_'.
bool plain_integer(const char*& p, const char* end, std::int64_t& out) {
  const char* from = p;
  std::int64_t v = 0;
  for (; p < end && is_digit(*p); ++p) {
    if (p - from == 12) return false;
    v = v * 10 + (*p - '0');
  }
  if (p == from) return false;
  if (p < end && (*p == '.' || *p == '_' || *p == '+' || *p == '-' || *p == '*' || *p == '/')) return false;
  out = v;
  return true;
}

bool plain_axis(const char*& p, const char* end, AxisWord& slot) {
  if (slot.present) return false;  // twice: the lexer's error
  AxisWord w;
  w.present = true;
  if (!plain_number(p, end, w.value)) return false;
  slot = w;
  return true;
}
}  // namespace

bool read_plain_block(std::string_view text, BlockWords& out) {
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    while (p < end && is_space(*p)) ++p;
    if (p == end || *p == ';') return true;  // NC-LEX-2: a comment to the end of the line
    char letter = upper(*p++);               // NC-LEX-1: letters are case-insensitive
    // A letter of the lexer's other words (H, M, FA, X1=, …) or a space before the value
    if (p == end || !(is_digit(*p) || *p == '.' || *p == '+' || *p == '-')) return false;
    switch (letter) {
      case 'N': {
        std::int64_t n = 0;
        if (out.number || !plain_integer(p, end, n)) return false;
        out.number = n;
        break;
      }
      case 'G': {
        std::int64_t g = 0;
        if (out.motion || !plain_integer(p, end, g) || g > 3) return false;
        static constexpr Motion kMotion[] = {Motion::kRapid, Motion::kLinear, Motion::kArcCw, Motion::kArcCcw};
        out.motion = kMotion[g];
        break;
      }
      case 'X':
      case 'Y':
      case 'Z':
        if (!plain_axis(p, end, out.axis[static_cast<std::size_t>(letter - 'X')])) return false;
        break;
      case 'I':
      case 'J':
      case 'K':
        if (!plain_axis(p, end, out.centre[static_cast<std::size_t>(letter - 'I')])) return false;
        break;
      case 'F': {
        Decimal f;
        if (out.feed || !plain_number(p, end, f) || f.sign() < 0) return false;  // NC-LEX-5: F is not negative
        out.feed = f;
        break;
      }
      default:
        return false;
    }
    // What may follow a value: a space, a comment, the line's end or the next word's letter
    // (NC-LEX-1: words without spaces between them, G1X10Y20).
    if (p < end && !is_space(*p) && *p != ';' && !is_letter(*p)) return false;
    ++out.word_count;
  }
}

}  // namespace cutcom::lexer
