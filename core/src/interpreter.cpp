// The interpreter layer (interpreter.hpp; spec nc-parametric.md): statements, variables, jumps
// and loops run here; the reader gets plain blocks with every computed value written on the
// 10^-9 grid. Positions in the text are counted here (not asked of the stream per line).
#include "cutcom/interpreter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "cutcom/reader.hpp"
#include "nc_expression.hpp"
#include "word_lexer.hpp"

namespace cutcom {

using lexer::is_digit;
using lexer::is_letter;
using lexer::is_name_char;
using lexer::upper;

namespace {

std::string upper_text(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = upper(c);
  return u;
}

std::size_t skip_space(std::string_view s, std::size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
  return i;
}

std::size_t name_end(std::string_view s, std::size_t i) {
  if (i < s.size() && s[i] == '$') ++i;
  while (i < s.size() && is_name_char(s[i])) ++i;
  return i;
}

// The start of a block (NC-WORD-2): block skip, block number, and a label. Returns where the
// words begin; `number` and `label` (upper case) as found.
std::size_t block_prefix(std::string_view s, std::string* number, std::string* label) {
  std::size_t i = skip_space(s, 0);
  if (i < s.size() && s[i] == '/') {
    ++i;
    if (i < s.size() && is_digit(s[i])) ++i;
    i = skip_space(s, i);
  }
  for (int pass = 0; pass < 2; ++pass) {
    if (i < s.size() && (upper(s[i]) == 'N' || s[i] == ':') && i + 1 < s.size() && is_digit(s[i + 1])) {
      std::size_t j = i + 1;
      while (j < s.size() && is_digit(s[j])) ++j;
      if (number) *number = std::string(s.substr(i + 1, j - i - 1));
      i = skip_space(s, j);
    }
    // A label: a name of at least two characters followed by ':' (not a main-block number).
    if (i < s.size() && (is_letter(s[i]) || s[i] == '_')) {
      std::size_t j = name_end(s, i);
      std::size_t k = skip_space(s, j);
      if (j - i >= 2 && k < s.size() && s[k] == ':') {
        if (label) *label = upper_text(s.substr(i, j - i));
        i = skip_space(s, k + 1);
        continue;
      }
    }
    break;
  }
  return i;
}

// The first word of a block (upper case) and where its rest starts.
std::string first_word(std::string_view s, std::size_t& rest) {
  std::size_t i = block_prefix(s, nullptr, nullptr);
  std::size_t j = name_end(s, i);
  rest = j;
  return upper_text(s.substr(i, j - i));
}

bool has_jump(std::string_view s) {
  std::string u = upper_text(s.substr(0, s.find(';')));
  for (std::string_view k : {"GOTOF", "GOTOB", "GOTOC", "GOTO"}) {
    std::size_t p = u.find(k);
    while (p != std::string::npos) {
      bool before = p == 0 || !is_name_char(u[p - 1]);
      bool after = p + k.size() >= u.size() || !is_name_char(u[p + k.size()]);
      if (before && after) return true;
      p = u.find(k, p + 1);
    }
  }
  return false;
}

// NC-PARAM-GRID-1: a computed value becomes a decimal with nine places, the one nearest to the
// binary64 value (ties to even on its exact binary value).
std::string grid_text(const NcValue& v, int line, std::size_t at) {
  if (v.type == NcValue::Type::kString) return "\"" + v.text + "\"";
  if (!std::isfinite(v.number)) throw InputError(line, static_cast<int>(at) + 1, "the value is not a finite number");
  if (std::fabs(v.number) >= 1e12)
    throw InputError(line, static_cast<int>(at) + 1,
                     fmt::format("the value {} is out of the range of a position", v.number));
  std::string t = fmt::format("{:.9f}", v.number);
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  if (t == "-0") t = "0";
  return t;
}

// A plain literal: [+-]digits[.digits], or a quoted string; where it ends.
std::optional<std::size_t> literal_end(std::string_view s, std::size_t i) {
  if (i < s.size() && s[i] == '"') {
    std::size_t e = s.find('"', i + 1);
    if (e == std::string_view::npos) return std::nullopt;
    return e + 1;
  }
  std::size_t j = i;
  if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
  std::size_t d = j;
  while (j < s.size() && (is_digit(s[j]) || s[j] == '.')) ++j;
  if (j == d) return std::nullopt;
  // The word must end here: a space, the end, a comment, another word or a closing parenthesis.
  if (j < s.size() &&
      !(s[j] == ' ' || s[j] == '\t' || s[j] == '\r' || s[j] == ';' || s[j] == ')' || is_letter(s[j]) || s[j] == '$'))
    return std::nullopt;
  if (j < s.size() && upper(s[j]) == 'E' && j + 1 < s.size() && upper(s[j + 1]) == 'X') return std::nullopt;
  return j;
}

bool is_r_parameter(const std::string& n) {
  if (n.size() < 2 || n[0] != 'R') return false;
  for (std::size_t k = 1; k < n.size(); ++k)
    if (!is_digit(n[k])) return false;
  return true;
}

constexpr int kRParameters = 1000;  // R0 … R999 (NC-PARAM-VAR-1)

// The number of "Rn" (is_r_parameter), or kRParameters when it is too large to exist.
int r_number(const std::string& n) {
  if (n.size() > 5) return kRParameters;
  return std::stoi(n.substr(1));
}

}  // namespace

// Names in expressions: R parameters, user variables, system variables.
class InterpreterLookup : public ExpressionParser::Lookup {
 public:
  InterpreterLookup(Interpreter& it, int line) : it_(it), line_(line) {}
  NcValue read(const std::string& n, const std::vector<NcValue>& idx, std::size_t at) override {
    if (n == "R" && idx.size() == 1) return NcValue::real(r_value(idx[0], at));
    if (is_r_parameter(n) && idx.empty()) {
      int k = r_number(n);
      if (k >= kRParameters) fail(at, fmt::format("R parameter {} does not exist (R0 to R{})", n, kRParameters - 1));
      auto it = it_.r_.find(k);
      return NcValue::real(it == it_.r_.end() ? 0.0 : it->second);
    }
    if (!n.empty() && n[0] == '$') {
      std::optional<double> v = it_.system_ ? it_.system_->system_value(n, idx) : std::nullopt;
      if (!v) fail(at, fmt::format("system variable {} is not one cutcom knows (NC-PARAM-SYS-1 lists them)", n));
      return NcValue::real(*v);
    }
    Interpreter::Variable* v = it_.find_variable(n);
    if (!v) fail(at, fmt::format("undefined variable '{}'", n));
    return v->values[offset(n, *v, idx, at)];
  }
  bool is_variable(const std::string& n) const override { return it_.cx().variables.count(n) > 0; }

