// The lexer of one NC line (NC-LEX-*, NC-WORD-*): scanning primitives here, the words in
// words.cpp, G codes in words_g_codes.cpp, system variables in words_system_variables.cpp.
// Every rejected input names its column and what is wrong (NC-ERR-1/3).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "cutcom/reader.hpp"
#include "nc_vocabulary.hpp"

namespace cutcom::lexer {

// NC text is ASCII: the C locale's classes, without a call per character.
constexpr bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_name_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }
constexpr char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// The character at the start of `at` as an error message shows it (NC-ERR-1): a printable one
// quoted, a whole UTF-8 character quoted, any other byte (a control byte, a NUL, a stray byte of
// another encoding) by its value, which a terminal would not show or would garble.
inline std::string character_text(std::string_view at) {
  if (at.empty()) return "the end of the line";
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(at[k]); };
  unsigned char c = byte(0);
  if (c >= 0x20 && c < 0x7f) return fmt::format("'{}'", at[0]);
  std::size_t length = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  bool whole = length != 0 && at.size() >= length;
  for (std::size_t k = 1; whole && k < length; ++k) whole = (byte(k) & 0xc0) == 0x80;
  if (whole) return fmt::format("'{}' (not ASCII)", at.substr(0, length));
  return fmt::format("byte 0x{:02X}", c);
}

// Modal groups of the G codes kept as actions or state, for "two of one group" (NC-LEX-3).
enum GGroup : unsigned {
  kGroupDwell = 1u << 0,        // group 2, non-modal: G4 G74 G75
  kGroupExactStop = 1u << 1,    // group 11: G9
  kGroupPathMode = 1u << 2,     // group 10: G60 G64 G641…G645
  kGroupStopWindow = 1u << 3,   // group 12: G601 G602 G603
  kGroupUnits = 1u << 4,        // group 13: G70 G71 G700 G710
  kGroupFeedType = 1u << 5,     // group 15: G93 G94 G95 G96 G97 G961 G971
  kGroupOffset = 1u << 6,       // group 8: G500 G54…G57 G505…G599
  kGroupSuppression = 1u << 7,  // group 9: G53 G153
  kGroupCornerFeed = 1u << 8,   // group 57: G62 G621 (FENDNORM)
  kGroupDialect = 1u << 9,      // group 47: G290 G291
};

// The M functions that do more than act (the lexer's aux() and the one-pass reading ask both).
inline bool ends_program(std::int64_t m) { return m == 2 || m == 30 || m == 17; }  // NC-END-1
inline bool changes_tool(std::int64_t m) { return m == 6; }                        // TOOL-CHANGE-1

// The common block (N, G0…G3, X Y Z, I J K, F with plain decimals, M and H) in one pass, into `out` as
// reset: true when the whole line was read so, as WordLexer would read it; false leaves the line
// to WordLexer (`out` partly written). `in_line_buffer`: the text is a line of a LineBuffer,
// followed by its '\n' or a zero and the buffer's padding, and is read where it lies; other text
// is copied first. plain_block.cpp.
bool read_plain_block(std::string_view text, BlockWords& out, bool in_line_buffer = false);

class WordLexer {
 public:
  WordLexer(std::string_view text, int line, BlockWords& out, const std::vector<std::string>& machine_cycles)
      : s_(text), line_(line), out_(out), machine_cycles_(machine_cycles) {}

