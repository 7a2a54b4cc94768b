// The interpreter layer (interpreter.hpp; spec nc-parametric.md): the line loop, and a block's
// words and assignments; the reader gets plain blocks with every computed value written on the
// 10^-9 grid. Positions in the text are counted here (not asked of the stream per line).
#include "cutcom/interpreter.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "interpreter_lookup.hpp"
#include "interpreter_record.hpp"
#include "interpreter_text.hpp"
#include "nc_expression.hpp"
#include "nc_vocabulary.hpp"
#include "word_lexer.hpp"

namespace cutcom {

using namespace interpreter_text;

Interpreter::Interpreter(std::istream& in, SystemValues* system, InterpreterLimits limits)
    : system_(system), limits_(limits) {
  stack_.emplace_back();
  cx().in = &in;
  cx().cache = &line_caches_[""];
  std::streampos p = in.tellg();
  cx().offset = cx().start_offset = p == std::streampos(-1) ? 0 : static_cast<std::streamoff>(p);
  cx().stream_at = cx().offset;
}

void LineRecordDeleter::operator()(LineRecord* r) const { delete r; }

bool Interpreter::maybe_parametric(const std::string& s) {
  // One table look-up per character (every line of a program passes here); the runs of digits,
  // signs, points and spaces between letters are skipped up to the string's terminating NUL.
  enum : std::uint8_t { kName = 1, kAssign = 2, kComment = 4, kCall = 8, kNul = 16 };
  static constexpr std::array<std::uint8_t, 256> kClass = [] {
    std::array<std::uint8_t, 256> t{};
    for (int c = 0; c < 256; ++c)
      if (is_letter(static_cast<char>(c)) || c == '_') t[static_cast<std::size_t>(c)] = kName;
    t['='] = t[':'] = kAssign, t[';'] = kComment;
    t['L'] |= kCall, t['l'] |= kCall, t[0] = kNul;
    return t;
  }();
  const auto *begin = reinterpret_cast<const unsigned char*>(s.c_str()), *p = begin, *end = begin + s.size();
  while (true) {
    while (kClass[*p] == 0) ++p;
    std::uint8_t c = kClass[*p];
    if (c & kNul) {  // the end, or a NUL inside the line: nothing, as any other character of class 0
      if (p++ == end) return false;
      continue;
    }
    if (c & (kComment | kAssign)) return (c & kAssign) != 0;
    if (kClass[p[1]] & kName) return true;  // two letters: a name (p[1] is at most the final NUL)
    // Ln: a subprogram call (NC-PARAM-SUB-1)
    if ((c & kCall) && is_digit(static_cast<char>(p[1])) && (p == begin || !is_name_char(static_cast<char>(p[-1]))))
      return true;
    ++p;
  }
}

Interpreter::Variable* Interpreter::find_variable(const std::string& name) {
  auto it = cx().variables.find(name);
  if (it != cx().variables.end()) return &it->second;
  auto global = globals_.find(name);  // NC-PARAM-VAR-3: GUD, seen at every level
  return global == globals_.end() ? nullptr : &global->second;
}

NcValue Interpreter::evaluate(std::string_view expression, int line) {
  InterpreterLookup lookup(*this, line);
  ExpressionParser p(expression, 0, line, lookup);
  NcValue v = p.parse();
  if (skip_space(expression, p.position()) != expression.size())
    throw InputError(line, static_cast<int>(p.position()) + 1, "unexpected text after the expression");
  return v;
}

// NC-WORD-2: a skip block of a level the operator switched on is left out whole (its label stays
// a jump target).
bool Interpreter::skipped(const std::string& s) {
  std::size_t k = skip_space(s, 0);
  if (k >= s.size() || s[k] != '/') return false;
  int level = k + 1 < s.size() && is_digit(s[k + 1]) ? s[k + 1] - '0' : 0;
  if ((skip_levels_ & (1u << level)) == 0) return false;
  std::string number, label;
  block_prefix(s, &number, &label);
  if (!label.empty()) note_label(label, cx().line_start, cx().line - 1);
  return true;
}

bool Interpreter::next(std::string& text, int& line, BlockWords* plain) {
  if (plain) plain->plain = false;
  plain_refused_ = false;
  while (true) {
    if (pending_next_ < pending_.size()) {  // NC-PARAM-FRAME-1: the blocks of a frame assignment
      text = pending_[pending_next_++];
      line = pending_line_;
      return true;
    }
    try {
      if (modal_call_due_) {  // NC-PARAM-SUB-6: the block before moved
        modal_call_due_ = false;
        ModalCall m = *modal_call_;
        enter(m.file, std::move(m.args), std::move(m.names), 1, 0);
        continue;
      }
      // NC-PARAM-FLOW-5: the last block of a repeated section has run.
      if (!cx().sections.empty() && cx().line == cx().sections.back().last_line) {
        end_section_pass();
        continue;
      }
      std::string_view view;  // the line where it lies (the file's buffer, the line cache)
      bool read = getline(view);
      current_cached_ = last_cached_;
      bool copied = false;  // the line is in raw_
      if (read && (!macros_.empty() || skip_levels_ != 0)) {
        raw_.assign(view), copied = true;
        if (!macros_.empty()) expand_macros(raw_);
        if (skip_levels_ != 0 && skipped(raw_)) continue;
        view = raw_;
      }
      if (!read) {
        if (!cx().frames.empty())
          throw InputError(cx().line, 1, "the program ends inside a loop (WHILE, FOR, LOOP or REPEAT without its end)");
        if (!cx().open_ifs.empty()) throw InputError(cx().open_ifs.back(), 1, "IF without its ENDIF");
        if (stack_.size() == 1) return false;
        leave_subprogram();  // NC-PARAM-SUB-2: the end of the file returns
        continue;
      }
      // NC-PARAM-EXPR-4: a line of assignments and words that ran before runs from its plan.
      if (current_cached_ && current_cached_->record && current_cached_->record->plan &&
          run_plan(*current_cached_->record, text)) {
        if (text.empty()) continue;
        line = stack_.size() == 1 ? cx().line : stack_.front().line;
        return true;
      }
      if (stack_.size() == 1 && plain) {
        plain->reset(cx().line);
        // no name, '=' or ':': not parametric
        if (lexer::read_plain_block(view, *plain, !copied && line_padded_)) {
          plain->plain = true;
          line = cx().line;
          return true;
        }
      }
      if (!copied) raw_.assign(view);
      if (stack_.size() == 1 && !maybe_parametric(raw_)) {
        text.swap(raw_);
        line = cx().line;
        plain_refused_ = plain != nullptr;  // the text read_plain_block was given just now
        return true;
      }
      run_line(raw_, text);
    } catch (const InputError& e) {
      throw where(e);
    }
    if (text.empty()) continue;                                   // a statement only
    line = stack_.size() == 1 ? cx().line : stack_.front().line;  // NC-PARAM-SUB-3
    return true;
  }
}

// NC-PARAM-SUB-7: every name that is a macro, outside strings and comments, becomes its text (a
// DEFINE line itself is left as written: a macro may be defined again).
void Interpreter::expand_macros(std::string& line) const {
  std::size_t rest;
  if (first_word(line, rest) == "DEFINE") return;
  std::string out;
  bool changed = false;
  for (std::size_t i = 0; i < line.size();) {
    char c = line[i];
    if (c == ';') {  // the comment as written
      out.append(line, i, std::string::npos);
      break;
    }
    if (c == '"') {
      std::size_t e = line.find('"', i + 1);
      e = e == std::string::npos ? line.size() : e + 1;
      out.append(line, i, e - i);
      i = e;
      continue;
    }
    if (is_letter(c) || c == '_' || c == '$') {
      std::size_t e = name_end(line, i);
      if (e == i) e = i + 1;
      auto m = macros_.find(upper_text(std::string_view(line).substr(i, e - i)));
      if (m != macros_.end()) {
        out += m->second;
        changed = true;
      } else {
        out.append(line, i, e - i);
      }
      i = e;
      continue;
    }
    out += c;
    ++i;
  }
  if (changed) line = std::move(out);
}

void Interpreter::run_line(const std::string& s, std::string& out) {
  out.clear();
  std::string number, label;
  std::size_t i = block_prefix(s, &number, &label);
  if (label.empty()) {
    out.append(s, 0, i);
  } else {  // the label is the interpreter's: the reader gets the block skip and number only
    note_label(label, cx().line_start, cx().line - 1);
    control_flow_ = true;
    std::size_t k = skip_space(s, 0);
    if (k < s.size() && s[k] == '/') {
      out += '/';
      if (k + 1 < s.size() && is_digit(s[k + 1])) out += s[k + 1];
      out += ' ';
    }
    if (!number.empty()) out += "N" + number + " ";
  }
  std::size_t rest;
  std::string first = first_word(s, rest);
  // NC-PARAM-EXPR-4: the first run of a cached line records its plan, if it has one.
  std::optional<LinePlan> plan;
  LineRecord* record = nullptr;
  if (current_cached_ && &s == &raw_ && label.empty() && first != "MCALL") {
    record = &record_of(*current_cached_);
    if (!record->plan_tried) plan.emplace();
    record->plan_tried = true;
  }
  if (statement(first, s, rest)) {  // a statement line yields no block (but IF … GOTOS)
    out.clear();
    out.swap(statement_block_);
    return;
  }
  if (call(s, i)) {
    out.clear();
    return;
  }
  InterpreterLookup lookup(*this, cx().line);
  bool words = false;
  while (true) {
    std::size_t space = i;  // the text's own spacing is kept: the lexer's columns stay close
    i = skip_space(s, i);
    if (i >= s.size()) break;
    char c = s[i];
    if (c == ';') {
      out.append(s, space, std::string::npos);
      break;
    }
    if (c == '"') {  // a string outside a word: copied
      std::size_t e = s.find('"', i + 1);
      e = e == std::string::npos ? s.size() : e + 1;
      out.append(s, space, e - space);
      i = e;
      continue;
    }
    if (!is_letter(c) && c != '$' && c != '_') {
      out.append(s, space, i + 1 - space);  // the lexer names what is wrong
      ++i;
      words = true;
      continue;
    }
    std::size_t start = i;
    std::size_t j = name_end(s, i);
    std::string n = upper_text(s.substr(i, j - i));
    std::size_t after = skip_space(s, j);
    // NC-WORD-9: a synchronized action's condition and actions are read while the blocks run,
    // not now: the rest of the block goes to the lexer as written.
    if (starts_synchronized_action(n)) {
      plan.reset();
      out.append(s, space, std::string::npos);
      words = true;
      break;
    }
    // NC-PARAM-ERR-2: the program raises an alarm of its own and the control stops.
    if (n == "SETAL" && after < s.size() && s[after] == '(') {
      std::size_t e = after + 1;
      std::vector<NcValue> args = values(s, e, ')', lookup);
      std::string alarm = args.empty() ? "?" : grid_text(args[0], cx().line, after);
      throw InputError(cx().line, static_cast<int>(start) + 1,
                       fmt::format("the program raises alarm {} (SETAL): the control stops here", alarm));
    }
    // MSG(expression): the message as the operator would read it.
    if (n == "MSG" && after < s.size() && s[after] == '(' && skip_space(s, after + 1) < s.size() &&
        s[skip_space(s, after + 1)] != ')') {
      plan.reset();
      ExpressionParser p(s, after + 1, cx().line, lookup);
      NcValue text = p.parse();
      std::size_t e = skip_space(s, p.position());
      if (e >= s.size() || s[e] != ')') throw InputError(cx().line, static_cast<int>(e) + 1, "MSG: ')' expected");
      std::string shown = text.type == NcValue::Type::kString ? text.text : grid_text(text, cx().line, after);
      for (char& ch : shown)
        if (ch == '"') ch = '\'';
      out.append(s, space, start - space);
      out += "MSG(\"" + shown + "\")";
      words = true;
      i = e + 1;
      continue;
    }
    // NC-PARAM-FLOW-7: GOTOS, back to the program's start: one pass is shown, so it ends the run
    // as M30 would (the lexer keeps it as the block's end).
    if (n == "GOTOS") {
      gotos_in_the_main_program(start);
      plan.reset();
      control_flow_ = true;
      out.append(s, space, std::string::npos);
      words = true;
      break;
    }
    // Jumps end a block's words (NC-PARAM-FLOW-1).
    if (n == "GOTOF" || n == "GOTOB" || n == "GOTO" || n == "GOTOC") {
      plan.reset();
      std::size_t t = skip_space(s, j);
      std::size_t te = name_end(s, t);
      std::string target = upper_text(s.substr(t, te - t));
      if (target.empty())
        throw InputError(cx().line, static_cast<int>(t) + 1, fmt::format("{} needs a label or block number", n));
      std::string keep = out;
      jump(target, n != "GOTOB", n != "GOTOF", n != "GOTOC", start);
      out = words ? keep : std::string();
      return;
    }
    // AX[axis]=value: the axis named by an AXIS variable or written out (indirect axis
    // programming); the reader gets the axis' own word.
    std::string axis_word;
    if (n == "AX" && after < s.size() && s[after] == '[') {
      plan.reset();
      std::size_t from = skip_space(s, after + 1), to = name_end(s, from), close = skip_space(s, to);
      if (close >= s.size() || s[close] != ']')
        throw InputError(cx().line, static_cast<int>(from) + 1,
                         "AX[...]: an axis name or an AXIS variable is expected");
      axis_word = upper_text(s.substr(from, to - from));
      if (find_variable(axis_word)) {
        NcValue held = lookup.read(axis_word, {}, from);
        axis_word = held.type == NcValue::Type::kString ? upper_text(held.text) : std::string();
      }
      if (axis_word.empty() || !is_letter(axis_word[0]))
        throw InputError(cx().line, static_cast<int>(from) + 1,
                         "AX[...]: an axis name or an AXIS variable is expected");
      j = close + 1;
      after = skip_space(s, j);
      if (after >= s.size() || s[after] != '=')
        throw InputError(cx().line, static_cast<int>(after) + 1, "AX[...] is given a value with '='");
      n = axis_word;
    }
    std::vector<NcValue> indices;
    std::size_t k = after;
    bool indexed = k < s.size() && s[k] == '[';
    bool r_indexed = indexed && n == "R";
    bool variable = is_r_parameter(n) || r_indexed || find_variable(n) != nullptr;
    if (indexed || n[0] == '$') plan.reset();
    if (plan && !variable) plan->words.push_back(n);
    if (n == "$P_UIFR" && after < s.size() && s[after] == '[') {  // NC-PARAM-SYS-2
      i = settable_offset(s, after);
      continue;
    }
    if (n == "$P_IFRAME" && after < s.size() && (s[after] == '[' || s[after] == '=')) {  // NC-PARAM-SYS-5
      i = settable_offset(s, after, true);
      continue;
    }
    if (n == "$P_PFRAME" && after < s.size() && (s[after] == '=' || s[after] == '[')) {  // NC-PARAM-FRAME-1/2
      std::size_t end = after;
      NcValue frame = s[after] == '[' ? frame_component_assignment(s, after, end) : NcValue{};
      if (s[after] == '=') {
        ExpressionParser p(s, after + 1, cx().line, lookup);
        frame = p.parse();
        if (frame.type != NcValue::Type::kFrame)
          throw InputError(cx().line, static_cast<int>(after) + 2, "$P_PFRAME is assigned a value that is not a frame");
        end = p.position();
      }
      end = skip_space(s, end);
      if (words || (end < s.size() && s[end] != ';'))
        throw InputError(cx().line, static_cast<int>(start) + 1,
                         "a $P_PFRAME assignment must stand in a block of its own, as a frame instruction does");
      // The programmable frame is replaced: TRANS alone resets it, then the chain's blocks.
      pending_.assign({"TRANS"});
      for (std::size_t from = 0; from < frame.text.size();) {
        std::size_t e = frame.text.find('\n', from);
        if (e == std::string::npos) e = frame.text.size();
        pending_.emplace_back(frame.text.substr(from, e - from));
        from = e + 1;
      }
      pending_next_ = 0;
      pending_line_ = stack_.size() == 1 ? cx().line : stack_.front().line;
      out.clear();
      return;
    }
    bool tool_data = n.rfind("$TC_", 0) == 0;  // other system variables go to the lexer as written
    if (indexed && (variable || tool_data)) {
      // Indices as expressions: R[expr], A[i,j], $TC_DP6[t,d].
      std::size_t e = k + 1;
      indices = values(s, e, ']', lookup);
      k = skip_space(s, e);
    }
    std::string raw_index;  // an address word's index (SPOS[1]=, ACC[X]=): kept as written
    if (indexed && !variable && !tool_data && (n[0] != '$' || is_machine_output(n))) {
      std::size_t close = s.find(']', k);
      if (close != std::string_view::npos) {
        std::size_t after_index = skip_space(s, close + 1);
        if (after_index < s.size() && s[after_index] == '=' &&
            !(after_index + 1 < s.size() && s[after_index + 1] == '=')) {
          for (char ch : s.substr(k, close + 1 - k))
            if (ch != ' ' && ch != '\t') raw_index += upper(ch);
          k = after_index;
          plan.reset();
        }
      }
    }
    bool assignment = k < s.size() && s[k] == '=' && !(k + 1 < s.size() && s[k + 1] == '=');
    if (n[0] == '$' && !tool_data && raw_index.empty() && !is_machine_counter(n)) assignment = false;
    if (!assignment) {
      if (variable && !indexed && !is_r_parameter(n))
        throw InputError(cx().line, static_cast<int>(start) + 1,
                         fmt::format("'{}' is a variable: a value is assigned with '='", n));
      // A plain word: copied as written up to the next word.
      std::size_t e = j;
      int depth = 0;
      bool quoted = false;
      while (e < s.size()) {
        char d = s[e];
        if (d == '"') quoted = !quoted;
        if (!quoted) {
          if (d == '(' || d == '[') ++depth;
          if (d == ')' || d == ']') --depth;
          if (depth <= 0 && (d == ' ' || d == '\t' || d == ';')) break;
          if (depth <= 0 && (is_letter(d) || d == '$') && e > j && !is_letter(s[e - 1]) && s[e - 1] != '_' &&
              s[e - 1] != '$')
            break;  // "X10Y20": the next address starts
        }
        ++e;
      }
      out.append(s, space, e - space);
      words = true;
      i = e;
      continue;
    }
    std::size_t v = skip_space(s, k + 1);
    if (is_machine_counter(n)) {  // NC-WORD-7: the value goes to the reader; later reads see it
      plan.reset();
      std::size_t value_end;
      NcValue value = expression(s, v, lookup, value_end, nullptr);
      std::string t = grid_text(value, cx().line, v);
      machine_values_[n] = NcValue::real(value.number);
      out.append(s, space, j - space);
      out += '=';
      out += t;
      words = true;
      i = value_end;
      continue;
    }
    if (variable) {  // NC-PARAM-VAR-*: an assignment, run now; the reader never sees it
      std::size_t value_end;
      int recorded;
      NcValue value = expression(s, v, lookup, value_end, &recorded);
      if (recorded < 0 || r_indexed || (is_r_parameter(n) && r_number(n) >= kRParameters)) plan.reset();
      if (plan) {
        bool r = is_r_parameter(n);
        plan->steps.push_back({r ? LinePlan::Step::Kind::kAssignR : LinePlan::Step::Kind::kAssignVariable,
                               recorded,
                               r ? r_number(n) : 0,
                               {},
                               start,
                               v});
        if (!r) plan->names.push_back(n);
      }
      if (r_indexed) {
        r_[lookup.r_index(indices[0], start)] = value.type == NcValue::Type::kString ? 0 : value.number;
        if (value.type == NcValue::Type::kString)
          throw InputError(cx().line, static_cast<int>(v) + 1, "an R parameter holds a number, not a string");
      } else if (is_r_parameter(n)) {
        int r = r_number(n);
        if (r >= kRParameters)
          throw InputError(cx().line, static_cast<int>(start) + 1, fmt::format("R parameter {} does not exist", n));
        if (value.type == NcValue::Type::kString)
          throw InputError(cx().line, static_cast<int>(v) + 1, "an R parameter holds a number, not a string");
        r_[r] = value.number;
      } else {
        Variable& var = *find_variable(n);
        store(var, lookup.offset(n, var, indices, start), value, start);
      }
      i = value_end;
      continue;
    }
    // An address with a value: a literal is copied as written (exact); an expression is
    // evaluated and written on the grid (NC-PARAM-GRID-1). AC(...)/IC(...) keep their wrapper.
    words = true;
    if (axis_word.empty()) {
      out.append(s, space, j - space);
    } else {
      out.append(s, space, start - space);
      out += axis_word;
    }
    out += raw_index;
    if (!indices.empty()) {
      out += '[';
      for (std::size_t q = 0; q < indices.size(); ++q) out += (q ? "," : "") + grid_text(indices[q], cx().line, start);
      out += ']';
    }
    out += '=';
    // Value modes the lexer reads around a value: AC(…), IC(…), PM(…) …
    // QU(…): an auxiliary function's quick output (M=QU(8)): for the path, its value alone.
    static constexpr std::string_view kWrappers[] = {"AC",  "IC",  "ACN",  "ACP",  "DC",  "PM", "PR",
                                                     "CAC", "CIC", "CACN", "CACP", "CDC", "QU"};
    std::string wrapper;
    std::size_t w = name_end(s, v);
    std::string wn = upper_text(s.substr(v, w - v));
    std::size_t open = skip_space(s, w);
    bool wrapped = false;
    for (std::string_view x : kWrappers) wrapped = wrapped || wn == x;
    if (wrapped && open < s.size() && s[open] == '(') {
      wrapper = wn;
      v = skip_space(s, open + 1);
    }
    std::optional<std::size_t> lit = literal_end(s, v);
    std::size_t end;
    if (lit && (wrapper.empty() || (skip_space(s, *lit) < s.size() && s[skip_space(s, *lit)] == ')'))) {
      std::string value(s.substr(v, *lit - v));
      out += wrapper.empty() || wrapper == "QU" ? value : wrapper + "(" + value + ")";
      end = wrapper.empty() ? *lit : skip_space(s, *lit) + 1;
    } else {
      int recorded;
      NcValue value = expression(s, v, lookup, end, &recorded);
      if (!wrapper.empty()) {
        end = skip_space(s, end);
        if (end >= s.size() || s[end] != ')') throw InputError(cx().line, static_cast<int>(end) + 1, "')' expected");
        ++end;
      }
      std::string t = grid_text(value, cx().line, v);
      if (recorded < 0) plan.reset();
      if (plan) {
        std::size_t at = out.size() + (wrapper.empty() || wrapper == "QU" ? 0 : wrapper.size() + 1);
        plan->steps.push_back({LinePlan::Step::Kind::kValue, recorded, 0, {}, start, v, at, t.size()});
      }
      out += wrapper.empty() || wrapper == "QU" ? t : wrapper + "(" + t + ")";
    }
    i = end;
  }
  if (!words) out.clear();
  if (plan) {  // the block's text without its values, and where they go
    std::size_t from = 0;
    for (LinePlan::Step& step : plan->steps) {
      if (step.kind != LinePlan::Step::Kind::kValue) continue;
      plan->text.append(out, from, step.text_at - from);
      from = step.text_at + step.length;
      step.text_at = plan->text.size();
    }
    plan->text.append(out, from, std::string::npos);
    std::size_t bytes = sizeof(LinePlan) + plan->text.size() + plan->steps.size() * sizeof(LinePlan::Step) +
                        32 * (plan->names.size() + plan->words.size());
    if (cached_bytes_ + bytes <= limits_.line_cache_bytes) {
      cached_bytes_ += bytes;
      record->plan = std::move(plan);
    }
  }
}

// expr, expr, … up to `close`, from i (just after the opening bracket); i ends after `close`.
std::vector<NcValue> Interpreter::values(std::string_view s, std::size_t& i, char close, InterpreterLookup& lookup) {
  std::vector<NcValue> out;
  while (true) {
    ExpressionParser p(s, i, cx().line, lookup);
    out.push_back(p.parse());
    i = skip_space(s, p.position());
    if (i < s.size() && s[i] == ',') {
      ++i;
      continue;
    }
    if (i < s.size() && s[i] == close) {
      ++i;
      return out;
    }
    throw InputError(cx().line, static_cast<int>(i) + 1, fmt::format("'{}' or ',' expected", close));
  }
}

void Interpreter::store(Variable& var, std::size_t at_offset, const NcValue& value, std::size_t at) {
  NcValue v = value;
  using T = NcValue::Type;
  if ((var.type == T::kFrame) != (value.type == T::kFrame))  // NC-PARAM-FRAME-1
    throw InputError(cx().line, static_cast<int>(at) + 1,
                     var.type == T::kFrame ? "a FRAME variable is assigned a value that is not a frame"
                                           : "a frame is assigned to a variable that is not a FRAME");
  if (var.type == T::kFrame) {
    var.values[at_offset] = value;
    return;
  }
  bool text = var.type == T::kString;
  if (text != (value.type == T::kString))
    throw InputError(cx().line, static_cast<int>(at) + 1,
                     text ? "a STRING variable is assigned a number" : "a number variable is assigned a string");
  if (var.type == T::kInt) {  // NC-PARAM-TYPE-1: rounded; beyond INT's range an error
    double whole = std::round(value.number);
    if (!NcValue::fits_int(whole))
      throw InputError(cx().line, static_cast<int>(at) + 1,
                       fmt::format("{} is outside the range of INT (-2147483648 to 2147483647)", value.number));
    v = NcValue::integer(whole);
  }
  if (var.type == T::kBool) v = NcValue::boolean(value.number != 0);
  if (var.type == T::kReal) v = NcValue::real(value.number);
  var.values[at_offset] = v;
}
}  // namespace cutcom
