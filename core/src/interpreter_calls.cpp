// Subprograms (NC-PARAM-SUB-*): calls, PROC parameters, returns and where an error in a
// subprogram happened.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "cutcom/interpreter.hpp"
#include "cutcom/reader.hpp"
#include "interpreter_lookup.hpp"
#include "interpreter_text.hpp"
#include "nc_expression.hpp"
#include "nc_vocabulary.hpp"

namespace cutcom {

using namespace interpreter_text;

// NC-PARAM-SUB-3: an error in a subprogram names its file and line and the calls that led there;
// the line it reports is the main program's calling line.
InputError Interpreter::where(const InputError& e) const {
  if (stack_.size() == 1 || e.detail().rfind("in subprogram ", 0) == 0) return e;
  std::string chain = fmt::format("in subprogram {} line {}, column {}", cx().name, e.line(), e.column());
  for (std::size_t k = stack_.size() - 1; k-- > 1;)
    chain += fmt::format(", called from {} line {}", stack_[k].name, stack_[k].line);
  return InputError(stack_.front().line, 1,
                    fmt::format("{} (called from line {}): {}", chain, stack_.front().line, e.detail()));
}

namespace {
// NC-PARAM-SYS-2: a frame value that a settable offset can hold (translations only, NC-OFFSET-2) as
// the CTRANS(…) of its translation; the chain's ATRANS blocks add up while nothing turns or scales.
std::string settable_translation(const std::string& chain, int line, std::size_t at) {
  std::array<Decimal, 3> t{};
  for (std::size_t from = 0; from < chain.size();) {
    std::size_t e = chain.find('\n', from);
    if (e == std::string::npos) e = chain.size();
    std::string_view block(chain.data() + from, e - from);
    from = e + 1;
    std::size_t sp = block.find(' ');
    std::string_view word = block.substr(0, sp);
    for (std::size_t k = sp; k != std::string_view::npos && k < block.size();) {
      std::size_t ke = block.find(' ', k + 1);
      std::string_view item = block.substr(k + 1, ke == std::string_view::npos ? std::string_view::npos : ke - k - 1);
      k = ke;
      if (item.empty()) continue;
      auto v = Decimal::parse(item.substr(item[0] == 'R' ? 4 : 1));
      if (!v.value) throw InputError(line, static_cast<int>(at) + 1, fmt::format("'{}' is not a frame value", item));
      bool neutral = word == "ATRANS" || (word == "AROT" && v.value->is_zero()) ||
                     (word == "ASCALE" && *v.value == Decimal::from_int(1));
      if (!neutral)
        throw InputError(line, static_cast<int>(at) + 1,
                         fmt::format("a settable offset holds translations only: {} {} is not simulated", word, item));
      if (word == "ATRANS") {
        std::size_t a = static_cast<std::size_t>(item[0] - 'X');
        t[a] = t[a] + *v.value;
      }
    }
  }
  return fmt::format("CTRANS(X,{},Y,{},Z,{})", t[0].to_string(), t[1].to_string(), t[2].to_string());
}
}  // namespace

// NC-PARAM-SYS-2: $P_UIFR[n]=frame (CTRANS(X,expr,…), $P_UIFR[k], a chain of them) or
// $P_UIFR[n,X,TR]=expr, from just after the name (at '['); the values are evaluated and the
// assignment, written on the grid, goes to the reader's settable offsets. NC-PARAM-SYS-5, in_force:
// $P_IFRAME=frame or $P_IFRAME[X,TR]=expr from just after the name, to the frame in force.
// Returns where the assignment ends.
std::size_t Interpreter::settable_offset(std::string_view s, std::size_t i, bool in_force) {
  InterpreterLookup lookup(*this, cx().line);
  const char* name = in_force ? "$P_IFRAME" : "$P_UIFR";
  std::size_t open = i;
  std::string text = "$P_UIFR[";
  bool component = false;
  if (in_force) {  // $P_IFRAME=frame or $P_IFRAME[axis, component]=value
    text += "1";
    component = i < s.size() && s[i] == '[';
  } else {
    ExpressionParser index(s, i + 1, cx().line, lookup);
    text += grid_text(index.parse(), cx().line, i + 1);
    i = skip_space(s, index.position());
    component = i < s.size() && s[i] == ',';
  }
  if (component) {  // [n, axis, component]: names, kept as written
    std::size_t close = s.find(']', i);
    if (close == std::string_view::npos) throw InputError(cx().line, static_cast<int>(open) + 1, "']' expected");
    if (in_force) text += ',';
    for (char c : s.substr(in_force ? i + 1 : i, close - (in_force ? i + 1 : i)))
      if (c != ' ' && c != '\t') text += upper(c);
    i = close;
  }
  if (in_force && !component) {
    --i;  // at the '='
  } else if (i >= s.size() || s[i] != ']') {
    throw InputError(cx().line, static_cast<int>(i) + 1, "']' expected");
  }
  i = skip_space(s, i + 1);
  if (i >= s.size() || s[i] != '=') throw InputError(cx().line, static_cast<int>(i) + 1, "'=' expected");
  text += "]=";
  std::size_t value_at = skip_space(s, i + 1);
  ExpressionParser value(s, value_at, cx().line, lookup);
  NcValue v = value.parse();
  i = value.position();
  if (component) {
    text += grid_text(v, cx().line, value_at);
  } else {
    if (v.type != NcValue::Type::kFrame)
      throw InputError(cx().line, static_cast<int>(value_at) + 1,
                       fmt::format("{} is assigned a value that is not a frame", in_force ? name : "$P_UIFR[n]"));
    text += settable_translation(v.text, cx().line, value_at);
  }
  bool taken = false;
  try {
    taken = system_ && (in_force ? system_->write_settable_frame(text) : system_->write_settable_offset(text));
  } catch (const InputError& e) {
    throw InputError(cx().line, static_cast<int>(open) + 1,
                     fmt::format("{}: {}", in_force ? std::string(name) : text, e.detail()));
  }
  if (!taken) throw InputError(cx().line, static_cast<int>(open) + 1, fmt::format("{} cannot be written here", name));
  control_flow_ = true;
  return i;
}

NcValue Interpreter::frame_component_assignment(std::string_view s, std::size_t at, std::size_t& end) {
  InterpreterLookup lookup(*this, cx().line);
  auto expect_name = [&](std::size_t& k) {
    k = skip_space(s, k);
    std::size_t e = name_end(s, k);
    std::string n = upper_text(s.substr(k, e - k));
    k = skip_space(s, e);
    return n;
  };
  std::size_t k = at + 1, axis_at = skip_space(s, k);
  std::string axis = expect_name(k);
  if (find_variable(axis)) {  // an AXIS variable holding the axis' name
    NcValue held = lookup.read(axis, {}, axis_at);
    axis = held.type == NcValue::Type::kString ? upper_text(held.text) : std::string();
  }
  if (axis != "X" && axis != "Y" && axis != "Z")
    throw InputError(cx().line, static_cast<int>(axis_at) + 1,
                     "$P_PFRAME[axis, component]: an axis X, Y or Z is expected");
  if (k >= s.size() || s[k] != ',') throw InputError(cx().line, static_cast<int>(k) + 1, "',' expected");
  ++k;
  std::size_t comp_at = skip_space(s, k);
  std::string comp = expect_name(k);
  if (k >= s.size() || s[k] != ']') throw InputError(cx().line, static_cast<int>(k) + 1, "']' expected");
  k = skip_space(s, k + 1);
  if (k >= s.size() || s[k] != '=') throw InputError(cx().line, static_cast<int>(k) + 1, "'=' expected");
  ExpressionParser value(s, k + 1, cx().line, lookup);
  std::string text = grid_text(value.parse(), cx().line, k + 1);
  end = value.position();
  std::optional<std::string> chain;
  try {
    chain = system_ ? system_->programmable_frame_with(axis[0] - 'X', comp, text) : std::nullopt;
  } catch (const InputError& e) {
    throw InputError(cx().line, static_cast<int>(comp_at) + 1,
                     fmt::format("$P_PFRAME[{},{}]={}: {}", axis, comp, text, e.detail()));
  }
  if (!chain) throw InputError(cx().line, static_cast<int>(at) + 1, "$P_PFRAME cannot be written here");
  return NcValue::frame(*chain);
}

bool Interpreter::reader_knows(const std::string& word) {
  auto known = known_words_.find(word);
  if (known != known_words_.end()) return known->second;
  bool knows = true;
  try {
    BlockWords w;
    parse_block_words(word, 0, w);
  } catch (const InputError&) {
    knows = false;
  }
  if (known_words_.size() < 4096) known_words_.emplace(word, knows);
  return knows;
}

std::uint32_t Interpreter::block_source() {
  if (stack_.size() == 1) return 0;
  std::string key = fmt::format("{} line {}", cx().name, cx().line);
  for (std::size_t k = stack_.size() - 1; k-- > 1;)
    key += fmt::format(", called from {} line {}", stack_[k].name, stack_[k].line);
  auto [it, added] = source_ids_.try_emplace(std::move(key), static_cast<std::uint32_t>(source_names_.size()));
  if (added) source_names_.push_back(it->first);
  return it->second;
}

// The text of a subprogram: a unit of the program's own file (NC-PARAM-SUB-8), else NAME.SPF (or
// .MPF, any case) in the program's folder or the search path (NC-PARAM-SUB-1).
std::optional<Interpreter::SubprogramText> Interpreter::find_subprogram(const std::string& name) const {
  // Looked up once per name: a word met in every pass of a loop does not probe the files again.
  auto known = found_.find(name);
  if (known != found_.end()) return known->second;
  if (!units_scanned_) scan_units();
  std::optional<SubprogramText>& found = found_[name];
  if (auto unit = units_.find(name); unit != units_.end()) {
    if (auto twice = duplicate_units_.find(name); twice != duplicate_units_.end())
      throw InputError(cx().line, 1,
                       fmt::format("the program's file holds two units named {} (lines {} and {}): which one the "
                                   "control keeps depends on how the file is loaded",
                                   name, unit->second.line + 1, twice->second));
    return found = unit->second;
  }
  if (!subprogram_files_) return found;
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string& dir : search_path_.empty() ? std::vector<std::string>{"."} : search_path_)
    for (const std::string& f : {name + ".SPF", name + ".spf", lower + ".spf", lower + ".SPF", name + ".MPF",
                                 name + ".mpf", lower + ".mpf", "_N_" + name + "_SPF", name}) {
      std::string path = dir.empty() ? f : dir + "/" + f;
      std::ifstream probe(path);
      if (probe) return found = SubprogramText{path, "", 0, 0};
    }
  return found;
}

