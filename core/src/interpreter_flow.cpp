// Control flow of the interpreter (NC-PARAM-FLOW-*): IF/ELSE, loops, jumps to labels and block
// numbers, and the runaway limit.
#include <fmt/format.h>

#include <cmath>
#include <set>
#include <tuple>

#include "cutcom/interpreter.hpp"
#include "interpreter_lookup.hpp"
#include "interpreter_text.hpp"
#include "nc_expression.hpp"

namespace cutcom {

using namespace interpreter_text;

bool Interpreter::statement(std::string_view k, std::string_view s, std::size_t rest) {
  InterpreterLookup lookup(*this, cx().line);
  auto condition = [&](std::size_t from, std::size_t& end) {
    NcValue v = expression(s, from, lookup, end);
    end = skip_space(s, end);
    if (v.type == NcValue::Type::kString)
      throw InputError(cx().line, static_cast<int>(from) + 1, "a condition must be a number or BOOL, not a string");
    return v.number != 0;
  };
  auto nothing_after = [&](std::size_t e, std::string_view what) {
    e = skip_space(s, e);
    if (e < s.size() && s[e] != ';')
      throw InputError(cx().line, static_cast<int>(e) + 1, fmt::format("unexpected text after {}", what));
  };
  static constexpr std::string_view kStatements[] = {"IF",   "ELSE",    "ENDIF",  "WHILE", "ENDWHILE", "FOR", "ENDFOR",
                                                     "LOOP", "ENDLOOP", "REPEAT", "UNTIL", "REPEATB",  "CASE"};
  for (std::string_view w : kStatements) control_flow_ = control_flow_ || k == w;
  if (k == "IF") {
    std::size_t end;
    bool c = condition(rest, end);
    std::size_t j = name_end(s, end);
    std::string jump_word = upper_text(s.substr(end, j - end));
    if (jump_word == "GOTOS") {  // NC-PARAM-FLOW-7: taken, it ends the run as a block GOTOS
      nothing_after(j, "GOTOS");
      gotos_in_the_main_program(end);
      if (c) statement_block_ = "GOTOS";
      return true;
    }
    if (jump_word == "GOTOF" || jump_word == "GOTOB" || jump_word == "GOTO" || jump_word == "GOTOC") {
      // NC-PARAM-FLOW-1: a conditional jump.
      std::size_t t = skip_space(s, j);
      std::size_t te = name_end(s, t);
      std::string target = upper_text(s.substr(t, te - t));
      if (target.empty())
        throw InputError(cx().line, static_cast<int>(t) + 1,
                         fmt::format("{} needs a label or block number", jump_word));
      nothing_after(te, "the jump target");
      if (c) jump(target, jump_word != "GOTOB", jump_word != "GOTOF", jump_word != "GOTOC", end);
      return true;
    }
    nothing_after(end, "the condition of IF");
    // NC-PARAM-FLOW-2: IF … ELSE … ENDIF; the branch that runs ends at its ENDIF.
    if (c || skip_block("IF", "ENDIF", true) == "ELSE") cx().open_ifs.push_back(cx().line);
    return true;
  }
  if (k == "ELSE") {  // reached while running the IF branch: skip the ELSE branch
    nothing_after(rest, "ELSE");
    if (cx().open_ifs.empty()) throw InputError(cx().line, 1, "ELSE without its IF");
    cx().open_ifs.pop_back();
    skip_block("IF", "ENDIF", false);
    return true;
  }
  if (k == "ENDIF") {
    nothing_after(rest, "ENDIF");
    if (cx().open_ifs.empty()) throw InputError(cx().line, 1, "ENDIF without its IF");
    cx().open_ifs.pop_back();
    return true;
  }
  if (k == "WHILE") {  // NC-PARAM-FLOW-3
    std::size_t end;
    bool c = condition(rest, end);
    nothing_after(end, "the condition of WHILE");
    if (c)
      cx().frames.push_back({Frame::Kind::kWhile, cx().line_start, cx().line - 1, {}, 0, cx().line});
    else
      skip_block("WHILE", "ENDWHILE", false);
    return true;
  }
  auto close = [&](Frame::Kind kind, std::string_view word) -> Frame& {
    nothing_after(rest, word);
    if (cx().frames.empty() || cx().frames.back().kind != kind)
      throw InputError(cx().line, 1, fmt::format("{} without its opening statement", word));
    return cx().frames.back();
  };
  if (k == "ENDWHILE") {
    Frame f = close(Frame::Kind::kWhile, "ENDWHILE");
    cx().frames.pop_back();
    jump_back(f);  // the WHILE line decides again
    return true;
  }
  if (k == "FOR") {  // NC-PARAM-FLOW-4: FOR variable = start TO end
    std::size_t v = skip_space(s, rest);
    std::size_t ve = name_end(s, v);
    std::string var = upper_text(s.substr(v, ve - v));
    std::size_t eq = skip_space(s, ve);
    if (var.empty() || eq >= s.size() || s[eq] != '=')
      throw InputError(cx().line, static_cast<int>(v) + 1, "FOR needs 'variable = start TO end'");
    ExpressionParser p(s, eq + 1, cx().line, lookup);
    NcValue first = p.parse();
    std::size_t to = skip_space(s, p.position());
    if (upper_text(s.substr(to, 2)) != "TO" || (to + 2 < s.size() && is_name_char(s[to + 2])))
      throw InputError(cx().line, static_cast<int>(to) + 1, "FOR needs 'TO end'");
    ExpressionParser q(s, to + 2, cx().line, lookup);
    NcValue last = q.parse();
    nothing_after(q.position(), "the end value of FOR");
    assign_counter(var, first.number, v);
    if (first.number > last.number) {
      skip_block("FOR", "ENDFOR", false);
      return true;
    }
    cx().frames.push_back({Frame::Kind::kFor, cx().offset, cx().line, var, last.number, cx().line});
    return true;
  }
  if (k == "ENDFOR") {
    Frame& f = close(Frame::Kind::kFor, "ENDFOR");
    double next = counter(f.variable) + 1;
    assign_counter(f.variable, next, 0);
    if (next <= f.end) {
      jump_back(f);
    } else {
      cx().frames.pop_back();
    }
    return true;
  }
  if (k == "LOOP") {  // NC-PARAM-FLOW-3
    nothing_after(rest, "LOOP");
    cx().frames.push_back({Frame::Kind::kLoop, cx().offset, cx().line, {}, 0, cx().line});
    return true;
  }
  if (k == "ENDLOOP") {
    Frame f = close(Frame::Kind::kLoop, "ENDLOOP");
    jump_back(f);
    return true;
  }
  if (k == "REPEAT" || k == "REPEATB") {
    std::size_t e = skip_space(s, rest);
    if (k == "REPEATB" || (e < s.size() && s[e] != ';')) {
      repeat_section(s, rest, k == "REPEATB");
      return true;
    }
    cx().frames.push_back({Frame::Kind::kRepeat, cx().offset, cx().line, {}, 0, cx().line});
    return true;
  }
  if (k == "UNTIL") {
    if (cx().frames.empty() || cx().frames.back().kind != Frame::Kind::kRepeat)
      throw InputError(cx().line, 1, "UNTIL without its REPEAT");
    std::size_t end;
    bool c = condition(rest, end);
    nothing_after(end, "the condition of UNTIL");
    Frame f = cx().frames.back();
    if (c)
      cx().frames.pop_back();
    else
      jump_back(f);
    return true;
  }
  if (k == "CASE") {
    case_jump(s, rest);
    return true;
  }
  if (k == "DEF") {
    define(s, rest, cx().variables);
    return true;
  }
  if (k == "EXTERN") {  // NC-PARAM-SUB-7: a declaration; the subprogram is found by its file
    std::size_t n = skip_space(s, rest), ne = name_end(s, n);
    if (ne == n) throw InputError(cx().line, static_cast<int>(n) + 1, "EXTERN needs the subprogram's name");
    std::size_t e = skip_space(s, ne);
    if (e < s.size() && s[e] == '(') {
      std::size_t shut = s.find(')', e);
      if (shut == std::string_view::npos)
        throw InputError(cx().line, static_cast<int>(e) + 1, "EXTERN: ')' expected after the parameter types");
      e = shut + 1;
    }
    nothing_after(e, "the EXTERN declaration");
    return true;
  }
  if (k == "DEFINE") {  // NC-PARAM-SUB-7: a macro, its name replaced by its text from the next line on
    std::size_t n = skip_space(s, rest), ne = name_end(s, n);
    std::string name = upper_text(s.substr(n, ne - n));
    std::size_t as = skip_space(s, ne), ae = name_end(s, as);
    if (name.empty() || upper_text(s.substr(as, ae - as)) != "AS")
      throw InputError(cx().line, static_cast<int>(n) + 1, "DEFINE is written DEFINE name AS text");
    std::size_t t = skip_space(s, ae), te = std::min(s.find(';', t), s.size());
    while (te > t && (s[te - 1] == ' ' || s[te - 1] == '\t' || s[te - 1] == '\r')) --te;
    if (te == t) throw InputError(cx().line, static_cast<int>(t) + 1, "DEFINE: the macro's text is missing");
    macros_[name] = std::string(s.substr(t, te - t));
    return true;
  }
  if (k == "PROC") {
    procedure(s, rest);
    return true;
  }
  // NC-PARAM-SUB-2: RET, M17 (or M2/M30) end a subprogram; in the main program they stay words.
  if (stack_.size() > 1 && (k == "RET" || k == "M17" || k == "M2" || k == "M30")) {
    leave_subprogram();
    return true;
  }
  return false;
}

double Interpreter::counter(const std::string& name) {
  if (is_r_parameter(name) && r_number(name) < kRParameters) return r_[r_number(name)];
  Variable* v = find_variable(name);
  if (!v || !v->dims.empty() || v->type == NcValue::Type::kString)
    throw InputError(cx().line, 1,
                     fmt::format("the FOR counter '{}' must be an INT or REAL variable or an R parameter", name));
  return v->values[0].number;
}

void Interpreter::assign_counter(const std::string& name, double value, std::size_t at) {
  if (is_r_parameter(name)) {
    int r = r_number(name);
    if (r >= kRParameters)
      throw InputError(cx().line, static_cast<int>(at) + 1, fmt::format("R parameter {} does not exist", name));
    r_[r] = value;
    return;
  }
  Variable* v = find_variable(name);
  if (!v || !v->dims.empty() || v->type == NcValue::Type::kString)
    throw InputError(cx().line, static_cast<int>(at) + 1,
                     fmt::format("the FOR counter '{}' must be an INT or REAL variable or an R parameter", name));
  store(*v, 0, NcValue::real(value), at);
}

// NC-PARAM-FLOW-6: a program that keeps jumping back (loop passes, backward jumps, P runs) stops.
// NC-PARAM-FLOW-7: GOTOS ends the run of the main program; in a subprogram it is not simulated.
void Interpreter::gotos_in_the_main_program(std::size_t at) const {
  if (stack_.size() > 1)
    throw InputError(cx().line, static_cast<int>(at) + 1,
                     "GOTOS in a subprogram (a jump to its start) is SINUMERIK NC that cutcom does not simulate");
}

void Interpreter::count_backward_jump() {
  if (++backward_jumps_ > limits_.max_backward_jumps)
    throw InputError(cx().line, 1,
                     fmt::format("the program runs away: more than {} loop passes or backward jumps "
                                 "(NC-PARAM-FLOW-6; raise the limit with --max-loops)",
                                 limits_.max_backward_jumps));
}

void Interpreter::jump_back(const Frame& f) {
  count_backward_jump();
  seek(f.body, f.body_line);
}

bool Interpreter::defines(std::string_view text, std::string_view target) {
  std::string number, label;
  block_prefix(text, &number, &label);
  if (target.size() > 1 && target[0] == 'N' && is_digit(target[1])) return "N" + number == target;
  return label == target;
}

void Interpreter::jump(std::string_view target, bool forward, bool backward, bool must_exist, std::size_t at) {
  control_flow_ = true;
  int from_line = cx().line;
  std::streamoff from = cx().offset;
  // A target the whole file was searched for in vain is not looked for again: a GOTOC to a
  // missing label in a loop costs no scan of the file per pass.
  // Likewise a forward search from this line that failed (a GOTOC back to a label behind it).
  std::set<std::string>& absent = absent_targets_[cx().path];
  bool known_absent = forward && backward && absent.count(std::string(target)) > 0;
  std::string here = std::string(target) + '@' + std::to_string(from_line);
  bool ahead_absent = forward && absent.count(here) > 0;
  Passed passed;
  if (known_absent || ahead_absent) {
    // nothing to search ahead
  } else if (forward && find_forward(target, &passed)) {
    leave_structures(passed);
    return;
  }
  if (forward && !known_absent && !ahead_absent) absent.insert(here);
  if (backward && !known_absent) {
    if (forward) seek(from, from_line);
    if (find_backward(target, from_line)) {
      leave_structures_from(cx().line + 1);
      return;
    }
  }
  if (forward && backward) absent.insert(std::string(target));
  if (!must_exist) {  // GOTOC: no target, no jump
    seek(from, from_line);
    return;
  }
  throw InputError(from_line, static_cast<int>(at) + 1,
                   fmt::format("jump target '{}' not found {}", target,
                               forward && backward ? "in the program"
                               : forward           ? "after this block"
                                                   : "before this block"));
}

bool Interpreter::find_forward(std::string_view target, Passed* passed) {
  std::string text;
  int if_depth = 0, loop_depth = 0;  // structures opened and closed on the way
  while (true) {
    std::streamoff start = cx().offset;
    int line = cx().line;
    if (!getline(text)) return false;
    std::string label;
    block_prefix(text, nullptr, &label);
    if (!label.empty()) note_label(label, start, line);
    if (defines(text, target)) {
      seek(start, line);
      return true;
    }
    if (!passed) continue;
    std::size_t rest;
    std::string w = first_word(text, rest);
    if (w == "IF" && !has_jump(text)) {
      ++if_depth;
    } else if (w == "ENDIF") {
      if (if_depth > 0)
        --if_depth;
      else
        ++passed->ifs;
    } else if (w == "WHILE" || w == "FOR" || w == "LOOP" || (w == "REPEAT" && skip_space(text, rest) >= text.size())) {
      ++loop_depth;
    } else if (w == "ENDWHILE" || w == "ENDFOR" || w == "ENDLOOP" || w == "UNTIL") {
      if (loop_depth > 0)
        --loop_depth;
      else
        ++passed->loops;
    }
  }
}

// NC-PARAM-FLOW-1: a jump forward out of IF branches and loops ends them (their end words were
// passed); a jump back to before where one opened ends it too (it opens again when run).
void Interpreter::leave_structures(const Passed& passed) {
  for (int k = 0; k < passed.ifs && !cx().open_ifs.empty(); ++k) cx().open_ifs.pop_back();
  for (int k = 0; k < passed.loops && !cx().frames.empty(); ++k) cx().frames.pop_back();
}

void Interpreter::leave_structures_from(int target_line) {
  while (!cx().open_ifs.empty() && cx().open_ifs.back() >= target_line) cx().open_ifs.pop_back();
  while (!cx().frames.empty() && cx().frames.back().open_line >= target_line) cx().frames.pop_back();
}

// A label's place, kept once however often its line is read (a loop passes it every time).
void Interpreter::note_label(const std::string& label, std::streamoff start, int line) {
  auto& seen = cx().labels_seen[label];
  for (const auto& p : seen)
    if (p.first == start) return;
  seen.push_back({start, line});
}

bool Interpreter::find_backward(std::string_view target, int before_line) {
  count_backward_jump();
  auto it = cx().labels_seen.find(std::string(target));
  if (it != cx().labels_seen.end()) {
    const std::pair<std::streamoff, int>* best = nullptr;
    for (const auto& p : it->second)
      if (p.second < before_line && (!best || p.second > best->second)) best = &p;
    if (best) {
      seek(best->first, best->second);
      return true;
    }
  }
  // A block number (or a label not seen): read the program again from its start.
  seek(cx().start_offset, cx().start_line);
  std::string text;
  std::optional<std::pair<std::streamoff, int>> found;
  while (cx().line < before_line) {
    std::streamoff start = cx().offset;
    int line = cx().line;
    if (!getline(text)) break;
    if (cx().line < before_line && defines(text, target)) found = {start, line};
  }
  if (!found) return false;
  seek(found->first, found->second);
  return true;
}

std::optional<std::pair<std::streamoff, int>> Interpreter::locate(std::string_view target, bool backward,
                                                                  bool forward) {
  std::streamoff from = cx().offset;
  int from_line = cx().line;
  std::optional<std::pair<std::streamoff, int>> found;
  if (backward && find_backward(target, from_line)) found = std::make_pair(cx().offset, cx().line);
  if (!found && forward) {
    seek(from, from_line);
    if (find_forward(target)) found = std::make_pair(cx().offset, cx().line);
  }
  seek(from, from_line);
  return found;
}

// NC-PARAM-FLOW-5: REPEAT start P=n repeats the blocks from the label `start` up to the block
// before the REPEAT; REPEAT start end P=n from `start` to the block of `end` (ENDLABEL: the
// block labelled so); REPEATB label P=n the one block. P left out: once. Afterwards the program
// goes on after the REPEAT block.
void Interpreter::repeat_section(std::string_view s, std::size_t rest, bool one_block) {
  InterpreterLookup lookup(*this, cx().line);
  const char* word = one_block ? "REPEATB" : "REPEAT";
  auto target_at = [&](std::size_t& i) {
    i = skip_space(s, i);
    std::size_t e = name_end(s, i);
    std::string t = upper_text(s.substr(i, e - i));
    std::size_t at = i;
    i = skip_space(s, e);
    return std::make_pair(t, at);
  };
  std::size_t i = rest;
  auto [start, start_at] = target_at(i);
  if (start.empty() || (start == "P" && i < s.size() && s[i] == '='))
    throw InputError(cx().line, static_cast<int>(start_at) + 1,
                     fmt::format("{} needs the label or block number where the section starts", word));
  std::string end;
  std::size_t end_at = 0;
  if (!one_block && i < s.size() && s[i] != ';' &&
      !(upper(s[i]) == 'P' && skip_space(s, i + 1) < s.size() && s[skip_space(s, i + 1)] == '=')) {
    std::tie(end, end_at) = target_at(i);
    if (end.empty())
      throw InputError(cx().line, static_cast<int>(end_at) + 1, "the label where the section ends is expected");
  }
  int passes = 1;
  if (i < s.size() && upper(s[i]) == 'P') {
    std::size_t v = skip_space(s, i + 1);
    if (v >= s.size() || s[v] != '=') throw InputError(cx().line, static_cast<int>(i) + 1, "P=n expected");
    ExpressionParser p(s, v + 1, cx().line, lookup);
    NcValue count = p.parse();
    if (count.type == NcValue::Type::kString || count.number < 1 || count.number > 1e6 ||
        count.number != std::trunc(count.number))
      throw InputError(cx().line, static_cast<int>(i) + 1,
                       "P (the number of repetitions) must be a whole number from 1");
    passes = static_cast<int>(count.number);
    i = skip_space(s, p.position());
  }
  if (i < s.size() && s[i] != ';')
    throw InputError(cx().line, static_cast<int>(i) + 1, fmt::format("unexpected text after {}", word));
  control_flow_ = true;
  // REPEAT label P=n: the section lies before; otherwise searched towards the start first.
  bool only_back = !one_block && end.empty();
  auto first = locate(start, true, !only_back);
  if (!first)
    throw InputError(cx().line, static_cast<int>(start_at) + 1,
                     fmt::format("the section's start '{}' is not found {}", start,
                                 only_back ? "before this block" : "in the program"));
  Context::Section section{first->first, first->second, 0, passes, cx().offset, cx().line};
  if (end.empty()) {
    section.last_line = one_block ? first->second + 1 : cx().line - 1;
  } else {  // the end label: from the start on
    seek(first->first, first->second);
    std::string text;
    getline(text);
    if (!defines(text, end)) {
      if (!find_forward(end))
        throw InputError(section.resume_line, static_cast<int>(end_at) + 1,
                         fmt::format("the section's end '{}' is not found after its start", end));
    }
    section.last_line = defines(text, end) ? first->second + 1 : cx().line + 1;
  }
  if (section.last_line <= section.start_line) {  // REPEAT label in the block right after the label's? none to run
    seek(section.resume, section.resume_line);
    return;
  }
  count_backward_jump();
  seek(section.start, section.start_line);
  cx().sections.push_back(section);
}

void Interpreter::end_section_pass() {
  Context::Section& sec = cx().sections.back();
  if (--sec.passes_left > 0) {
    count_backward_jump();
    seek(sec.start, sec.start_line);
    return;
  }
  Context::Section done = sec;
  cx().sections.pop_back();
  seek(done.resume, done.resume_line);
}

// NC-PARAM-FLOW-5: CASE (expression) OF value GOTOF target … DEFAULT GOTOF target: the first
// value equal to the expression's jumps; none equal: DEFAULT's jump, or on with the next block.
void Interpreter::case_jump(std::string_view s, std::size_t rest) {
  InterpreterLookup lookup(*this, cx().line);
  ExpressionParser p(s, rest, cx().line, lookup);
  NcValue v = p.parse();
  std::size_t i = skip_space(s, p.position());
  std::size_t e = name_end(s, i);
  if (upper_text(s.substr(i, e - i)) != "OF") throw InputError(cx().line, static_cast<int>(i) + 1, "CASE needs OF");
  i = skip_space(s, e);
  std::optional<std::pair<std::string, std::size_t>> chosen;
  std::string chosen_jump;
  while (i < s.size() && s[i] != ';') {
    std::size_t at = i;
    std::size_t we = name_end(s, i);
    bool is_default = upper_text(s.substr(i, we - i)) == "DEFAULT";
    bool equal = false;
    if (is_default) {
      i = skip_space(s, we);
    } else {
      ExpressionParser c(s, i, cx().line, lookup);
      NcValue constant = c.parse();
      if ((constant.type == NcValue::Type::kString) != (v.type == NcValue::Type::kString))
        throw InputError(cx().line, static_cast<int>(at) + 1, "a CASE value must be of the expression's type");
      equal = v.type == NcValue::Type::kString ? constant.text == v.text : constant.number == v.number;
      i = skip_space(s, c.position());
    }
    std::size_t je = name_end(s, i);
    std::string jump_word = upper_text(s.substr(i, je - i));
    if (jump_word != "GOTOF" && jump_word != "GOTOB" && jump_word != "GOTO" && jump_word != "GOTOC")
      throw InputError(cx().line, static_cast<int>(i) + 1, "GOTOF or GOTOB and a target expected after a CASE value");
    std::size_t t = skip_space(s, je);
    std::size_t te = name_end(s, t);
    std::string target = upper_text(s.substr(t, te - t));
    if (target.empty())
      throw InputError(cx().line, static_cast<int>(t) + 1, fmt::format("{} needs a label or block number", jump_word));
    if (!chosen && (equal || is_default)) chosen = std::make_pair(target, t), chosen_jump = jump_word;
    i = skip_space(s, te);
    if (is_default && i < s.size() && s[i] != ';')
      throw InputError(cx().line, static_cast<int>(i) + 1, "DEFAULT is the last choice of CASE");
  }
  control_flow_ = true;
  if (chosen)
    jump(chosen->first, chosen_jump != "GOTOB", chosen_jump != "GOTOF", chosen_jump != "GOTOC", chosen->second);
}

// Skips to the end of a structure: nested ones counted by their opening word.
std::string Interpreter::skip_block(std::string_view open, std::string_view end, bool or_else) {
  int start_line = cx().line;
  int depth = 0;
  std::string text;
  while (true) {
    std::streamoff start = cx().offset;
    int line = cx().line;
    if (!getline(text)) break;
    std::string label;
    block_prefix(text, nullptr, &label);
    if (!label.empty()) note_label(label, start, line);
    std::size_t rest;
    std::string w = first_word(text, rest);
    if (w == open && !(open == "IF" && has_jump(text))) {
      ++depth;
    } else if (w == end) {
      if (depth == 0) return w;
      --depth;
    } else if (or_else && depth == 0 && w == "ELSE") {
      return w;
    }
  }
  throw InputError(start_line, 1, fmt::format("{} without its {}", open, end));
}
}  // namespace cutcom