  double r_value(const NcValue& index, std::size_t at) {
    int k = r_index(index, at);
    auto it = it_.r_.find(k);
    return it == it_.r_.end() ? 0.0 : it->second;
  }
  int r_index(const NcValue& index, std::size_t at) {
    if (index.type == NcValue::Type::kString) fail(at, "an R parameter's index must be a number");
    double k = std::round(index.number);
    if (k < 0 || k >= kRParameters)
      fail(at, fmt::format("R parameter R[{}] does not exist (R0 to R{})", k, kRParameters - 1));
    return static_cast<int>(k);
  }
  // NC-PARAM-ERR-1: an index outside the array's bounds is an error.
  std::size_t offset(const std::string& n, const Interpreter::Variable& v, const std::vector<NcValue>& idx,
                     std::size_t at) {
    if (idx.size() != v.dims.size())
      fail(at,
           fmt::format("'{}' has {} index{}, {} given", n, v.dims.size(), v.dims.size() == 1 ? "" : "es", idx.size()));
    std::size_t o = 0;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      if (idx[k].type == NcValue::Type::kString) fail(at, fmt::format("an index of '{}' must be a number", n));
      double i = std::round(idx[k].number);
      if (i < 0 || i >= v.dims[k]) fail(at, fmt::format("index {} of '{}' is outside 0 to {}", i, n, v.dims[k] - 1));
      o = o * static_cast<std::size_t>(v.dims[k]) + static_cast<std::size_t>(i);
    }
    return o;
  }
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    throw InputError(line_, static_cast<int>(at) + 1, what);
  }

 private:
  Interpreter& it_;
  int line_;
};

