// Definitions of user variables (NC-PARAM-VAR-2): DEF type name[dims][=value], ….
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "cutcom/interpreter.hpp"
#include "interpreter_lookup.hpp"
#include "interpreter_text.hpp"
#include "nc_expression.hpp"

namespace cutcom {

using namespace interpreter_text;

// NC-PARAM-VAR-2: DEF type name[dims][=value], …
void Interpreter::define(std::string_view s, std::size_t i, std::map<std::string, Variable>& into) {
  ++variables_epoch_;  // NC-PARAM-EXPR-4: records resolve their names again
  InterpreterLookup lookup(*this, cx().line);
  i = skip_space(s, i);
  std::size_t e = name_end(s, i);
  std::string type = upper_text(s.substr(i, e - i));
  // Words of global data before the type: range, preprocessing stop, initialisation time.
  static constexpr std::string_view kBefore[] = {"NCK",   "CHAN",  "SYNR",  "SYNW", "SYNRW",
                                                 "INIPO", "INIRE", "INICF", "PRLOC"};
  while (std::find(std::begin(kBefore), std::end(kBefore), type) != std::end(kBefore)) {
    i = skip_space(s, e);
    e = name_end(s, i);
    type = upper_text(s.substr(i, e - i));
  }
  std::optional<NcValue::Type> known = value_type(type);
  if (!known)
    throw InputError(cx().line, static_cast<int>(i) + 1,
                     fmt::format("'{}' is not a type (REAL INT BOOL CHAR STRING AXIS FRAME)", type));
  NcValue::Type t = *known;
  i = skip_space(s, e);
  if (type == "STRING" && i < s.size() && s[i] == '[') {  // STRING[length]
    std::size_t c = s.find(']', i);
    if (c == std::string_view::npos) throw InputError(cx().line, static_cast<int>(i) + 1, "']' expected");
    i = skip_space(s, c + 1);
  }
  // After it: physical unit, limits and access rights, each with its value (not checked here).
  static constexpr std::string_view kAttributes[] = {"PHU", "LLI", "ULI", "APR", "APW", "APRP", "APWP", "APRB", "APWB"};
  while (true) {
    std::size_t a = name_end(s, i);
    if (std::find(std::begin(kAttributes), std::end(kAttributes), upper_text(s.substr(i, a - i))) ==
        std::end(kAttributes))
      break;
    std::size_t v = skip_space(s, a);
    std::size_t ve = v;
    while (ve < s.size() && (is_digit(s[ve]) || s[ve] == '.' || s[ve] == '-' || s[ve] == '+')) ++ve;
    if (ve == v) throw InputError(cx().line, static_cast<int>(v) + 1, "a value is expected after the attribute");
    i = skip_space(s, ve);
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
    into[name] = var;  // a second DEF of a name starts it again
    Variable& v = into[name];
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
      } else if (type == "AXIS" && at < s.size() && is_letter(s[at]) &&
                 !(skip_space(s, w) < s.size() && s[skip_space(s, w)] == '(')) {  // an axis name: X, Y, Z …
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
}  // namespace cutcom

namespace cutcom {

// NC-PARAM-SYS-4: machine and setting data by their $ names, as the machine data gave them.
void Interpreter::set_machine_values(const std::map<std::string, std::string>& values) {
  machine_values_.clear();
  for (const auto& [name, text] : values) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
      machine_values_[name] = NcValue::string(text.substr(1, text.size() - 2));
      continue;
    }
    double v = 0;
    std::string_view t = text;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      throw InputError(0, 0, fmt::format("{}: '{}' is neither a number nor a \"quoted\" text", name, text));
    machine_values_[name] = NcValue::real(v);
  }
}

}  // namespace cutcom