  void run() {
    out_.reset(line_);
    if (read_plain_block(s_, out_)) {
      out_.plain = true;  // resolve leaves out the steps of the other words
      return;
    }
    general();
  }
  // The line read word by word, every word of the vocabulary (run() leaves only the lines
  // read_plain_block does not take to it).
  void general() {
    out_.reset(line_);
    skip_space();
    if (peek() == '%') return;  // NC-WORD-1: file header %_N_…_MPF / %: not a block
    block_start();
    while (true) {
      skip_space();
      if (at_end()) return;
      if (peek() == ';') return;  // NC-LEX-2: comment to end of line
      if (peek() == '$') {
        system_variable();
      } else {
        // NC-LEX-2: a comment in parentheses is the ISO dialect's (G291), which cutcom does not read.
        if (peek() == '(')
          fail(
              "unexpected character '(': a comment in parentheses is ISO dialect (G291); in the SINUMERIK "
              "dialect a comment starts with ';'");
        if (!is_letter(peek())) fail("unexpected character " + character_text(s_.substr(i_)));
        word();
      }
      ++out_.word_count;
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t at) const {
    throw InputError(line_, static_cast<int>(at) + 1, what);
  }
  [[noreturn]] void fail(const std::string& what) const { fail(what, i_); }

  bool at_end() const { return i_ >= s_.size(); }
  char peek(std::size_t ahead = 0) const { return i_ + ahead >= s_.size() ? '\0' : s_[i_ + ahead]; }
  void skip_space() {
    while (!at_end() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }

  // NC-WORD-2: block skip "/" or "/n" (skip levels off: the block runs), main block ":n",
  // and a jump label "NAME:" (nothing jumps to it without control flow; it is passed over).
  void block_start() {
    if (peek() == '/') {
      ++i_;
      if (is_digit(peek())) ++i_;
      skip_space();
    }
    if (peek() == ':' && is_digit(peek(1))) {
      std::size_t at = i_;
      ++i_;
      out_.number = integer("main block number");
      if (*out_.number < 0) fail("block number must not be negative", at);
      ++out_.word_count;
      return;
    }
    std::size_t j = i_;
    while (j < s_.size() && is_name_char(s_[j])) ++j;
    if (j > i_ + 1 && j < s_.size() && s_[j] == ':' && is_letter(s_[i_]) && (j + 1 >= s_.size() || s_[j + 1] != '=')) {
      i_ = j + 1;
    }
  }

  std::string letters() {  // measured first, then copied at once (most words are one letter)
    std::size_t from = i_;
    while (!at_end() && is_letter(s_[i_])) ++i_;
    std::string n(s_.substr(from, i_ - from));
    for (char& c : n) c = upper(c);
    return n;
  }
  // The rest of a multi-letter name: letters, digits and '_' (CYCLE832, GROUP_BEGIN, R_T).
  void name_tail(std::string& n) {
    while (!at_end() && is_name_char(s_[i_])) n.push_back(upper(s_[i_++]));
  }

  // A decimal literal [+-]digits[.digits]; must end at a word boundary.
  Decimal number(std::string_view what) {
    std::size_t start = i_;
    if (peek() == '+' || peek() == '-') ++i_;
    while (!at_end() && (is_digit(peek()) || peek() == '.')) ++i_;
    std::string_view text = s_.substr(start, i_ - start);
    Decimal::ParseResult r = Decimal::parse(text);
    if (!r.value) {
      if (text.empty() || text == "+" || text == "-") {
        if (is_letter(peek()) || peek() == '$' || peek() == '(')
          fail(fmt::format("{} needs a number: a variable or an expression ('{}') is written with '=' ({}=…)", what,
                           rest_of_word(), what),
               start);
        fail(fmt::format("{} needs a number", what), start);
      }
      switch (r.error) {
        case Decimal::ParseError::kTooManyDecimals:
          fail(fmt::format("{}: '{}' has more than {} decimal places", what, text, Decimal::kFractionDigits), start);
        case Decimal::ParseError::kOutOfRange:
          fail(fmt::format("{}: '{}' is out of range (magnitude above 10^12)", what, text), start);
        case Decimal::ParseError::kSyntax:
          fail(fmt::format("{}: '{}' is not a number", what, text), start);
      }
    }
    if (!at_end() && (is_digit(peek()) || peek() == '.' || peek() == '_'))
      fail(fmt::format("{}: malformed number", what));
    if (!at_end() && (peek() == '+' || peek() == '-' || peek() == '*' || peek() == '/'))
      fail(fmt::format("{}: an expression is written with '=' ({}=…)", what, what));
    return *r.value;
  }
  std::string rest_of_word() const {
    std::size_t j = i_;
    while (j < s_.size() && (is_name_char(s_[j]) || s_[j] == '$')) ++j;
    return std::string(s_.substr(i_, std::max<std::size_t>(j - i_, 1)));
  }

  std::int64_t integer(std::string_view what) {
    std::size_t start = i_;
    // Digits alone (G1, D1, N10; at most 12, below number()'s limit) read directly: the value and
    // the checks of number() and to_integer() for them, without a decimal between.
    std::size_t j = i_;
    std::int64_t digits_value = 0;
    while (j < s_.size() && j - i_ < 12 && is_digit(s_[j])) digits_value = digits_value * 10 + (s_[j++] - '0');
    char after = j < s_.size() ? s_[j] : '\0';
    if (j > i_ && !is_digit(after) && std::string_view(".+-*/_").find(after) == std::string_view::npos) {
      i_ = j;
      return digits_value;
    }
    Decimal d = number(what);
    auto v = d.to_integer();
    if (!v) fail(fmt::format("{} needs a whole number, not '{}'", what, d.to_string()), start);
    return *v;
  }

  // An unsigned whole number written with digits only (indices of system variables).
  std::int64_t digits(std::string_view what) {
    std::size_t start = i_;
    std::int64_t v = 0;
    while (!at_end() && is_digit(peek())) {
      v = v * 10 + (s_[i_++] - '0');
      if (v > 1'000'000'000) fail(fmt::format("{} is out of range", what), start);
    }
    if (i_ == start) fail(fmt::format("{} expected", what));
    return v;
  }

  bool equals() {
    skip_space();
    if (peek() != '=' || peek(1) == '=') return false;
    ++i_;
    skip_space();
    return true;
  }

  // AC(v), IC(v), PM(v), PR(v) wrappers after '='.
  bool wrapper(std::string_view fn) {
    if (s_.size() - i_ < fn.size() + 1) return false;
    for (std::size_t k = 0; k < fn.size(); ++k)
      if (upper(s_[i_ + k]) != fn[k]) return false;
    std::size_t j = i_ + fn.size();
    while (j < s_.size() && s_[j] == ' ') ++j;
    if (j >= s_.size() || s_[j] != '(') return false;
    i_ = j + 1;
    return true;
  }
  void close_paren(std::string_view what) {
    skip_space();
    if (peek() != ')') fail(fmt::format("{}: ')' expected", what));
    ++i_;
  }

  // A string in double quotes at the cursor, without them; `what` names it in the error.
  std::string quoted(std::string_view what) {
    ++i_;  // the opening quote
    std::size_t start = i_;
    while (!at_end() && peek() != '"') ++i_;
    if (at_end()) fail(fmt::format("{}: closing '\"' expected", what));
    std::string text(s_.substr(start, i_ - start));
    ++i_;
    return text;
  }

  template <class T>
  void set_once(Opt<T>& slot, T value, std::string_view what, std::size_t at) {
    if (slot) fail(fmt::format("{} programmed twice in one block", what), at);
    slot = value;
  }

  // Value with optional AC()/IC() (axes, centre, DISCL, DISRP).
  void positional(AxisWord& slot, std::string_view what, std::size_t at, bool allow_ic, bool need_eq) {
    if (slot.present) fail(fmt::format("{} programmed twice in one block", what), at);
    AxisWord w;
    w.present = true;
    bool eq = equals();
    if (need_eq && !eq) fail(fmt::format("{} needs '='", what));
    if (eq && wrapper("AC")) {
      skip_space();
      w.value = number(what);
      w.mode = ValueMode::kAbsolute;
      close_paren(what);
    } else if (eq && wrapper("IC")) {
      if (!allow_ic) fail(fmt::format("{}=IC(...) is not allowed", what));
      skip_space();
      w.value = number(what);
      w.mode = ValueMode::kIncremental;
      close_paren(what);
    } else {
      w.value = number(what);
    }
    slot = w;
  }

  Decimal plain_value(std::string_view what, bool need_eq) {
    bool eq = equals();
    if (need_eq && !eq) fail(fmt::format("{} needs '=' (write {}=...)", what, what));
    return number(what);
  }

  // --- actions (NC-WORD-*) ----------------------------------------------------------------------
  void add_action(AuxFunction a, std::size_t at) {
    if (out_.aux_count == BlockWords::kMaxAux)
      fail(fmt::format("more than {} actions (M, H, S, G4, MSG, …) in one block", BlockWords::kMaxAux), at);
    out_.aux[static_cast<std::size_t>(out_.aux_count++)] = std::move(a);
  }
  void add_text_action(std::string text, std::size_t at) {
    AuxFunction a;
    a.address = 0;
    a.text = std::move(text);
    add_action(std::move(a), at);
  }
  // An action word as written, its names in capitals as the control reads them (s1200 is S1200);
  // quoted text (MSG("…")) keeps its case.
  std::string written(std::size_t from) const {
    std::string w(s_.substr(from, i_ - from));
    bool quoted = false;
    for (char& c : w) {
      if (c == '"') quoted = !quoted;
      if (!quoted) c = upper(c);
    }
    return w;
  }

  // A value of an action word: a number, or NAME(number) such as DC(90) or ACP(0).
  void action_value(std::string_view what) {
    skip_space();
    if (is_letter(peek())) {
      std::size_t at = i_;
      std::string fn = letters();
      if (!is_action_value_wrapper(fn))
        fail(fmt::format("{} needs a number: a variable or an expression ('{}') is written with '=' ({}=…)", what, fn,
                         what),
             at);
      skip_space();
      if (peek() != '(') fail(fmt::format("{}: '(' expected after {}", what, fn));
      ++i_;
      skip_space();
      number(what);
      close_paren(what);
      return;
    }
    number(what);
  }

  // The balanced "(…)" after a call-form word, strings included; returns nothing, checks it closes.
  void balanced_arguments(std::string_view what, std::size_t at) {
    skip_space();
    if (peek() != '(') fail(fmt::format("{} needs its arguments in '(…)'", what));
    int depth = 0;
    bool in_string = false;
    for (; !at_end(); ++i_) {
      char c = s_[i_];
      if (in_string) {
        if (c == '"') in_string = false;
        continue;
      }
      if (c == '"') in_string = true;
      if (c == ';') break;
      if (c == '(') ++depth;
      if (c == ')' && --depth == 0) {
        ++i_;
        return;
      }
    }
    fail(fmt::format("{}: ')' expected at the end of its arguments", what), at);
  }

  void g_group(unsigned group, const char* name, std::size_t at) {
    if (groups_ & group) fail(fmt::format("two G codes of the {} group in one block", name), at);
    groups_ |= group;
  }

  void g_code(std::size_t at);
  // M and H (NC-LEX-5); M1=3 style addresses with a spindle or channel number are kept as written.
  void aux(char address, std::size_t at);
  // After a letter: digits, blanks and '=' (M1=3, S1=1000): an address with an extension.
  bool extended_address_follows() const;
  // S (NC-WORD-3): spindle speed, or with G4 the dwell in revolutions.
  void spindle(std::size_t at);
  void keyword(const std::string& n, std::size_t at);
  void keyword_value(const std::string& n, std::size_t at);
  // RND= CHF= CHR= RNDM= FRC= FRCM=: a length or feed, not negative.
  void contour_value(const std::string& n, std::size_t at);
  // Multi-letter words other than the compensation parameters.
  void named_word(const std::string& n, std::size_t at);
  // NC-CYCLE-3: a cycle of the machine named on the command line, as a standard cycle.
  bool machine_cycle(const std::string& n) const {
    return std::find(machine_cycles_.begin(), machine_cycles_.end(), n) != machine_cycles_.end();
  }
  void not_simulated_cycle(const std::string& n, std::size_t at);
  void explicit_machine_call(const std::string& n, std::size_t at);
  // NC-WORD-9: ID=n/IDS=n, WHEN/WHENEVER/EVERY/FROM … DO …: the rest of the block, kept as written.
  void synchronized_action(std::size_t at);
  void word();
  // T (TOOL-NAME-1): T5, T=5, T="NAME", T1=5 (tool for spindle 1).
  void tool(std::size_t at);
  void rotary_axis(const std::string& n, std::size_t at);
  bool axis_as_action(const std::string& n, std::size_t at);
  void plane_axis_after_rotary(std::size_t at);
  void orientation(const std::string& n, std::size_t at);
  // `(…)` after a word, if there: read whole (balanced); false (nothing read) otherwise.
  bool optional_arguments(const std::string& n, std::size_t at);
  static std::string_view orientation_literal(std::string_view n);
  static std::string area_limit_message(int g) {
    return fmt::format(
        "G{} after an axis word: a working area limitation (G{} X… Z…) names its axes after G{}, and they move "
        "nothing",
        g, g, g);
  }
  // System variables (NC-LEX-6): tool data $TC_DPn[t,d]=v and $TC_TP2[t]="NAME".
  void system_variable();
  void index_open(std::string_view what);
  void index_close();
  void tool_edge_data(int p, std::size_t at);
  std::pair<std::int64_t, std::int64_t> tool_edge_index(std::string_view what);
  // $TC_TP2[t]="NAME": the tool's name (TOOL-NAME-1).
  void tool_name_data(std::size_t at);
  // $TC_SCPkp[t,d]=v, $TC_ECPkp[t,d]=v: sum and setup offsets (TOOL-SUM-1).
  void sum_offset_data(const std::string& full, std::size_t at);
  // $TC_TP1, $TC_TP3 … $TC_TP11 (duplo number, size, place type, …): no effect on the path.
  void ignored_tool_parameter(std::string_view what);

  std::string_view s_;
  std::size_t i_ = 0;
  std::string_view rotary_name_;  // NC-WORD-8: the rotary axis word in the block so far (a literal)
  int area_limit_ = 0;            // NC-WORD-8: G25 or G26 in the block
  int line_;
  BlockWords& out_;
  const std::vector<std::string>& machine_cycles_;  // NC-CYCLE-3
  unsigned groups_ = 0;
};

}  // namespace cutcom::lexer