// NC-PARAM-SUB-1: a call: NAME, NAME(arguments), Ln, CALL/PCALL/EXTCALL "NAME", each with P
// repetitions; the subprogram runs before the caller's next block.
bool Interpreter::call(std::string_view s, std::size_t word) {
  std::size_t w = name_end(s, word);
  std::string n = upper_text(s.substr(word, w - word));
  std::size_t i = skip_space(s, w);
  bool modal = n == "MCALL";  // NC-PARAM-SUB-6
  if (modal) {
    if (i >= s.size() || s[i] == ';') {  // MCALL alone ends a modal call (a cycle's too: the reader's)
      modal_call_.reset();
      return false;
    }
    std::size_t e = name_end(s, i);
    std::string target = upper_text(s.substr(i, e - i));
    modal_call_.reset();  // a new MCALL replaces the one in force
    std::optional<SubprogramText> file = find_subprogram(target);
    if (!file) return false;  // a standard cycle, or an error: the lexer names it
    std::vector<std::optional<NcValue>> args;
    std::vector<std::string> names;
    std::size_t k = skip_space(s, e);
    if (k < s.size() && s[k] == '(') {
      arguments(s, ++k, args, names);
      k = skip_space(s, k);
    }
    if (k < s.size() && s[k] != ';')
      throw InputError(cx().line, static_cast<int>(k) + 1, "a modal call takes its block alone");
    control_flow_ = true;
    modal_call_ = ModalCall{*file, std::move(args), std::move(names), stack_.size()};
    return true;
  }
  bool explicit_call = n == "CALL" || n == "PCALL" || n == "EXTCALL";
  bool l_number = false;  // Ln: a call, whatever follows
  if (explicit_call) {
    std::size_t e;
    if (i < s.size() && s[i] == '"') {
      e = s.find('"', i + 1);
      if (e == std::string_view::npos)
        throw InputError(cx().line, static_cast<int>(i) + 1, "the name has no closing '\"'");
      n = upper_text(s.substr(i + 1, e - i - 1));
      ++e;
    } else {
      e = name_end(s, i);
      n = upper_text(s.substr(i, e - i));
    }
    if (n.empty()) throw InputError(cx().line, static_cast<int>(i) + 1, "a subprogram name is expected");
    n = called_name(std::move(n));
    i = skip_space(s, e);
  } else {
    l_number = n.size() > 1 && n[0] == 'L';
    for (std::size_t k = 1; l_number && k < n.size(); ++k) l_number = is_digit(n[k]);
    if (!l_number && (n.size() < 2 || find_variable(n) || is_r_parameter(n))) return false;
    bool next_ok = i >= s.size() || s[i] == ';' || s[i] == '(' ||
                   (upper(s[i]) == 'P' && i + 1 < s.size() && (is_digit(s[i + 1]) || s[i + 1] == '='));
    if (!next_ok) return false;
    // A word the block reader knows (KONT, CDON, G17, X10, CYCLE81, …) is never a call, whatever
    // files the folders hold; but E_…/F_… are ShopMill cycles only by their prefix (NC-CYCLE-1), so
    // the program's own subprogram of that name is called.
    if (!l_number && reader_knows(n) && !(is_shopmill_cycle_name(n) && find_subprogram(n))) return false;
  }
  std::optional<SubprogramText> file = find_subprogram(n);
  if (!file) {
    // NC-CYCLE-3: a cycle of the machine: the block reader takes it as not simulated.
    if (std::find(machine_cycles_.begin(), machine_cycles_.end(), n) != machine_cycles_.end()) return false;
    if (!explicit_call && !l_number) return false;  // not a call: the lexer names the word
    throw InputError(
        cx().line, static_cast<int>(word) + 1,
        fmt::format("subprogram {} not found ({}.SPF or .MPF in the program's folder or --search-path; a cycle of "
                    "the machine itself, not simulated: --machine-cycle {})",
                    n, n, n));
  }
  // Arguments: values now; a VAR parameter's argument is also remembered by name.
  InterpreterLookup lookup(*this, cx().line);
  std::vector<std::optional<NcValue>> args;
  std::vector<std::string> names;
  if (i < s.size() && s[i] == '(') {
    arguments(s, ++i, args, names);
    i = skip_space(s, i);
  }
  int passes = 1;
  if (i < s.size() && upper(s[i]) == 'P') {
    std::size_t v = i + 1;
    if (v < s.size() && s[v] == '=') ++v;
    ExpressionParser p(s, v, cx().line, lookup);
    NcValue count = p.parse();
    if (count.type == NcValue::Type::kString || count.number < 1 || count.number > 9999 ||
        count.number != std::trunc(count.number))
      throw InputError(cx().line, static_cast<int>(i) + 1,
                       "P (the number of runs) must be a whole number from 1 to 9999");
    passes = static_cast<int>(count.number);
    i = skip_space(s, p.position());
  }
  if (i < s.size() && s[i] != ';')
    throw InputError(cx().line, static_cast<int>(i) + 1, "a subprogram call takes its block alone");
  enter(*file, std::move(args), std::move(names), passes, word);
  return true;
}

