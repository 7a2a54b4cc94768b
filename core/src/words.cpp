// NC-LEX-*: the words of one block. Every rejected input names its column and what is wrong.
#include <fmt/format.h>

#include <cctype>

#include "cutcom/reader.hpp"

namespace cutcom {

InputError::InputError(int line, int column, const std::string& what)
    : std::runtime_error(fmt::format("line {}, column {}: {}", line, column, what)),
      line_(line),
      column_(column),
      detail_(what) {}

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }

class WordLexer {
 public:
  WordLexer(std::string_view text, int line, BlockWords& out) : s_(text), line_(line), out_(out) {}

  void run() {
    out_ = BlockWords{};
    out_.line = line_;
    while (true) {
      skip_space();
      if (at_end()) return;
      if (peek() == ';') return;  // NC-LEX-2: comment to end of line
      if (peek() == '$') {
        tool_data();
      } else {
        if (!is_letter(peek())) fail(fmt::format("unexpected character '{}'", peek()));
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
  char peek() const { return at_end() ? '\0' : s_[i_]; }
  void skip_space() {
    while (!at_end() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }

  std::string name() {
    std::string n;
    while (!at_end() && is_letter(s_[i_])) n.push_back(upper(s_[i_++]));
    return n;
  }

  // A decimal literal [+-]digits[.digits]; must end at a word boundary.
  Decimal number(const std::string& what) {
    std::size_t start = i_;
    if (peek() == '+' || peek() == '-') ++i_;
    while (!at_end() && (is_digit(peek()) || peek() == '.')) ++i_;
    std::string_view text = s_.substr(start, i_ - start);
    Decimal::ParseResult r = Decimal::parse(text);
    if (!r.value) {
      if (text.empty() || text == "+" || text == "-") fail(fmt::format("{} needs a number", what), start);
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
    return *r.value;
  }

  std::int64_t integer(const std::string& what) {
    std::size_t start = i_;
    Decimal d = number(what);
    auto v = d.to_integer();
    if (!v) fail(fmt::format("{} needs a whole number, not '{}'", what, d.to_string()), start);
    return *v;
  }

  // An unsigned whole number written with digits only (indices of system variables).
  std::int64_t digits(const std::string& what) {
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
    if (peek() != '=') return false;
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
  void close_paren(const std::string& what) {
    skip_space();
    if (peek() != ')') fail(fmt::format("{}: ')' expected", what));
    ++i_;
  }

  template <class T>
  void set_once(Opt<T>& slot, T value, const std::string& what, std::size_t at) {
    if (slot) fail(fmt::format("{} programmed twice in one block", what), at);
    slot = value;
  }

  // Value with optional AC()/IC() (axes, centre, DISCL, DISRP).
  void positional(AxisWord& slot, const std::string& what, std::size_t at, bool allow_ic, bool need_eq) {
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

  Decimal plain_value(const std::string& what, bool need_eq) {
    bool eq = equals();
    if (need_eq && !eq) fail(fmt::format("{} needs '=' (write {}=...)", what, what));
    return number(what);
  }

  void g_code(std::size_t at) {
    skip_space();
    std::int64_t g = integer("G");
    auto group = [&](auto& slot, auto value, const char* group_name) {
      if (slot) fail(fmt::format("two G codes of the {} group in one block", group_name), at);
      slot = value;
    };
    BlockWords& o = out_;
    switch (g) {
      case 0:
        group(o.motion, Motion::kRapid, "motion");
        break;
      case 1:
        group(o.motion, Motion::kLinear, "motion");
        break;
      case 2:
        group(o.motion, Motion::kArcCw, "motion");
        break;
      case 3:
        group(o.motion, Motion::kArcCcw, "motion");
        break;
      case 17:
        group(o.plane, Plane::kG17, "plane");
        break;
      case 18:
        group(o.plane, Plane::kG18, "plane");
        break;
      case 19:
        group(o.plane, Plane::kG19, "plane");
        break;
      case 40:
        group(o.side, Side::kOff, "tool radius compensation");
        break;
      case 41:
        group(o.side, Side::kLeft, "tool radius compensation");
        break;
      case 42:
        group(o.side, Side::kRight, "tool radius compensation");
        break;
      case 60:
        group(o.path_mode, PathMode::kG60, "exact stop / continuous path");
        break;
      case 64:
        group(o.path_mode, PathMode::kG64, "exact stop / continuous path");
        break;
      case 90:
        group(o.absolute, true, "dimensions");
        break;
      case 91:
        group(o.absolute, false, "dimensions");
        break;
      case 94:
        group(o.feed_type, FeedType::kG94, "feed type");
        break;
      case 95:
        group(o.feed_type, FeedType::kG95, "feed type");
        break;
      case 140:
        group(o.sar_side, SarSide::kG140, "SAR side");
        break;
      case 141:
        group(o.sar_side, SarSide::kG141, "SAR side");
        break;
      case 142:
        group(o.sar_side, SarSide::kG142, "SAR side");
        break;
      case 143:
        group(o.sar_side, SarSide::kG143, "SAR side");
        break;
      case 147:
        group(o.sar_contour, SarContour::kG147, "SAR contour");
        break;
      case 148:
        group(o.sar_contour, SarContour::kG148, "SAR contour");
        break;
      case 247:
        group(o.sar_contour, SarContour::kG247, "SAR contour");
        break;
      case 248:
        group(o.sar_contour, SarContour::kG248, "SAR contour");
        break;
      case 347:
        group(o.sar_contour, SarContour::kG347, "SAR contour");
        break;
      case 348:
        group(o.sar_contour, SarContour::kG348, "SAR contour");
        break;
      case 340:
        group(o.sar_segmentation, SarSegmentation::kG340, "SAR segmentation");
        break;
      case 341:
        group(o.sar_segmentation, SarSegmentation::kG341, "SAR segmentation");
        break;
      case 450:
        group(o.corner, CornerMode::kG450, "outer corner");
        break;
      case 451:
        group(o.corner, CornerMode::kG451, "outer corner");
        break;
      case 460:
        group(o.edge_strategy, EdgeStrategy::kG460, "approach/retraction (group 48)");
        break;
      case 461:
        group(o.edge_strategy, EdgeStrategy::kG461, "approach/retraction (group 48)");
        break;
      case 462:
        group(o.edge_strategy, EdgeStrategy::kG462, "approach/retraction (group 48)");
        break;
      default:
        fail(fmt::format("G{} is not supported by cutcom", g), at);
    }
  }

  void aux(char address, std::size_t at) {
    equals();
    std::int64_t v = integer(std::string(1, address));
    if (v < 0) fail(fmt::format("{}{}: auxiliary function numbers are not negative", address, v), at);
    if (out_.aux_count == BlockWords::kMaxAux)
      fail(fmt::format("more than {} auxiliary functions in one block", BlockWords::kMaxAux), at);
    out_.aux[static_cast<std::size_t>(out_.aux_count++)] = {address, v};
    if (address == 'M' && (v == 2 || v == 30)) out_.program_end = true;
  }

  void keyword_value(const std::string& n, std::size_t at) {
    if (n == "CR") {
      set_once(out_.cr, plain_value("CR", true), "CR", at);
    } else if (n == "OFFN") {
      set_once(out_.offn, plain_value("OFFN", true), "OFFN", at);
    } else if (n == "DISC") {
      Decimal v = plain_value("DISC", true);
      if (v.sign() < 0) fail("DISC must not be negative", at);
      set_once(out_.disc, v, "DISC", at);
    } else if (n == "DISR") {
      set_once(out_.disr, plain_value("DISR", true), "DISR", at);
    } else if (n == "DISCL") {
      positional(out_.discl, "DISCL", at, false, true);
    } else if (n == "DISRP") {
      positional(out_.disrp, "DISRP", at, false, true);
    } else if (n == "FAD") {
      if (out_.fad) fail("FAD programmed twice in one block", at);
      if (!equals()) fail("FAD needs '=' (write FAD=...)");
      bool pm = wrapper("PM");
      if (pm || wrapper("PR")) {
        out_.fad_mode = pm ? FadMode::kPm : FadMode::kPr;
        skip_space();
        out_.fad = number("FAD");
        close_paren("FAD");
      } else {
        out_.fad = number("FAD");
      }
      if (out_.fad->sign() <= 0) fail("FAD must be positive", at);
    } else {
      fail(fmt::format("unknown address '{}'", n), at);
    }
  }

  void word() {
    std::size_t at = i_;
    std::string n = name();
    // Keywords without a value (NC-LEX-5).
    if (n == "NORM") return set_once(out_.approach, ApproachMode::kNorm, "NORM/KONT", at);
    if (n == "KONT") return set_once(out_.approach, ApproachMode::kKont, "NORM/KONT", at);
    if (n == "KONTC") return set_once(out_.approach, ApproachMode::kKontC, "NORM/KONT", at);
    if (n == "KONTT") return set_once(out_.approach, ApproachMode::kKontT, "NORM/KONT", at);
    if (n == "CDON") return set_once(out_.collision, CollisionMode::kCdon, "CDON/CDOF", at);
    if (n == "CDOF") {
      if (peek() == '2' && (i_ + 1 >= s_.size() || !is_digit(s_[i_ + 1]))) {
        ++i_;
        return set_once(out_.collision, CollisionMode::kCdof2, "CDON/CDOF", at);
      }
      return set_once(out_.collision, CollisionMode::kCdof, "CDON/CDOF", at);
    }
    if (n == "STOPRE") {
      out_.stopre = true;
      return;
    }
    if (n.size() > 1) return keyword_value(n, at);
    skip_space();
    switch (n[0]) {
      case 'N': {
        if (out_.number) fail("N programmed twice in one block", at);
        std::int64_t v = integer("N");
        if (v < 0) fail("block number must not be negative", at);
        out_.number = v;
        return;
      }
      case 'G':
        return g_code(at);
      case 'M':
        return aux('M', at);
      case 'H':
        return aux('H', at);
      case 'T': {
        equals();
        std::int64_t v = integer("T");
        if (v < 0) fail("tool number must not be negative", at);
        return set_once(out_.tool, v, "T", at);
      }
      case 'D': {
        equals();
        std::int64_t v = integer("D");
        if (v < 0) fail("D number must not be negative", at);
        return set_once(out_.edge, v, "D", at);
      }
      case 'F': {
        Decimal v = plain_value("F", false);
        if (v.sign() < 0) fail("feed must not be negative", at);
        return set_once(out_.feed, v, "F", at);
      }
      case 'X':
        return positional(out_.axis[0], "X", at, true, false);
      case 'Y':
        return positional(out_.axis[1], "Y", at, true, false);
      case 'Z':
        return positional(out_.axis[2], "Z", at, true, false);
      case 'I':
        return positional(out_.centre[0], "I", at, true, false);
      case 'J':
        return positional(out_.centre[1], "J", at, true, false);
      case 'K':
        return positional(out_.centre[2], "K", at, true, false);
      default:
        fail(fmt::format("unknown address '{}'", n), at);
    }
  }

  // $TC_DPn[t,d]=value (NC-LEX-6).
  void tool_data() {
    std::size_t at = i_;
    ++i_;
    std::string n = name();
    if (n != "TC" || peek() != '_') fail("only $TC_DP1, $TC_DP6 and $TC_DP15 system variables are supported", at);
    ++i_;
    n = name();
    if (n != "DP") fail("only $TC_DP1, $TC_DP6 and $TC_DP15 system variables are supported", at);
    std::int64_t p = integer("$TC_DP parameter");
    if (p != 1 && p != 6 && p != 15)
      fail(fmt::format("$TC_DP{} is not supported (only $TC_DP1, $TC_DP6, $TC_DP15)", p), at);
    skip_space();
    if (peek() != '[') fail("'[' expected after $TC_DP" + std::to_string(p));
    ++i_;
    skip_space();
    std::int64_t t = digits("tool number");
    skip_space();
    if (peek() != ',') fail("',' expected between tool and edge number (write $TC_DPn[t,d])");
    ++i_;
    skip_space();
    std::int64_t d = digits("edge number");
    skip_space();
    if (peek() != ']') fail("']' expected");
    ++i_;
    if (!equals()) fail("'=' expected");
    Decimal v = number("$TC_DP value");
    if (t < 1 || d < 1) fail("tool and edge numbers start at 1", at);
    if (out_.tool_data_count == BlockWords::kMaxToolData) fail("too many tool data assignments in one block", at);
    out_.tool_data[static_cast<std::size_t>(out_.tool_data_count++)] = {static_cast<int>(p), static_cast<int>(t),
                                                                        static_cast<int>(d), v};
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int line_;
  BlockWords& out_;
};

}  // namespace

void parse_block_words(std::string_view text, int line, BlockWords& out) { WordLexer(text, line, out).run(); }

}  // namespace cutcom