Interpreter::Interpreter(std::istream& in, SystemValues* system, InterpreterLimits limits)
    : system_(system), limits_(limits) {
  stack_.emplace_back();
  cx().in = &in;
  std::streampos p = in.tellg();
  cx().offset = cx().start_offset = p == std::streampos(-1) ? 0 : static_cast<std::streamoff>(p);
}

bool Interpreter::getline(std::string& text) {
  cx().line_start = cx().offset;
  if (!std::getline((*cx().in), text)) return false;
  cx().offset += static_cast<std::streamoff>(text.size()) + 1;
  ++cx().line;
  return true;
}

void Interpreter::seek(std::streamoff to, int line) {
  (*cx().in).clear();
  (*cx().in).seekg(to);
  if (!(*cx().in)) throw InputError(cx().line, 1, "a jump needs a program that can be read again (a file, not a pipe)");
  cx().offset = to;
  cx().line = line;
}

bool Interpreter::maybe_parametric(std::string_view s) {
  bool letter = false;
  for (std::size_t k = 0; k < s.size(); ++k) {
    char c = s[k];
    if (c == ';') return false;
    if (c == '=' || c == ':') return true;
    bool l = is_letter(c) || c == '_';
    if (l && letter) return true;
    // Ln: a subprogram call (NC-PARAM-SUB-1)
    if ((c == 'L' || c == 'l') && k + 1 < s.size() && is_digit(s[k + 1]) && (k == 0 || !is_name_char(s[k - 1])))
      return true;
    letter = l;
  }
  return false;
}

Interpreter::Variable* Interpreter::find_variable(const std::string& name) {
  auto it = cx().variables.find(name);
  return it == cx().variables.end() ? nullptr : &it->second;
}

NcValue Interpreter::evaluate(std::string_view expression, int line) {
  InterpreterLookup lookup(*this, line);
  ExpressionParser p(expression, 0, line, lookup);
  NcValue v = p.parse();
  if (skip_space(expression, p.position()) != expression.size())
    throw InputError(line, static_cast<int>(p.position()) + 1, "unexpected text after the expression");
  return v;
}