void Interpreter::enter(const SubprogramText& text, std::vector<std::optional<NcValue>> args,
                        std::vector<std::string> names, int passes, std::size_t word) {
  ++variables_epoch_;  // NC-PARAM-EXPR-4: records resolve their names again
  if (stack_.size() >= kMaxLevels)
    throw InputError(
        cx().line, static_cast<int>(word) + 1,
        fmt::format("more than {} program levels (subprograms calling subprograms: NC-PARAM-SUB-2)", kMaxLevels));
  control_flow_ = true;
  Context c;
  if (text.file.empty()) {  // NC-PARAM-SUB-8: a unit of the main program's text, read from its stream
    c.in = stack_.front().in;
    c.cache = stack_.front().cache;
    c.name = text.unit;
    c.offset = c.start_offset = c.header = text.header;
    c.line = c.start_line = text.line;
  } else {
    c.path = text.file;
    c.cache = &line_caches_[text.file];
    c.name = std::filesystem::path(text.file).filename().string();
  }
  c.passes_left = passes - 1;
  c.args = std::move(args);
  c.arg_names = std::move(names);
  stack_.push_back(std::move(c));
}

// The arguments of a call from just after its '(' to just after its ')': values, a left-out one
// empty; an argument that is only a name is also kept by name (for a VAR parameter).
void Interpreter::arguments(std::string_view s, std::size_t& i, std::vector<std::optional<NcValue>>& args,
                            std::vector<std::string>& names) {
  InterpreterLookup lookup(*this, cx().line);
  i = skip_space(s, i);
  if (i < s.size() && s[i] == ')') {
    ++i;
    return;
  }
  while (true) {
    i = skip_space(s, i);
    if (i < s.size() && (s[i] == ',' || s[i] == ')')) {
      args.emplace_back(), names.emplace_back();  // left out: the parameter's default
    } else {
      std::size_t ne = name_end(s, i);
      std::size_t after = skip_space(s, ne);
      names.push_back(after < s.size() && (s[after] == ',' || s[after] == ')') ? upper_text(s.substr(i, ne - i)) : "");
      const Variable* whole = names.back().empty() ? nullptr : find_variable(names.back());
      if (whole && !whole->dims.empty()) {  // a whole array: passed by reference (NC-PARAM-SUB-2)
        args.emplace_back(NcValue{});
        i = after;
      } else {
        ExpressionParser p(s, i, cx().line, lookup);
        args.push_back(p.parse());
        i = skip_space(s, p.position());
      }
    }
    if (i < s.size() && s[i] == ',') {
      ++i;
      continue;
    }
    if (i < s.size() && s[i] == ')') {
      ++i;
      return;
    }
    throw InputError(cx().line, static_cast<int>(i) + 1, "')' or ',' expected in the call");
  }
}

