// NC-LEX-*, NC-WORD-*: the words of one block. Every rejected input names its column and what is
// wrong; an unknown or unsupported word is named whole, in one wording (NC-ERR-3).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "cutcom/reader.hpp"
#include "nc_vocabulary.hpp"

namespace cutcom {

InputError::InputError(int line, int column, const std::string& what)
    : std::runtime_error(fmt::format("line {}, column {}: {}", line, column, what)),
      line_(line),
      column_(column),
      detail_(what) {}

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }
char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }

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
};

class WordLexer {
 public:
  WordLexer(std::string_view text, int line, BlockWords& out) : s_(text), line_(line), out_(out) {}

  void run() {
    out_ = BlockWords{};
    out_.line = line_;
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

  std::string letters() {
    std::string n;
    while (!at_end() && is_letter(s_[i_])) n.push_back(upper(s_[i_++]));
    return n;
  }
  // The rest of a multi-letter name: letters, digits and '_' (CYCLE832, GROUP_BEGIN, R_T).
  void name_tail(std::string& n) {
    while (!at_end() && is_name_char(s_[i_])) n.push_back(upper(s_[i_++]));
  }

  // A decimal literal [+-]digits[.digits]; must end at a word boundary.
  Decimal number(const std::string& what) {
    std::size_t start = i_;
    if (peek() == '+' || peek() == '-') ++i_;
    while (!at_end() && (is_digit(peek()) || peek() == '.')) ++i_;
    std::string_view text = s_.substr(start, i_ - start);
    Decimal::ParseResult r = Decimal::parse(text);
    if (!r.value) {
      if (text.empty() || text == "+" || text == "-") {
        if (is_letter(peek()) || peek() == '$' || peek() == '(')
          fail(fmt::format("{} needs a number: expressions and variables ('{}') are not supported yet", what,
                           rest_of_word()),
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
      fail(fmt::format("{}: expressions are not supported yet", what));
    return *r.value;
  }
  std::string rest_of_word() const {
    std::size_t j = i_;
    while (j < s_.size() && (is_name_char(s_[j]) || s_[j] == '$')) ++j;
    return std::string(s_.substr(i_, std::max<std::size_t>(j - i_, 1)));
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
  std::string written(std::size_t from) const { return std::string(s_.substr(from, i_ - from)); }

  // A value of an action word: a number, or NAME(number) such as DC(90) or ACP(0).
  void action_value(const std::string& what) {
    skip_space();
    if (is_letter(peek())) {
      std::size_t at = i_;
      std::string fn = letters();
      if (!is_action_value_wrapper(fn))
        fail(fmt::format("{} needs a number: expressions and variables ('{}') are not supported yet", what, fn), at);
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
  void balanced_arguments(const std::string& what, std::size_t at) {
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

  void g_code(std::size_t at) {
    skip_space();
    std::int64_t g = integer("G");
    auto group = [&](auto& slot, auto value, const char* group_name) {
      if (slot) fail(fmt::format("two G codes of the {} group in one block", group_name), at);
      slot = value;
    };
    auto action = [&](unsigned grp, const char* group_name) {
      g_group(grp, group_name, at);
      add_text_action(fmt::format("G{}", g), at);
    };
    BlockWords& o = out_;
    switch (g) {
      case 0:
        if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
        return group(o.motion, Motion::kRapid, "motion");
      case 1:
        if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
        return group(o.motion, Motion::kLinear, "motion");
      case 2:
        if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
        return group(o.motion, Motion::kArcCw, "motion");
      case 3:
        if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
        return group(o.motion, Motion::kArcCcw, "motion");
      case 4:  // NC-WORD-4: dwell; its F or S is the time or the revolutions
        g_group(kGroupDwell, "non-modal (G4/G74/G75)", at);
        o.dwell = true;
        return;
      case 9:  // NC-WORD-5: exact stop for this block
        return action(kGroupExactStop, "exact stop (G9)");
      case 17:
        return group(o.plane, Plane::kG17, "plane");
      case 18:
        return group(o.plane, Plane::kG18, "plane");
      case 19:
        return group(o.plane, Plane::kG19, "plane");
      case 40:
        return group(o.side, Side::kOff, "tool radius compensation");
      case 41:
        return group(o.side, Side::kLeft, "tool radius compensation");
      case 42:
        return group(o.side, Side::kRight, "tool radius compensation");
      case 53:
      case 153:  // NC-CYCLE-1: a move in machine coordinates is not simulated
        g_group(kGroupSuppression, "frame suppression (G53/G153)", at);
        o.not_simulated = fmt::format("G{}", g);
        return;
      case 60:
        g_group(kGroupPathMode, "exact stop / continuous path", at);
        return group(o.path_mode, PathMode::kG60, "exact stop / continuous path");
      case 64:
      case 641:
      case 642:
      case 643:
      case 644:
      case 645:  // NC-WORD-5: continuous path modes
        g_group(kGroupPathMode, "exact stop / continuous path", at);
        o.path_mode = PathMode::kG64;
        if (g != 64) add_text_action(fmt::format("G{}", g), at);
        return;
      case 601:
      case 602:
      case 603:
        return action(kGroupStopWindow, "exact stop window (G601/G602/G603)");
      case 70:
        g_group(kGroupUnits, "units", at);
        o.units = Units::kG70;
        return;
      case 71:
        g_group(kGroupUnits, "units", at);
        o.units = Units::kG71;
        return;
      case 700:
        g_group(kGroupUnits, "units", at);
        o.units = Units::kG700;
        return;
      case 710:
        g_group(kGroupUnits, "units", at);
        o.units = Units::kG710;
        return;
      case 74:
      case 75:  // NC-CYCLE-1: reference point / fixed point approach
        g_group(kGroupDwell, "non-modal (G4/G74/G75)", at);
        o.not_simulated = fmt::format("G{}", g);
        return;
      case 90:
        return group(o.absolute, true, "dimensions");
      case 91:
        return group(o.absolute, false, "dimensions");
      case 93:
        g_group(kGroupFeedType, "feed type", at);
        o.feed_type = FeedType::kG93;
        return add_text_action("G93", at);
      case 94:
      case 961:
      case 971:
        g_group(kGroupFeedType, "feed type", at);
        o.feed_type = FeedType::kG94;
        if (g != 94) add_text_action(fmt::format("G{}", g), at);
        return;
      case 95:
      case 96:
      case 97:
        g_group(kGroupFeedType, "feed type", at);
        o.feed_type = FeedType::kG95;
        if (g != 95) add_text_action(fmt::format("G{}", g), at);
        return;
      case 140:
        return group(o.sar_side, SarSide::kG140, "SAR side");
      case 141:
        return group(o.sar_side, SarSide::kG141, "SAR side");
      case 142:
        return group(o.sar_side, SarSide::kG142, "SAR side");
      case 143:
        return group(o.sar_side, SarSide::kG143, "SAR side");
      case 147:
        return group(o.sar_contour, SarContour::kG147, "SAR contour");
      case 148:
        return group(o.sar_contour, SarContour::kG148, "SAR contour");
      case 247:
        return group(o.sar_contour, SarContour::kG247, "SAR contour");
      case 248:
        return group(o.sar_contour, SarContour::kG248, "SAR contour");
      case 347:
        return group(o.sar_contour, SarContour::kG347, "SAR contour");
      case 348:
        return group(o.sar_contour, SarContour::kG348, "SAR contour");
      case 340:
        return group(o.sar_segmentation, SarSegmentation::kG340, "SAR segmentation");
      case 341:
        return group(o.sar_segmentation, SarSegmentation::kG341, "SAR segmentation");
      case 110:
      case 111:
      case 112:  // NC-POLAR-1: the pole
        return group(o.cw_set().pole, g == 110 ? PoleWord::kG110 : g == 111 ? PoleWord::kG111 : PoleWord::kG112, "pole");
      case 450:
        return group(o.corner, CornerMode::kG450, "outer corner");
      case 451:
        return group(o.corner, CornerMode::kG451, "outer corner");
      case 460:
        return group(o.edge_strategy, EdgeStrategy::kG460, "approach/retraction (group 48)");
      case 461:
        return group(o.edge_strategy, EdgeStrategy::kG461, "approach/retraction (group 48)");
      case 462:
        return group(o.edge_strategy, EdgeStrategy::kG462, "approach/retraction (group 48)");
      default:
        break;
    }
    // NC-OFFSET-1: settable work offsets.
    if (g == 500 || (g >= 54 && g <= 57) || (g >= 505 && g <= 599)) {
      g_group(kGroupOffset, "settable work offset", at);
      o.settable_offset = g == 500 ? 0 : g <= 57 ? static_cast<int>(g - 53) : static_cast<int>(g - 500);
      return;
    }
    fail(unsupported_message(fmt::format("G{}", g)), at);
  }

  // M and H (NC-LEX-5); M1=3 style addresses with a spindle or channel number are kept as written.
  void aux(char address, std::size_t at) {
    if (is_digit(peek()) && extended_address_follows()) {
      digits("address extension");
      equals();
      integer(std::string(1, address));
      return add_text_action(written(at), at);
    }
    equals();
    std::int64_t v = integer(std::string(1, address));
    if (v < 0) fail(fmt::format("{}{}: auxiliary function numbers are not negative", address, v), at);
    AuxFunction a;
    a.address = address, a.value = v;
    add_action(std::move(a), at);
    if (address != 'M') return;
    if (v == 2 || v == 30 || v == 17) out_.program_end = true;  // NC-END-1
    if (v == 6) out_.tool_change = true;                        // TOOL-CHANGE-1
  }
  // After a letter: digits, blanks and '=' (M1=3, S1=1000): an address with an extension.
  bool extended_address_follows() const {
    std::size_t j = i_;
    while (j < s_.size() && is_digit(s_[j])) ++j;
    while (j < s_.size() && s_[j] == ' ') ++j;
    return j < s_.size() && s_[j] == '=' && (j + 1 >= s_.size() || s_[j + 1] != '=');
  }

  // S (NC-WORD-3): spindle speed, or with G4 the dwell in revolutions.
  void spindle(std::size_t at) {
    if (is_digit(peek()) && extended_address_follows()) {
      digits("spindle number");
      equals();
    } else {
      equals();
    }
    Decimal v = number("S");
    if (v.sign() < 0) fail("S must not be negative", at);
    add_text_action(written(at), at);
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
    } else if (n == "RND" || n == "RNDM" || n == "CHF" || n == "CHR" || n == "FRC" || n == "FRCM") {
      contour_value(n, at);  // NC-CONTOUR-1/2
    } else if (n == "ANG") {
      set_once(out_.cw_set().ang, plain_value("ANG", true), "ANG", at);  // NC-CONTOUR-3
    } else if (n == "AP") {
      positional(out_.cw_set().ap, "AP", at, true, true);  // NC-POLAR-2
    } else if (n == "RP") {
      Decimal v = plain_value("RP", true);
      if (v.sign() < 0) fail("RP (polar radius) must not be negative", at);
      set_once(out_.cw_set().rp, v, "RP", at);
    } else if (n == "AR") {
      set_once(out_.cw_set().ar, plain_value("AR", true), "AR", at);  // NC-CONTOUR-5
    } else if (n == "TURN") {
      if (!equals()) fail("TURN needs '=' (write TURN=...)");
      std::int64_t v = integer("TURN");
      if (v < 0 || v > 999) fail("TURN: 0 to 999 full turns", at);
      set_once(out_.cw_set().turn, v, "TURN", at);
    } else if (n == "RPL") {
      set_once(out_.cw_set().rpl, plain_value("RPL", true), "RPL", at);  // NC-FRAME-4
    } else if (n == "CIP" || n == "CT") {  // NC-CONTOUR-4: circles of the motion group
      if (out_.cw().circle_definition || out_.motion) fail("two G codes of the motion group in one block", at);
      out_.cw_set().circle_definition = n == "CIP" ? CircleDefinition::kCip : CircleDefinition::kCt;
    } else {
      named_word(n, at);
    }
  }

  // RND= CHF= CHR= RNDM= FRC= FRCM=: a length or feed, not negative.
  void contour_value(const std::string& n, std::size_t at) {
    Decimal v = plain_value(n, true);
    if (v.sign() < 0) fail(fmt::format("{} must not be negative", n), at);
    Opt<Decimal>& slot = n == "RND" ? out_.cw_set().rnd : n == "RNDM" ? out_.cw_set().rndm : n == "CHF" ? out_.cw_set().chf
                       : n == "CHR" ? out_.cw_set().chr : n == "FRC" ? out_.cw_set().frc : out_.cw_set().frcm;
    set_once(slot, v, n, at);
  }

  // Multi-letter words other than the compensation parameters.
  void named_word(const std::string& n, std::size_t at) {
    static constexpr std::pair<std::string_view, FrameWord> kFrames[] = {
        {"TRANS", FrameWord::kTrans},   {"ATRANS", FrameWord::kAtrans}, {"SCALE", FrameWord::kScale},
        {"ASCALE", FrameWord::kAscale}, {"MIRROR", FrameWord::kMirror}, {"AMIRROR", FrameWord::kAmirror},
        {"ROT", FrameWord::kRot},       {"AROT", FrameWord::kArot}};
    for (const auto& [name, f] : kFrames)
      if (n == name) return set_once(out_.frame, f, "a frame instruction", at);  // NC-FRAME-1
    switch (classify_named_word(n)) {
      case NamedWord::kActionKeyword:  // NC-WORD-5/6: SOFT, FFWON, CFC, TRAFOOF, …
        return add_text_action(n, at);
      case NamedWord::kActionValue: {  // NC-WORD-5/3: ADIS=, ADISPOS=, LIMS=, SPOS=, SPOS[n]=
        if (peek() == '[') {
          ++i_;
          skip_space();
          digits(n + " index");
          skip_space();
          if (peek() != ']') fail(fmt::format("{}: ']' expected", n));
          ++i_;
        }
        if (!equals()) fail(fmt::format("{} needs '=' (write {}=...)", n, n));
        action_value(n);
        return add_text_action(written(at), at);
      }
      case NamedWord::kActionCall:  // NC-WORD-6: MSG("…"), WORKPIECE(…), GROUP_BEGIN(…), CYCLE832(…)
        balanced_arguments(n, at);
        return add_text_action(written(at), at);
      case NamedWord::kDiameter:  // NC-DIAM-1
        return set_once(out_.diameter,
                        n == "DIAMON"   ? DiameterMode::kDiamon
                        : n == "DIAM90" ? DiameterMode::kDiam90
                                        : DiameterMode::kDiamof,
                        "DIAMON/DIAMOF/DIAM90", at);
      case NamedWord::kCycle:  // NC-CYCLE-1: a standard cycle is not simulated
        if (!out_.not_simulated.empty())
          fail(fmt::format("'{}' and '{}' in one block", out_.not_simulated, n), at);
        skip_space();
        if (peek() == '(') balanced_arguments(n, at);
        out_.not_simulated = n;
        return;
      case NamedWord::kModalCall: {  // NC-CYCLE-2: MCALL CYCLEnn(…) / MCALL alone
        skip_space();
        if (at_end() || peek() == ';') {
          out_.modal_call_end = true;
          return;
        }
        std::size_t cat = i_;
        std::string cycle = letters();
        name_tail(cycle);
        if (classify_named_word(cycle) != NamedWord::kCycle)
          fail(fmt::format("MCALL of '{}': only standard cycles can be called modally (subprograms are not "
                           "supported yet)",
                           cycle),
               cat);
        skip_space();
        if (peek() == '(') balanced_arguments(cycle, cat);
        out_.not_simulated = cycle;
        out_.modal_call = true;
        return;
      }
      case NamedWord::kSubprogramEnd:  // RET: end of a subprogram run on its own (NC-END-1)
        add_text_action("RET", at);
        out_.program_end = true;
        return;
      case NamedWord::kNotSimulated:
        fail(unsupported_message(n), at);
      case NamedWord::kUnknown:
        break;
    }
    fail(unknown_message(n), at);
  }

  void word() {
    std::size_t at = i_;
    std::string n = letters();
    if (n.size() > 1 || peek() == '_') name_tail(n);
    // Keywords without a value (NC-LEX-3).
    if (n == "NORM") return set_once(out_.approach, ApproachMode::kNorm, "NORM/KONT", at);
    if (n == "KONT") return set_once(out_.approach, ApproachMode::kKont, "NORM/KONT", at);
    if (n == "KONTC") return set_once(out_.approach, ApproachMode::kKontC, "NORM/KONT", at);
    if (n == "KONTT") return set_once(out_.approach, ApproachMode::kKontT, "NORM/KONT", at);
    if (n == "CDON") return set_once(out_.collision, CollisionMode::kCdon, "CDON/CDOF", at);
    if (n == "CDOF") return set_once(out_.collision, CollisionMode::kCdof, "CDON/CDOF", at);
    if (n == "CDOF2") return set_once(out_.collision, CollisionMode::kCdof2, "CDON/CDOF", at);
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
      case 'E': {  // NC-WORD-3: E is kept as an action as written
        equals();
        number("E");
        return add_text_action(written(at), at);
      }
      case 'S':
        return spindle(at);
      case 'T':
        return tool(at);
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
      case 'J':
      case 'K': {
        std::size_t k = static_cast<std::size_t>(n[0] - 'I');
        if (peek() == '1' && !is_digit(peek(1)) && extended_address_follows()) {  // I1= J1= K1= (CIP)
          ++i_;
          return positional(out_.cw_set().intermediate[k], n + "1", at, true, true);
        }
        return positional(out_.centre[k], n, at, true, false);
      }
      case 'R':
        if (is_digit(peek()) || peek() == '[')
          fail(unsupported_message(fmt::format("R{}", rest_of_word()), "R parameters"), at);
        break;
      case 'L':
        if (is_digit(peek())) fail(unsupported_message(fmt::format("L{}", rest_of_word()), "subprogram calls"), at);
        break;
      case 'P':
        fail(unsupported_message("P", "subprogram repetitions"), at);
      default:
        break;
    }
    fail(unknown_message(n), at);
  }

  // T (TOOL-NAME-1): T5, T=5, T="NAME", T1=5 (tool for spindle 1).
  void tool(std::size_t at) {
    if (is_digit(peek()) && extended_address_follows()) {
      digits("spindle number");
    }
    bool eq = equals();
    if (eq && peek() == '"') {
      ++i_;
      std::size_t start = i_;
      while (!at_end() && peek() != '"') ++i_;
      if (at_end()) fail("T=\"…\": closing '\"' expected");
      std::string name(s_.substr(start, i_ - start));
      ++i_;
      if (name.empty()) fail("T=\"\": the tool name is empty", at);
      if (out_.tool || out_.tool_name) fail("T programmed twice in one block", at);
      out_.tool_name = name;
      return;
    }
    std::int64_t v = integer("T");
    if (v < 0) fail("tool number must not be negative", at);
    if (out_.tool_name) fail("T programmed twice in one block", at);
    set_once(out_.tool, v, "T", at);
  }

  // System variables (NC-LEX-6): tool data $TC_DPn[t,d]=v and $TC_TP2[t]="NAME".
  void system_variable() {
    std::size_t at = i_;
    ++i_;
    std::string n = letters();
    name_tail(n);
    std::string full = "$" + n;
    std::size_t dp = n.rfind("TC_DP", 0) == 0 ? 5 : 0;
    if (dp) {
      std::string num = n.substr(5);
      int p = 0;
      bool ok = !num.empty() && num.size() <= 2 && std::all_of(num.begin(), num.end(), is_digit);
      if (ok) p = std::stoi(num);
      if (!ok || p < 1 || p > 25) fail(fmt::format("'{}' is not a tool edge parameter ($TC_DP1 … $TC_DP25)", full), at);
      return tool_edge_data(p, at);
    }
    if (n == "TC_TP2") return tool_name_data(at);
    if (n == "TC_TP1" || n == "TC_TP3" || n == "TC_TP4" || n == "TC_TP5" || n == "TC_TP6" || n == "TC_TP7" ||
        n == "TC_TP8" || n == "TC_TP9" || n == "TC_TP10" || n == "TC_TP11") {
      return ignored_tool_parameter(full);
    }
    fail(fmt::format("system variable '{}' is SINUMERIK NC that cutcom does not simulate (supported: $TC_DP1 … "
                     "$TC_DP25, $TC_TP1 … $TC_TP11)",
                     full),
         at);
  }

  void index_open(const std::string& what) {
    skip_space();
    if (peek() != '[') fail(fmt::format("'[' expected after {}", what));
    ++i_;
    skip_space();
  }
  void index_close() {
    skip_space();
    if (peek() != ']') fail("']' expected");
    ++i_;
  }

  void tool_edge_data(int p, std::size_t at) {
    std::string what = fmt::format("$TC_DP{}", p);
    index_open(what);
    std::int64_t t = digits("tool number");
    skip_space();
    if (peek() != ',') fail(fmt::format("',' expected between tool and edge number (write {}[t,d])", what));
    ++i_;
    skip_space();
    std::int64_t d = digits("edge number");
    index_close();
    if (!equals()) fail("'=' expected");
    Decimal v = number(what + " value");
    if (t < 1 || d < 1) fail("tool and edge numbers start at 1", at);
    if (d > 32000) fail("edge numbers go up to 32000", at);
    if (out_.tool_data_count == BlockWords::kMaxToolData) fail("too many tool data assignments in one block", at);
    out_.tool_data[static_cast<std::size_t>(out_.tool_data_count++)] = {p, static_cast<int>(t), static_cast<int>(d), v};
  }

  // $TC_TP2[t]="NAME": the tool's name (TOOL-NAME-1).
  void tool_name_data(std::size_t at) {
    index_open("$TC_TP2");
    std::int64_t t = digits("tool number");
    index_close();
    if (!equals()) fail("'=' expected");
    if (peek() != '"') fail("$TC_TP2 needs a name in quotes: $TC_TP2[t]=\"NAME\"");
    ++i_;
    std::size_t start = i_;
    while (!at_end() && peek() != '"') ++i_;
    if (at_end()) fail("closing '\"' expected");
    std::string name(s_.substr(start, i_ - start));
    ++i_;
    if (t < 1) fail("tool numbers start at 1", at);
    if (name.empty()) fail("the tool name is empty", at);
    if (out_.tool_names_count == BlockWords::kMaxToolData) fail("too many tool names in one block", at);
    out_.tool_names[static_cast<std::size_t>(out_.tool_names_count++)] = {static_cast<int>(t), name};
  }

  // $TC_TP1, $TC_TP3 … $TC_TP11 (duplo number, size, place type, …): no effect on the path.
  void ignored_tool_parameter(const std::string& what) {
    index_open(what);
    digits("tool number");
    index_close();
    if (!equals()) fail("'=' expected");
    if (peek() == '"') {
      ++i_;
      while (!at_end() && peek() != '"') ++i_;
      if (at_end()) fail("closing '\"' expected");
      ++i_;
      return;
    }
    number(what + " value");
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int line_;
  BlockWords& out_;
  unsigned groups_ = 0;
};

}  // namespace

void parse_block_words(std::string_view text, int line, BlockWords& out) { WordLexer(text, line, out).run(); }

}  // namespace cutcom