bool Interpreter::next(std::string& text, int& line) {
  while (true) {
    try {
      if (!getline(raw_)) {
        if (!cx().frames.empty())
          throw InputError(cx().line, 1, "the program ends inside a loop (WHILE, FOR, LOOP or REPEAT without its end)");
        if (!cx().open_ifs.empty()) throw InputError(cx().open_ifs.back(), 1, "IF without its ENDIF");
        if (stack_.size() == 1) return false;
        leave_subprogram();  // NC-PARAM-SUB-2: the end of the file returns
        continue;
      }
      if (stack_.size() == 1 && !maybe_parametric(raw_)) {
        text.swap(raw_);
        line = cx().line;
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

// The file of a subprogram: NAME.SPF (or .MPF, any case) in the program's folder or the search
// path (NC-PARAM-SUB-1).
std::optional<std::string> Interpreter::find_subprogram(const std::string& name) const {
  // Looked up once per name: a word met in every pass of a loop does not probe the files again.
  auto known = found_.find(name);
  if (known != found_.end()) return known->second;
  std::optional<std::string>& found = found_[name];
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string& dir : search_path_.empty() ? std::vector<std::string>{"."} : search_path_)
    for (const std::string& f : {name + ".SPF", name + ".spf", lower + ".spf", lower + ".SPF", name + ".MPF",
                                 name + ".mpf", lower + ".mpf", "_N_" + name + "_SPF", name}) {
      std::string path = dir.empty() ? f : dir + "/" + f;
      std::ifstream probe(path);
      if (probe) return found = path;
    }
  return found;
}

// NC-PARAM-SUB-1: a call: NAME, NAME(arguments), Ln, CALL/PCALL/EXTCALL "NAME", each with P
// repetitions; the subprogram runs before the caller's next block.
bool Interpreter::call(std::string_view s, std::size_t word) {
  std::size_t w = name_end(s, word);
  std::string n = upper_text(s.substr(word, w - word));
  std::size_t i = skip_space(s, w);
  bool explicit_call = n == "CALL" || n == "PCALL" || n == "EXTCALL";
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
    std::size_t slash = n.find_last_of("/\\");
    if (slash != std::string::npos) n = n.substr(slash + 1);  // EXTCALL "PATH/NAME": the name
    for (const char* ext : {".SPF", ".MPF"})
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ext) == 0) n.resize(n.size() - 4);
    i = skip_space(s, e);
  } else {
    bool l_number = n.size() > 1 && n[0] == 'L';
    for (std::size_t k = 1; l_number && k < n.size(); ++k) l_number = is_digit(n[k]);
    if (!l_number && (n.size() < 2 || cx().variables.count(n) || is_r_parameter(n))) return false;
    bool next_ok = i >= s.size() || s[i] == ';' || s[i] == '(' ||
                   (upper(s[i]) == 'P' && i + 1 < s.size() && (is_digit(s[i + 1]) || s[i + 1] == '='));
    if (!next_ok) return false;
    if (!find_subprogram(n)) {
      if (l_number)
        throw InputError(
            cx().line, static_cast<int>(word) + 1,
            fmt::format("subprogram {} not found ({}.SPF in the program's folder or --search-path)", n, n));
      return false;  // not a call: the lexer names the word
    }
  }
  std::optional<std::string> file = find_subprogram(n);
  if (!file)  // CALL "NAME" of a missing file (a name or Ln without a file was handled above)
    throw InputError(cx().line, static_cast<int>(word) + 1,
                     fmt::format("subprogram {} not found ({}.SPF in the program's folder or --search-path)", n, n));
  // Arguments: values now; a VAR parameter's argument is also remembered by name.
  InterpreterLookup lookup(*this, cx().line);
  std::vector<std::optional<NcValue>> args;
  std::vector<std::string> names;
  if (i < s.size() && s[i] == '(') {
    ++i;
    i = skip_space(s, i);
    if (i < s.size() && s[i] == ')') {
      ++i;
    } else {
      while (true) {
        i = skip_space(s, i);
        if (i < s.size() && (s[i] == ',' || s[i] == ')')) {
          args.emplace_back(), names.emplace_back();  // left out: the parameter's default
        } else {
          std::size_t ne = name_end(s, i);
          std::size_t after = skip_space(s, ne);
          names.push_back(after < s.size() && (s[after] == ',' || s[after] == ')') ? upper_text(s.substr(i, ne - i))
                                                                                   : "");
          ExpressionParser p(s, i, cx().line, lookup);
          args.push_back(p.parse());
          i = skip_space(s, p.position());
        }
        if (i < s.size() && s[i] == ',') {
          ++i;
          continue;
        }
        if (i < s.size() && s[i] == ')') {
          ++i;
          break;
        }
        throw InputError(cx().line, static_cast<int>(i) + 1, "')' or ',' expected in the call");
      }
    }
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
  if (stack_.size() >= kMaxLevels)
    throw InputError(
        cx().line, static_cast<int>(word) + 1,
        fmt::format("more than {} program levels (subprograms calling subprograms: NC-PARAM-SUB-2)", kMaxLevels));
  control_flow_ = true;
  Context c;
  c.owned = std::make_unique<std::ifstream>(*file);
  c.in = c.owned.get();
  c.name = std::filesystem::path(*file).filename().string();
  c.passes_left = passes - 1;
  c.args = std::move(args);
  c.arg_names = std::move(names);
  stack_.push_back(std::move(c));
  return true;
}

// NC-PARAM-SUB-2: PROC name(type par, VAR type par, …): the parameters become local variables,
// given the call's values (left out: 0); a VAR parameter is written back to the caller's variable
// when the subprogram returns.
void Interpreter::procedure(std::string_view s, std::size_t i) {
  std::size_t e = name_end(s, skip_space(s, i));
  i = skip_space(s, e);
  std::vector<std::tuple<std::string, NcValue::Type, bool>> params;
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
      NcValue::Type vt;
      if (type == "REAL")
        vt = NcValue::Type::kReal;
      else if (type == "INT" || type == "CHAR")
        vt = NcValue::Type::kInt;
      else if (type == "BOOL")
        vt = NcValue::Type::kBool;
      else if (type == "STRING" || type == "AXIS")
        vt = NcValue::Type::kString;
      else
        throw InputError(cx().line, static_cast<int>(i) + 1,
                         fmt::format("'{}' is not a parameter type (REAL INT BOOL CHAR STRING AXIS)", type));
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
      params.emplace_back(name, vt, by_ref);
      i = skip_space(s, ne);
      if (i < s.size() && s[i] == '[')
        throw InputError(cx().line, static_cast<int>(i) + 1, "array parameters are not simulated yet");
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
    if (word == "SAVE")
      throw InputError(cx().line, static_cast<int>(i) + 1,
                       "PROC … SAVE (restoring the caller's modal state) is not simulated yet");
    if (word != "DISPLOF" && word != "DISPLON" && word != "SBLOF" && word != "SBLON" && word != "ACTBLOCNO")
      throw InputError(
          cx().line, static_cast<int>(i) + 1,
          fmt::format("unexpected '{}' after the parameters of PROC", word.empty() ? std::string(1, s[i]) : word));
    i = skip_space(s, w);
  }
  if (cx().args.size() > params.size())
    throw InputError(cx().line, 1,
                     fmt::format("{} arguments given, the PROC has {} parameters", cx().args.size(), params.size()));
  for (std::size_t k = 0; k < params.size(); ++k) {
    auto& [name, type, by_ref] = params[k];
    Variable v;
    v.type = type;
    v.values.assign(1, type == NcValue::Type::kString ? NcValue::string("") : NcValue{type, 0, {}});
    cx().variables[name] = v;
    if (k < cx().args.size() && cx().args[k]) store(cx().variables[name], 0, *cx().args[k], 0);
    if (by_ref && stack_.size() > 1) {  // run on its own, the main program: nothing to write back
      if (k >= cx().arg_names.size() || cx().arg_names[k].empty())
        throw InputError(cx().line, 1, fmt::format("the VAR parameter {} needs a variable as its argument", name));
      cx().by_reference.emplace_back(name, cx().arg_names[k]);
    }
  }
}