// NC-PARAM-SUB-5: a subprogram file run on its own takes these arguments as if called with them.
void Interpreter::set_arguments(std::string_view list) {
  std::string text = fmt::format("({})", list);
  std::size_t i = 1;
  std::vector<std::string> names;
  cx().args.clear();
  try {
    arguments(text, i, cx().args, names);
    if (skip_space(text, i) != text.size())
      throw InputError(0, static_cast<int>(i), "unexpected text after the arguments");
  } catch (const InputError& e) {
    throw InputError(0, std::max(1, e.column() - 1), "in the arguments given: " + e.detail());
  }
}

// NC-PARAM-VAR-3: the DEF lines of a definitions file (GUD); comments, block numbers, a header
// (%_N_…_DEF) and the closing M17/M30/RET are allowed around them.
void Interpreter::load_definitions(std::istream& in) {
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // a UTF-8 byte order mark
    try {
      std::size_t rest;
      std::string first = first_word(line, rest);
      std::size_t start = skip_space(line, 0);
      if (first.empty() && (start >= line.size() || line[start] == ';' || line[start] == '%')) continue;
      if (first == "M17" || first == "M30" || first == "M2" || first == "M02" || first == "RET") continue;
      if (first == "DEFINE") {  // NC-PARAM-SUB-7: macros of a definitions file (UMAC.DEF, SMAC.DEF)
        statement(first, line, rest);
        continue;
      }
      if (first != "DEF")
        throw InputError(n, static_cast<int>(start) + 1, "a definitions file holds DEF and DEFINE lines only");
      define(line, rest, globals_);
    } catch (const InputError& e) {
      throw InputError(n, e.column(), e.detail());
    }
  }
}

