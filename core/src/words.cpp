// NC-LEX-*, NC-WORD-*: the words of one block (addresses, keywords, actions, tools). An unknown
// or unsupported word is named whole, in one wording (NC-ERR-3).
#include <cstring>

#include "word_lexer.hpp"

namespace cutcom::lexer {

// M and H (NC-LEX-5); M1=3 style addresses with a spindle or channel number are kept as written.
void WordLexer::aux(char address, std::size_t at) {
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
  if (ends_program(v)) out_.program_end = true;  // NC-END-1
  if (changes_tool(v)) out_.tool_change = true;  // TOOL-CHANGE-1
}

// After a letter: digits, blanks and '=' (M1=3, S1=1000): an address with an extension.
bool WordLexer::extended_address_follows() const {
  std::size_t j = i_;
  while (j < s_.size() && is_digit(s_[j])) ++j;
  while (j < s_.size() && s_[j] == ' ') ++j;
  return j < s_.size() && s_[j] == '=' && (j + 1 >= s_.size() || s_[j + 1] != '=');
}

// S (NC-WORD-3): spindle speed, or with G4 the dwell in revolutions.
void WordLexer::spindle(std::size_t at) {
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

void WordLexer::keyword_value(const std::string& n, std::size_t at) {
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
  } else if (n == "DL") {                                           // TOOL-SUM-1: the sum offset of the edge
    if (!equals()) fail("DL needs '=' (write DL=n; DL=0 deselects)");
    std::int64_t v = integer("DL");
    if (v < 0 || v > 6) fail("DL: a sum offset number 0 … 6", at);
    set_once(out_.sum_offset, v, "DL", at);
  } else if (n == "LEAD" || n == "TILT" || n == "THETA" || n == "PSI") {
    orientation(n, at);  // NC-WORD-11
  } else if (n == "TURN") {
    if (!equals()) fail("TURN needs '=' (write TURN=...)");
    std::int64_t v = integer("TURN");
    if (v < 0 || v > 999) fail("TURN: 0 to 999 full turns", at);
    set_once(out_.cw_set().turn, v, "TURN", at);
  } else if (n == "RPL") {
    set_once(out_.cw_set().rpl, plain_value("RPL", true), "RPL", at);  // NC-FRAME-4
  } else if (n == "CIP" || n == "CT") {                                // NC-CONTOUR-4: circles of the motion group
    if (out_.cw().circle_definition || out_.motion) fail("two G codes of the motion group in one block", at);
    out_.cw_set().circle_definition = n == "CIP" ? CircleDefinition::kCip : CircleDefinition::kCt;
  } else {
    named_word(n, at);
  }
}

// RND= CHF= CHR= RNDM= FRC= FRCM=: a length or feed, not negative.
void WordLexer::contour_value(const std::string& n, std::size_t at) {
  Decimal v = plain_value(n, true);
  if (v.sign() < 0) fail(fmt::format("{} must not be negative", n), at);
  Opt<Decimal>& slot = n == "RND"    ? out_.cw_set().rnd
                       : n == "RNDM" ? out_.cw_set().rndm
                       : n == "CHF"  ? out_.cw_set().chf
                       : n == "CHR"  ? out_.cw_set().chr
                       : n == "FRC"  ? out_.cw_set().frc
                                     : out_.cw_set().frcm;
  set_once(slot, v, n, at);
}

// NC-CYCLE-1/3: a cycle cutcom does not simulate, with its arguments if any.
void WordLexer::not_simulated_cycle(const std::string& n, std::size_t at) {
  if (!out_.not_simulated.empty()) fail(fmt::format("'{}' and '{}' in one block", out_.not_simulated, n), at);
  optional_arguments(n, at);
  out_.not_simulated = n;
}

// NC-CYCLE-3: CALL/PCALL/EXTCALL of a cycle of the machine (the interpreter calls any the folders
// hold): "PATH/NAME.SPF" or NAME, read as the cycle NAME; any other is a word cutcom does not know.
void WordLexer::explicit_machine_call(const std::string& n, std::size_t at) {
  skip_space();
  std::string target;
  if (peek() == '"') {
    std::size_t close = s_.find('"', i_ + 1);
    if (close == std::string_view::npos) fail("the name has no closing '\"'");
    for (std::size_t k = i_ + 1; k < close; ++k) target.push_back(upper(s_[k]));
    i_ = close + 1;
    target = called_name(std::move(target));
  } else {
    target = letters();
    name_tail(target);
  }
  if (target.empty() || !machine_cycle(target)) fail(unknown_message(n), at);
  not_simulated_cycle(target, at);
}

// Multi-letter words other than the compensation parameters.
void WordLexer::named_word(const std::string& n, std::size_t at) {
  static constexpr std::pair<std::string_view, FrameWord> kFrames[] = {
      {"TRANS", FrameWord::kTrans},   {"ATRANS", FrameWord::kAtrans}, {"SCALE", FrameWord::kScale},
      {"ASCALE", FrameWord::kAscale}, {"MIRROR", FrameWord::kMirror}, {"AMIRROR", FrameWord::kAmirror},
      {"ROT", FrameWord::kRot},       {"AROT", FrameWord::kArot}};
  for (const auto& [name, f] : kFrames)
    if (n == name) return set_once(out_.frame, f, "a frame instruction", at);  // NC-FRAME-1
  if (machine_cycle(n)) return not_simulated_cycle(n, at);                     // NC-CYCLE-3
  if (n == "CALL" || n == "PCALL" || n == "EXTCALL") return explicit_machine_call(n, at);
  switch (classify_named_word(n)) {
    case NamedWord::kActionKeyword:  // NC-WORD-5/6: SOFT, FFWON, CFC, …, with its axes: BRISKA(X,Y), TOFFOF()
      if ((n == "FINEA" || n == "COARSEA" || n == "IPOENDA") && peek() == '[') {  // NC-WORD-7: FINEA[C]
        ++i_;
        skip_space();
        if (!is_letter(peek())) fail(fmt::format("{}: an axis is expected", n));
        std::string axis = letters();
        name_tail(axis);
        skip_space();
        if (peek() != ']') fail(fmt::format("{}: ']' expected", n));
        ++i_;
        return add_text_action(written(at), at);
      }
      return add_text_action(optional_arguments(n, at) ? written(at) : n, at);
    case NamedWord::kActionValue: {  // NC-WORD-5/3/7: ADIS=, LIMS=, SPOS=, SPOS[n]=, ACC[X]=
      if (peek() == '[') {
        ++i_;
        skip_space();
        if (is_letter(peek())) {  // an axis: ACC[X], VELOLIM[Z], POS[A]
          std::size_t axis_at = i_;
          std::string axis = letters();
          name_tail(axis);
          if ((n == "POS" || n == "POSA") && axis != "A" && axis != "B" && axis != "C")  // NC-WORD-8
            fail(fmt::format("{}[{}]: {} as a positioning axis is SINUMERIK NC that cutcom does not simulate", n, axis,
                             axis),
                 axis_at);
        } else {
          digits(n + " index");
        }
        skip_space();
        if (peek() != ']') fail(fmt::format("{}: ']' expected", n));
        ++i_;
      }
      if (!equals()) fail(fmt::format("{} needs '=' (write {}=...)", n, n));
      action_value(n);
      return add_text_action(written(at), at);
    }
    case NamedWord::kActionCall:  // NC-WORD-6/7: MSG("…"), WORKPIECE(…), CYCLE832(…), WAITM(…)
      skip_space();
      if (n == "WAITS" && peek() != '(') return add_text_action(n, at);  // all spindles
      balanced_arguments(n, at);
      return add_text_action(written(at), at);
    case NamedWord::kDiameter:  // NC-DIAM-1
      return set_once(out_.diameter,
                      n == "DIAMON"   ? DiameterMode::kDiamon
                      : n == "DIAM90" ? DiameterMode::kDiam90
                                      : DiameterMode::kDiamof,
                      "DIAMON/DIAMOF/DIAM90", at);
    case NamedWord::kCycle:  // NC-CYCLE-1: a standard cycle is not simulated
      return not_simulated_cycle(n, at);
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
        fail(fmt::format("MCALL of '{}': neither a standard cycle nor a subprogram found ({}.SPF in the program's "
                         "folder or --search-path)",
                         cycle, cycle),
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

// NC-WORD-9: a synchronized action runs in the interpolation cycle while the blocks move; its
// condition is read then, not now. One that acts on the path of X, Y, Z is not simulated.
void WordLexer::synchronized_action(std::size_t at) {
  bool quoted = false;
  while (!at_end() && (quoted || peek() != ';')) {
    if (peek() == '"') quoted = !quoted;
    ++i_;
  }
  std::string text = written(at);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.pop_back();
  // Words that move a geometry axis, change the offsets or delete the distance to go.
  static constexpr std::string_view kMovesThePath[] = {"DELDTG",  "FTOC",   "SYNFCT", "PRESETON",
                                                       "TRAILON", "LEADON", "$AA_OFF"};
  std::size_t do_at = std::string::npos;
  for (std::size_t k = 0; k < text.size();) {
    if (!is_letter(text[k]) && text[k] != '$' && text[k] != '_') {
      ++k;
      continue;
    }
    std::size_t e = k + 1;
    while (e < text.size() && (is_name_char(text[e]) || text[e] == '$')) ++e;
    std::string_view w = std::string_view(text).substr(k, e - k);
    if (w == "DO" && do_at == std::string::npos) do_at = k;
    bool moves = std::find(std::begin(kMovesThePath), std::end(kMovesThePath), w) != std::end(kMovesThePath);
    if (!moves && do_at != std::string::npos && (w == "POS" || w == "MOV" || w == "POSA")) {
      std::size_t b = e;
      while (b < text.size() && text[b] == ' ') ++b;
      if (b + 1 < text.size() && text[b] == '[') {
        std::size_t a = b + 1;
        while (a < text.size() && text[a] == ' ') ++a;
        moves = a < text.size() && (text[a] == 'X' || text[a] == 'Y' || text[a] == 'Z') &&
                (a + 1 >= text.size() || !is_name_char(text[a + 1]));
      }
    }
    if (moves)
      fail(fmt::format("a synchronized action with {} (it moves or offsets the path while the blocks run) is "
                       "SINUMERIK NC that cutcom does not simulate",
                       w),
           at + k);
    k = e;
  }
  if (do_at == std::string::npos) fail("a synchronized action needs DO and its actions", at);
  add_text_action(std::move(text), at);
  out_.synchronized_action = true;
}

// A word of more than one letter: keywords without a value (NC-LEX-3), then those with one.
void WordLexer::keyword(const std::string& n, std::size_t at) {
  if (starts_synchronized_action(n)) return synchronized_action(at);
  if (n == "NORM") return set_once(out_.approach, ApproachMode::kNorm, "NORM/KONT", at);
  if (n == "KONT") return set_once(out_.approach, ApproachMode::kKont, "NORM/KONT", at);
  if (n == "KONTC") return set_once(out_.approach, ApproachMode::kKontC, "NORM/KONT", at);
  if (n == "KONTT") return set_once(out_.approach, ApproachMode::kKontT, "NORM/KONT", at);
  if (n == "CDON") return set_once(out_.collision, CollisionMode::kCdon, "CDON/CDOF", at);
  if (n == "CDOF") return set_once(out_.collision, CollisionMode::kCdof, "CDON/CDOF", at);
  if (n == "CDOF2") return set_once(out_.collision, CollisionMode::kCdof2, "CDON/CDOF", at);
  if (n == "GOTOS") {  // NC-PARAM-FLOW-7: the program runs again from its start; one pass is shown
    add_text_action(n, at);
    out_.program_end = true;
    out_.repeats_from_start = true;
    return;
  }
  if (n == "STOPRE") {
    out_.stopre = true;
    return;
  }
  // NC-WORD-11/13: the 5-axis or the face's polar transformation on (its number), or off.
  if (n == "TRAORI" || n == "TRANSMIT" || n == "TRAFOOF") {
    bool arguments = n != "TRAFOOF" && optional_arguments(n, at);
    set_once(out_.transformation,
             n == "TRAORI"     ? Transformation::kTraori
             : n == "TRANSMIT" ? Transformation::kTransmit
                               : Transformation::kOff,
             "TRAORI/TRANSMIT/TRAFOOF", at);
    return add_text_action(arguments ? written(at) : n, at);
  }
  keyword_value(n, at);
}

void WordLexer::word() {
  std::size_t at = i_;
  if (is_letter(peek(1)) || peek(1) == '_') {
    std::string n = letters();
    name_tail(n);
    return keyword(n, at);
  }
  // One letter, as most words are: its name from a table, not a string built per word.
  static const std::array<std::string, 26> kLetters = [] {
    std::array<std::string, 26> a;
    for (int k = 0; k < 26; ++k) a[static_cast<std::size_t>(k)] = std::string(1, static_cast<char>('A' + k));
    return a;
  }();
  const std::string& n = kLetters[static_cast<std::size_t>(upper(s_[i_++]) - 'A')];
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
    case 'A':
    case 'B':
    case 'C':
      if ((peek() == '2' || peek() == '3') && extended_address_follows()) {  // NC-WORD-11: angles, vector
        std::string name = n;
        name += peek();
        ++i_;
        return orientation(name, at);
      }
      if (axis_as_action(n, at)) return;
      return rotary_axis(n, at);
    case 'X':
      if (axis_as_action(n, at)) return;
      plane_axis_after_rotary(at);
      return positional(out_.axis[0], "X", at, true, false);
    case 'Y':
      if (axis_as_action(n, at)) return;
      plane_axis_after_rotary(at);
      return positional(out_.axis[1], "Y", at, true, false);
    case 'Z':
      if (axis_as_action(n, at)) return;
      plane_axis_after_rotary(at);
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
      if (is_digit(peek())) {
        std::string call = fmt::format("L{}", rest_of_word());
        if (!machine_cycle(call)) fail(unsupported_message(call, "subprogram calls"), at);
        i_ += call.size() - 1;  // NC-CYCLE-3: Ln of the machine, as a standard cycle
        return not_simulated_cycle(call, at);
      }
      break;
    case 'P':
      fail(unsupported_message("P", "subprogram repetitions"), at);
    default:
      break;
  }
  fail(unknown_message(n), at);
}

// An axis word that is no position, kept as written: NC-WORD-7, an axis after G25/G26 (the working
// area's limit); NC-CYCLE-1, G74 X1=0 Y1=0 (reference point), G75 FP=2 Z1=0 (fixed point), the
// axes with the extension 1 that move there (the move is not simulated). False: a position.
bool WordLexer::axis_as_action(const std::string& n, std::size_t at) {
  if (area_limit_) {  // NC-WORD-7: G25/G26 X… Y… Z…: the working area's limits, no motion
    equals();
    number(n);
    add_text_action(written(at), at);
    return true;
  }
  if (!is_digit(peek()) || !extended_address_follows()) return false;
  if (out_.not_simulated != "G74" && out_.not_simulated != "G75")
    fail(fmt::format("{}{}= (an axis with an extension) is read only after G74 or G75", n, peek()), at);
  digits("axis extension");
  equals();
  number(n);
  add_text_action(written(at), at);
  return true;
}

// NC-WORD-8: a rotary axis A, B or C (A90, A=DC(90), C=ACP(45), B=IC(-5)) positions the workpiece
// or the head; the path is shown in the workpiece system, so the word is an action, kept as
// written. Moved together with X, Y or Z it is noted for the reader, which allows it only in a
// rapid move without compensation (program_reader.cpp).
void WordLexer::rotary_axis(const std::string& n, std::size_t at) {
  std::string_view name = orientation_literal(n);
  for (const AxisWord& a : out_.axis)
    if (a.present && out_.rotary_with_plane.empty())
      out_.rotary_with_plane = name, out_.rotary_column = static_cast<int>(at) + 1;
  equals();
  action_value(n);
  rotary_name_ = name;
  add_text_action(written(at), at);
}

bool WordLexer::optional_arguments(const std::string& n, std::size_t at) {
  std::size_t after = i_;
  skip_space();
  if (peek() != '(') {
    i_ = after;
    return false;
  }
  balanced_arguments(n, at);
  return true;
}

// NC-WORD-11: the tool's orientation under TRAORI: Euler or RPY angles A2= B2= C2=, a direction
// vector A3= B3= C3=, the angles LEAD= TILT= THETA= PSI=. Kept as actions like a rotary axis; the
// reader allows them only with TRAORI in force.
void WordLexer::orientation(const std::string& n, std::size_t at) {
  if (out_.orientation_word.empty()) out_.orientation_word = orientation_literal(n);
  rotary_axis(n, at);
}

std::string_view WordLexer::orientation_literal(std::string_view n) {
  static constexpr std::string_view kNames[] = {"A",  "B",  "C",    "A2",   "B2",    "C2", "A3",
                                                "B3", "C3", "LEAD", "TILT", "THETA", "PSI"};
  for (std::string_view k : kNames)
    if (k == n) return k;
  return "A";  // (never: the callers pass one of the names above)
}

void WordLexer::plane_axis_after_rotary(std::size_t at) {
  if (!rotary_name_.empty() && out_.rotary_with_plane.empty())
    out_.rotary_with_plane = rotary_name_, out_.rotary_column = static_cast<int>(at) + 1;
}

// T (TOOL-NAME-1): T5, T=5, T="NAME", T1=5 (tool for spindle 1).
void WordLexer::tool(std::size_t at) {
  if (is_digit(peek()) && extended_address_follows()) {
    digits("spindle number");
  }
  bool eq = equals();
  if (eq && peek() == '"') {
    std::string name = quoted("T=\"…\"");
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

}  // namespace cutcom::lexer

namespace cutcom {

InputError::InputError(int line, int column, const std::string& what)
    : std::runtime_error(fmt::format("line {}, column {}: {}", line, column, what)),
      line_(line),
      column_(column),
      detail_(what) {}

void reset_fields(BlockWordFields& fields) {
  // An empty block is all zero bytes (tests/reader_test.cpp holds it so): cleared by 16-byte
  // stores alone, unrolled, not copied from an empty one (half the instructions of the copy's
  // loop; every block is reset). The compiler's own clear of this size is a loop or a call.
  typedef char Chunk __attribute__((vector_size(16), aligned(8), may_alias));
  static_assert(sizeof(BlockWordFields) % 8 == 0 && alignof(BlockWordFields) >= 8);
  constexpr std::size_t kChunks = sizeof(BlockWordFields) / 16;
  auto* to = reinterpret_cast<char*>(&fields);
  const Chunk zero{};
#pragma GCC unroll 64
  for (std::size_t i = 0; i < kChunks; ++i) *reinterpret_cast<Chunk*>(to + 16 * i) = zero;
  if constexpr (sizeof(BlockWordFields) % 16 != 0) std::memset(to + 16 * kChunks, 0, 8);
}

void parse_block_words(std::string_view text, int line, BlockWords& out, const std::vector<std::string>& machine_cycles,
                       bool plain_refused) {
  lexer::WordLexer lexer(text, line, out, machine_cycles);
  if (plain_refused)
    lexer.general();  // not read plain a second time
  else
    lexer.run();
}

}  // namespace cutcom