void Interpreter::leave_subprogram() {
  Context& c = cx();
  // VAR parameters: the caller's variables take the values.
  std::vector<std::pair<std::string, NcValue>> results;
  for (const auto& [local, caller] : c.by_reference) results.emplace_back(caller, c.variables[local].values[0]);
  bool again = c.passes_left > 0;
  if (again) {  // P: run it again from its start, with the same arguments
    --c.passes_left;
    count_backward_jump();
    seek(c.start_offset, 0);
    c.frames.clear(), c.open_ifs.clear(), c.variables.clear(), c.by_reference.clear(), c.labels_seen.clear();
  } else {
    stack_.pop_back();
  }
  Context& caller = again ? stack_[stack_.size() - 2] : cx();
  for (auto& [name, value] : results) {
    if (is_r_parameter(name) && r_number(name) < kRParameters) {
      r_[r_number(name)] = value.number;
    } else if (auto it = caller.variables.find(name); it != caller.variables.end() && it->second.dims.empty()) {
      store(it->second, 0, value, 0);
    }
  }
}

void Interpreter::run_line(const std::string& s, std::string& out) {
  out.clear();
  std::string number, label;
  std::size_t i = block_prefix(s, &number, &label);
  if (label.empty()) {
    out.append(s, 0, i);
  } else {  // the label is the interpreter's: the reader gets the block skip and number only
    cx().labels_seen[label].push_back({cx().line_start, cx().line - 1});
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
  if (first == "CASE" || first == "REPEATB") {  // not simulated yet: the lexer names it (NC-ERR-3)
    out = s;
    return;
  }
  if (statement(first, s, rest)) {  // a statement line yields no block
    out.clear();
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
    // Jumps end a block's words (NC-PARAM-FLOW-1).
    if (n == "GOTOF" || n == "GOTOB" || n == "GOTO" || n == "GOTOC") {
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
    std::vector<NcValue> indices;
    std::size_t k = after;
    bool indexed = k < s.size() && s[k] == '[';
    bool r_indexed = indexed && n == "R";
    bool variable = is_r_parameter(n) || r_indexed || cx().variables.count(n) > 0;
    bool tool_data = n.rfind("$TC_", 0) == 0;  // other system variables go to the lexer as written
    if (indexed && (variable || tool_data)) {
      // Indices as expressions: R[expr], A[i,j], $TC_DP6[t,d].
      std::size_t e = k + 1;
      indices = values(s, e, ']', lookup);
      k = skip_space(s, e);
    }
    bool assignment = k < s.size() && s[k] == '=' && !(k + 1 < s.size() && s[k + 1] == '=');
    if (n[0] == '$' && !tool_data) assignment = false;
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
    if (variable) {  // NC-PARAM-VAR-*: an assignment, run now; the reader never sees it
      ExpressionParser p(s, v, cx().line, lookup);
      NcValue value = p.parse();
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
        Variable& var = cx().variables[n];
        store(var, lookup.offset(n, var, indices, start), value, start);
      }
      i = p.position();
      continue;
    }
    // An address with a value: a literal is copied as written (exact); an expression is
    // evaluated and written on the grid (NC-PARAM-GRID-1). AC(...)/IC(...) keep their wrapper.
    words = true;
    out.append(s, space, j - space);
    if (!indices.empty()) {
      out += '[';
      for (std::size_t q = 0; q < indices.size(); ++q) out += (q ? "," : "") + grid_text(indices[q], cx().line, start);
      out += ']';
    }
    out += '=';
    // Value modes the lexer reads around a value: AC(…), IC(…), PM(…) …
    static constexpr std::string_view kWrappers[] = {"AC", "IC",  "ACN", "ACP",  "DC",   "PM",
                                                     "PR", "CAC", "CIC", "CACN", "CACP", "CDC"};
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
      out += wrapper.empty() ? value : wrapper + "(" + value + ")";
      end = wrapper.empty() ? *lit : skip_space(s, *lit) + 1;
    } else {
      ExpressionParser p(s, v, cx().line, lookup);
      NcValue value = p.parse();
      end = p.position();
      if (!wrapper.empty()) {
        end = skip_space(s, end);
        if (end >= s.size() || s[end] != ')') throw InputError(cx().line, static_cast<int>(end) + 1, "')' expected");
        ++end;
      }
      std::string t = grid_text(value, cx().line, v);
      out += wrapper.empty() ? t : wrapper + "(" + t + ")";
    }
    i = end;
  }
  if (!words) out.clear();
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
  bool text = var.type == T::kString;
  if (text != (value.type == T::kString))
    throw InputError(cx().line, static_cast<int>(at) + 1,
                     text ? "a STRING variable is assigned a number" : "a number variable is assigned a string");
  if (var.type == T::kInt) v = NcValue::integer(static_cast<double>(std::llround(value.number)));  // NC-PARAM-TYPE-1
  if (var.type == T::kBool) v = NcValue::boolean(value.number != 0);
  if (var.type == T::kReal) v = NcValue::real(value.number);
  var.values[at_offset] = v;
}