// NC-PARAM-SUB-2: PROC name(type par, VAR type par, …): the parameters become local variables,
// given the call's values (left out: 0); a VAR parameter is written back to the caller's variable
// when the subprogram returns.
void Interpreter::procedure(std::string_view s, std::size_t i) {
  ++variables_epoch_;  // NC-PARAM-EXPR-4: records resolve their names again
  std::size_t e = name_end(s, skip_space(s, i));
  i = skip_space(s, e);
  struct Parameter {
    std::string name;
    NcValue::Type type;
    bool by_ref;
    std::optional<std::vector<int>> dims;  // an array: its sizes (0: left open, "[,3]")
    std::size_t at;
  };
  std::vector<Parameter> params;
  InterpreterLookup lookup(*this, cx().line);
  if (i < s.size() && s[i] == '(') {
    ++i;
    while (true) {
      i = skip_space(s, i);
      if (i < s.size() && s[i] == ')') {
        ++i;
        break;
      }
      std::size_t t = name_end(s, i);
      std::string type = upper_text(s.substr(i, t - i));
      bool by_ref = type == "VAR";
      if (by_ref) {
        i = skip_space(s, t);
        t = name_end(s, i);
        type = upper_text(s.substr(i, t - i));
      }
      std::optional<NcValue::Type> known = value_type(type);
      if (!known)
        throw InputError(cx().line, static_cast<int>(i) + 1,
                         fmt::format("'{}' is not a parameter type (REAL INT BOOL CHAR STRING AXIS FRAME)", type));
      NcValue::Type vt = *known;
      i = skip_space(s, t);
      if (type == "STRING" && i < s.size() && s[i] == '[') {
        std::size_t c = s.find(']', i);
        if (c == std::string_view::npos) throw InputError(cx().line, static_cast<int>(i) + 1, "']' expected");
        i = skip_space(s, c + 1);
      }
      std::size_t ne = name_end(s, i);
      std::string name = upper_text(s.substr(i, ne - i));
      if (name.size() < 2)
        throw InputError(cx().line, static_cast<int>(i) + 1, "a parameter name of at least two characters is expected");
      params.push_back({name, vt, by_ref, std::nullopt, i});
      i = skip_space(s, ne);
      if (i < s.size() && s[i] == '[') {  // VAR REAL NAME[], NAME[,3], NAME[4,3]: an array, by reference
        if (!by_ref)
          throw InputError(cx().line, static_cast<int>(i) + 1,
                           fmt::format("the array parameter {} must be a VAR parameter", name));
        std::vector<int> dims;
        ++i;
        while (true) {
          i = skip_space(s, i);
          if (i < s.size() && (s[i] == ',' || s[i] == ']')) {
            dims.push_back(0);
          } else {
            ExpressionParser size(s, i, cx().line, lookup);
            NcValue d = size.parse();
            if (d.type == NcValue::Type::kString || d.type == NcValue::Type::kFrame || d.number < 1 || d.number > 1e6 ||
                d.number != std::trunc(d.number))
              throw InputError(cx().line, static_cast<int>(i) + 1,
                               "an array size must be a whole number from 1 to 1000000");
            dims.push_back(static_cast<int>(d.number));
            i = skip_space(s, size.position());
          }
          if (i < s.size() && s[i] == ',') {
            ++i;
            continue;
          }
          if (i < s.size() && s[i] == ']') break;
          throw InputError(cx().line, static_cast<int>(i) + 1, "']' or ',' expected in the array parameter");
        }
        if (dims.size() > 3) throw InputError(cx().line, static_cast<int>(i) + 1, "an array has at most three indices");
        params.back().dims = dims;
        i = skip_space(s, i + 1);
      }
      if (i < s.size() && s[i] == ',') {
        ++i;
        continue;
      }
      if (i < s.size() && s[i] == ')') {
        ++i;
        break;
      }
      throw InputError(cx().line, static_cast<int>(i) + 1, "',' or ')' expected in the parameter list");
    }
  }
  i = skip_space(s, i);
  while (i < s.size() && s[i] != ';') {
    std::size_t w = name_end(s, i);
    std::string word = upper_text(s.substr(i, w - i));
    if (word == "SAVE") {  // NC-PARAM-SUB-4 (run on its own: nothing to restore)
      if (stack_.size() > 1 && !cx().saved && system_) system_->save_modal_state();
      cx().saved = stack_.size() > 1;
    } else if (word != "DISPLOF" && word != "DISPLON" && word != "SBLOF" && word != "SBLON" && word != "ACTBLOCNO")
      throw InputError(
          cx().line, static_cast<int>(i) + 1,
          fmt::format("unexpected '{}' after the parameters of PROC", word.empty() ? std::string(1, s[i]) : word));
    i = skip_space(s, w);
  }
  if (cx().args.size() > params.size())
    throw InputError(cx().line, 1,
                     fmt::format("{} arguments given, the PROC has {} parameters", cx().args.size(), params.size()));
  for (std::size_t k = 0; k < params.size(); ++k) {
    const Parameter& pm = params[k];
    const std::string& name = pm.name;
    // The caller's variable named as this argument, if it is an array.
    const Variable* array = nullptr;
    if (stack_.size() > 1 && k < cx().arg_names.size() && !cx().arg_names[k].empty()) {
      const Context& caller = stack_[stack_.size() - 2];
      auto it = caller.variables.find(cx().arg_names[k]);
      if (it != caller.variables.end())
        array = &it->second;
      else if (auto g = globals_.find(cx().arg_names[k]); g != globals_.end())
        array = &g->second;
      if (array && array->dims.empty()) array = nullptr;
    }
    if (pm.dims) {  // NC-PARAM-SUB-2: an array parameter works on the caller's array
      Variable v;
      if (array) {
        if (array->type != pm.type || array->dims.size() != pm.dims->size())
          throw InputError(
              cx().line, static_cast<int>(pm.at) + 1,
              fmt::format("the array {} given for {} has another type or number of indices", cx().arg_names[k], name));
        for (std::size_t d = 0; d < array->dims.size(); ++d)
          if ((*pm.dims)[d] != 0 && (*pm.dims)[d] != array->dims[d])
            throw InputError(cx().line, static_cast<int>(pm.at) + 1,
                             fmt::format("the array {} given for {} has {} elements in index {}, the PROC declares {}",
                                         cx().arg_names[k], name, array->dims[d], d + 1, (*pm.dims)[d]));
        v = *array;
        cx().by_reference.emplace_back(name, cx().arg_names[k]);
      } else if (stack_.size() == 1 && std::find(pm.dims->begin(), pm.dims->end(), 0) == pm.dims->end() &&
                 (k >= cx().args.size() || !cx().args[k])) {
        v.type = pm.type;  // run on its own without the argument: the declared array, zero
        v.dims = *pm.dims;
        std::size_t count = 1;
        for (int d : v.dims) count *= static_cast<std::size_t>(d);
        v.values.assign(count, pm.type == NcValue::Type::kString ? NcValue::string("") : NcValue{pm.type, 0, {}});
      } else {
        throw InputError(cx().line, static_cast<int>(pm.at) + 1,
                         fmt::format("the array parameter {} needs an array variable as its argument", name));
      }
      cx().variables[name] = std::move(v);
      continue;
    }
    if (array)
      throw InputError(cx().line, static_cast<int>(pm.at) + 1,
                       fmt::format("{} is an array: the parameter {} is not", cx().arg_names[k], name));
    Variable v;
    v.type = pm.type;
    v.values.assign(1, pm.type == NcValue::Type::kString ? NcValue::string("") : NcValue{pm.type, 0, {}});
    cx().variables[name] = v;
    if (k < cx().args.size() && cx().args[k]) store(cx().variables[name], 0, *cx().args[k], 0);
    if (pm.by_ref && stack_.size() > 1) {  // run on its own, the main program: nothing to write back
      if (k >= cx().arg_names.size() || cx().arg_names[k].empty())
        throw InputError(cx().line, 1, fmt::format("the VAR parameter {} needs a variable as its argument", name));
      cx().by_reference.emplace_back(name, cx().arg_names[k]);
    }
  }
}

void Interpreter::leave_subprogram() {
  ++variables_epoch_;  // NC-PARAM-EXPR-4: records resolve their names again
  Context& c = cx();
  // VAR parameters: the caller's variables take the values.
  std::vector<std::pair<std::string, Variable>> results;
  for (const auto& [local, caller] : c.by_reference) results.emplace_back(caller, std::move(c.variables[local]));
  if (c.saved && system_) system_->restore_modal_state();
  c.saved = false;
  bool again = c.passes_left > 0;
  if (again) {  // P: run it again from its start, with the same arguments
    --c.passes_left;
    count_backward_jump();
    seek(c.start_offset, c.start_line);
    c.frames.clear(), c.open_ifs.clear(), c.variables.clear(), c.by_reference.clear(), c.labels_seen.clear();
  } else {
    stack_.pop_back();
  }
  Context& caller = again ? stack_[stack_.size() - 2] : cx();
  for (auto& [name, local] : results) {
    Variable* target = nullptr;
    if (auto it = caller.variables.find(name); it != caller.variables.end())
      target = &it->second;
    else if (auto g = globals_.find(name); g != globals_.end())
      target = &g->second;
    if (!local.dims.empty()) {  // an array parameter: the whole array goes back
      if (target && target->values.size() == local.values.size()) target->values = std::move(local.values);
    } else if (is_r_parameter(name) && r_number(name) < kRParameters) {
      r_[r_number(name)] = local.values[0].number;
    } else if (target && target->dims.empty()) {
      store(*target, 0, local.values[0], 0);
    }
  }
}
}  // namespace cutcom