bool Interpreter::statement(std::string_view k, std::string_view s, std::size_t rest) {
  InterpreterLookup lookup(*this, cx().line);
  auto condition = [&](std::size_t from, std::size_t& end) {
    ExpressionParser p(s, from, cx().line, lookup);
    NcValue v = p.parse();
    end = skip_space(s, p.position());
    if (v.type == NcValue::Type::kString)
      throw InputError(cx().line, static_cast<int>(from) + 1, "a condition must be a number or BOOL, not a string");
    return v.number != 0;
  };
  auto nothing_after = [&](std::size_t e, std::string_view what) {
    e = skip_space(s, e);
    if (e < s.size() && s[e] != ';')
      throw InputError(cx().line, static_cast<int>(e) + 1, fmt::format("unexpected text after {}", what));
  };
  static constexpr std::string_view kStatements[] = {"IF",     "ELSE", "ENDIF",   "WHILE",  "ENDWHILE", "FOR",
                                                     "ENDFOR", "LOOP", "ENDLOOP", "REPEAT", "UNTIL"};
  for (std::string_view w : kStatements) control_flow_ = control_flow_ || k == w;
  if (k == "IF") {
    std::size_t end;
    bool c = condition(rest, end);
    std::size_t j = name_end(s, end);
    std::string jump_word = upper_text(s.substr(end, j - end));
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
      cx().frames.push_back({Frame::Kind::kWhile, cx().line_start, cx().line - 1, {}, 0});
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
    cx().frames.push_back({Frame::Kind::kFor, cx().offset, cx().line, var, last.number});
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
    cx().frames.push_back({Frame::Kind::kLoop, cx().offset, cx().line, {}, 0});
    return true;
  }
  if (k == "ENDLOOP") {
    Frame f = close(Frame::Kind::kLoop, "ENDLOOP");
    jump_back(f);
    return true;
  }
  if (k == "REPEAT") {
    std::size_t e = skip_space(s, rest);
    if (e < s.size() && s[e] != ';')
      throw InputError(cx().line, static_cast<int>(e) + 1,
                       "REPEAT of a program section (REPEAT label P=n) is not simulated yet");
    cx().frames.push_back({Frame::Kind::kRepeat, cx().offset, cx().line, {}, 0});
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
  if (k == "DEF") {
    define(s, rest);
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

// NC-PARAM-VAR-2: DEF type name[dims][=value], …
void Interpreter::define(std::string_view s, std::size_t i) {
  InterpreterLookup lookup(*this, cx().line);
  i = skip_space(s, i);
  std::size_t e = name_end(s, i);
  std::string type = upper_text(s.substr(i, e - i));
  if (type == "NCK" || type == "CHAN") {  // GUD scope words
    i = skip_space(s, e);
    e = name_end(s, i);
    type = upper_text(s.substr(i, e - i));
  }
  NcValue::Type t;
  if (type == "REAL")
    t = NcValue::Type::kReal;
  else if (type == "INT")
    t = NcValue::Type::kInt;
  else if (type == "BOOL")
    t = NcValue::Type::kBool;
  else if (type == "CHAR")
    t = NcValue::Type::kInt;
  else if (type == "STRING" || type == "AXIS")
    t = NcValue::Type::kString;
  else if (type == "FRAME")
    throw InputError(cx().line, static_cast<int>(i) + 1, "FRAME variables are not simulated yet");
  else
    throw InputError(cx().line, static_cast<int>(i) + 1,
                     fmt::format("'{}' is not a type (REAL INT BOOL CHAR STRING AXIS)", type));
  i = skip_space(s, e);
  if (type == "STRING" && i < s.size() && s[i] == '[') {  // STRING[length]
    std::size_t c = s.find(']', i);
    if (c == std::string_view::npos) throw InputError(cx().line, static_cast<int>(i) + 1, "']' expected");
    i = skip_space(s, c + 1);
  }
  while (true) {
    std::size_t n0 = i;
    std::size_t n1 = name_end(s, i);
    std::string name = upper_text(s.substr(n0, n1 - n0));
    if (name.empty() || (!is_letter(name[0]) && name[0] != '_'))
      throw InputError(cx().line, static_cast<int>(n0) + 1, "a variable name is expected");
    if (is_r_parameter(name) || name.size() < 2)
      throw InputError(cx().line, static_cast<int>(n0) + 1,
                       fmt::format("'{}' cannot be a variable name (an address or an R parameter)", name));
    Variable var;
    var.type = t;
    i = skip_space(s, n1);
    if (i < s.size() && s[i] == '[') {
      std::size_t at = ++i;
      for (const NcValue& d : values(s, i, ']', lookup)) {
        if (d.type == NcValue::Type::kString || d.number < 1 || d.number > 1e6 || d.number != std::trunc(d.number))
          throw InputError(cx().line, static_cast<int>(at) + 1,
                           "an array size must be a whole number from 1 to 1000000");
        var.dims.push_back(static_cast<int>(d.number));
      }
      i = skip_space(s, i);
    }
    std::size_t count = 1;
    for (int d : var.dims) count *= static_cast<std::size_t>(d);
    if (count > 1'000'000 || var.dims.size() > 3)
      throw InputError(cx().line, static_cast<int>(n0) + 1,
                       fmt::format("'{}' is too large: at most three indices and 1000000 elements", name));
    total_elements_ += count;
    if (total_elements_ > 4'000'000)
      throw InputError(cx().line, static_cast<int>(n0) + 1, "the program's variables hold more than 4000000 values");
    NcValue zero = t == NcValue::Type::kString ? NcValue::string("") : NcValue{t, 0, {}};
    var.values.assign(count, zero);
    cx().variables[name] = var;  // a second DEF of a name starts it again
    Variable& v = cx().variables[name];
    if (i < s.size() && s[i] == '=') {
      std::size_t at = skip_space(s, i + 1);
      std::size_t w = name_end(s, at);
      bool list = upper_text(s.substr(at, w - at)) == "SET" || (at < s.size() && s[at] == '(' && !v.dims.empty());
      if (!v.dims.empty() && list) {  // A[3]=SET(1,2,3) or =(1,2,3): from index 0 on
        std::size_t open = s[at] == '(' ? at : skip_space(s, w);
        if (open >= s.size() || s[open] != '(') throw InputError(cx().line, static_cast<int>(open) + 1, "'(' expected");
        std::size_t q = open + 1;
        std::vector<NcValue> list_values = values(s, q, ')', lookup);
        if (list_values.size() > v.values.size())
          throw InputError(cx().line, static_cast<int>(open) + 1, fmt::format("more values than '{}' holds", name));
        for (std::size_t k = 0; k < list_values.size(); ++k) store(v, k, list_values[k], open);
        i = skip_space(s, q);
      } else if (type == "AXIS" && at < s.size() && is_letter(s[at])) {  // an axis name: X, Y, Z …
        for (std::size_t k = 0; k < v.values.size(); ++k)
          v.values[k] = NcValue::string(upper_text(s.substr(at, w - at)));
        i = skip_space(s, w);
      } else {
        ExpressionParser p(s, at, cx().line, lookup);
        NcValue x = p.parse();
        for (std::size_t k = 0; k < v.values.size(); ++k) store(v, k, x, at);
        i = skip_space(s, p.position());
      }
    }
    if (i < s.size() && s[i] == ',') {
      i = skip_space(s, i + 1);
      continue;
    }
    if (i < s.size() && s[i] != ';')
      throw InputError(cx().line, static_cast<int>(i) + 1, "',' or the end of the DEF line expected");
    return;
  }
}

// NC-PARAM-FLOW-6: a program that keeps jumping back (loop passes, backward jumps, P runs) stops.
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
  if (forward && find_forward(target)) return;
  if (backward) {
    if (forward) seek(from, from_line);
    if (find_backward(target, from_line)) return;
  }
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

bool Interpreter::find_forward(std::string_view target) {
  std::string text;
  while (true) {
    std::streamoff start = cx().offset;
    int line = cx().line;
    if (!getline(text)) return false;
    std::string label;
    block_prefix(text, nullptr, &label);
    if (!label.empty()) cx().labels_seen[label].push_back({start, line});
    if (defines(text, target)) {
      seek(start, line);
      return true;
    }
  }
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
  seek(cx().start_offset, 0);
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
    if (!label.empty()) cx().labels_seen[label].push_back({start, line});
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
