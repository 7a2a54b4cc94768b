// NC-PARAM-EXPR-5: the string functions of the NC language (STRLEN, INDEX, SUBSTR, SPRINT,
// NUMBER, ISNUMBER, TOUPPER, …), apart from the expression grammar in nc_expression.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "interpreter_text.hpp"
#include "nc_expression.hpp"

namespace cutcom {

// NC-PARAM-EXPR-5: the string functions; positions count from 0, -1 when nothing is found.
bool ExpressionParser::string_function(const std::string& n, const std::vector<NcValue>& a, std::size_t at,
                                       NcValue& out) {
  auto fail = [&](const std::string& what) { throw InputError(line_, static_cast<int>(at) + 1, n + ": " + what); };
  auto need = [&](std::size_t lo, std::size_t hi) {
    if (a.size() < lo || a.size() > hi)
      fail(lo == hi ? fmt::format("takes {} argument{}", lo, lo == 1 ? "" : "s")
                    : fmt::format("takes {} to {} arguments", lo, hi));
  };
  auto text = [&](std::size_t k) -> const std::string& {
    if (a[k].type != NcValue::Type::kString) fail(fmt::format("argument {} must be a string", k + 1));
    return a[k].text;
  };
  auto character = [&](std::size_t k) {  // a CHAR (its code) or a string of one character
    if (a[k].type == NcValue::Type::kString) {
      if (a[k].text.size() != 1) fail(fmt::format("argument {} must be one character", k + 1));
      return a[k].text[0];
    }
    double c = as_number(a[k], line_, at);
    if (c < 0 || c > 255 || c != std::trunc(c)) fail(fmt::format("argument {} is not a character code", k + 1));
    return static_cast<char>(static_cast<int>(c));
  };
  auto position = [](std::size_t p) {
    return NcValue::integer(p == std::string::npos ? -1.0 : static_cast<double>(p));
  };
  if (n == "ISVAR") {  // a defined user variable, an R parameter or a system variable cutcom knows
    need(1, 1);
    std::string name = text(0);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    name = name.substr(0, name.find('['));
    bool r = name.size() > 1 && name.size() <= 4 && name[0] == 'R' &&
             name.find_first_not_of("0123456789", 1) == std::string::npos;
    bool known = r || lookup_.is_variable(name);
    if (!known && !name.empty() && name[0] == '$') {
      static constexpr std::string_view kIndexed[] = {"$TC_DP", "$TC_TP2",  "$P_EP",   "$AA_IW",    "$P_GG",
                                                      "$P_AD",  "$P_TOOLL", "$P_UIFR", "$P_PFRAME", "$P_SUBPAR"};
      for (std::string_view k : kIndexed) known = known || name.rfind(k, 0) == 0;
      if (!known) {
        try {
          lookup_.read(name, {}, at);
          known = true;
        } catch (const InputError&) {
        }
      }
    }
    return out = NcValue::boolean(known), true;
  }
  if (n == "SPRINT") {  // SPRINT("format", values…): %D %I %F %E %G %R %S %B %C %X, with .n, and %%
    if (a.empty()) fail("takes a format and its values");
    const std::string& f = text(0);
    std::string t;
    std::size_t next = 1;
    for (std::size_t k = 0; k < f.size(); ++k) {
      if (f[k] != '%') {
        t += f[k];
        continue;
      }
      std::size_t spec = k + 1;
      int places = -1;
      if (spec < f.size() && f[spec] == '.') {
        places = 0;
        for (++spec; spec < f.size() && f[spec] >= '0' && f[spec] <= '9'; ++spec)
          places = places * 10 + (f[spec] - '0');
      }
      if (spec >= f.size()) fail("a format ends in '%'");
      char c = static_cast<char>(std::toupper(static_cast<unsigned char>(f[spec])));
      k = spec;
      if (c == '%') {
        t += '%';
        continue;
      }
      if (next >= a.size()) fail("more formats than values");
      const NcValue& v = a[next++];
      if (c == 'S') {
        t += v.type == NcValue::Type::kString ? v.text : interpreter_text::grid_text(v, line_, at);
        continue;
      }
      double x = as_number(v, line_, at);
      if (!(std::fabs(x) < 9e18)) fail("a value too large to format");
      if (c == 'C' && !(x >= 0 && x < 256)) fail("%C needs a character code");
      if (c == 'D' || c == 'I')
        t += fmt::format("{}", static_cast<long long>(std::trunc(x)));
      else if (c == 'F' || c == 'R')
        t += fmt::format("{:.{}f}", x, places < 0 ? 6 : places);
      else if (c == 'E')
        t += fmt::format("{:.{}E}", x, places < 0 ? 6 : places);
      else if (c == 'G')
        t += fmt::format("{:G}", x);
      else if (c == 'B')
        t += x != 0 ? "TRUE" : "FALSE";
      else if (c == 'C')
        t += static_cast<char>(static_cast<int>(x));
      else if (c == 'X')
        t += fmt::format("{:X}", static_cast<long long>(std::trunc(x)));
      else
        fail(fmt::format("'%{}' is not a format cutcom knows", f[spec]));
    }
    return out = NcValue::string(t), true;
  }
  // NC-PARAM-EXPR-6: axis names as values. AXNAME("X") the axis of that name, AXSTRING(axis) its
  // name as a string, ISAXIS(n) whether geometry axis n (1 … 3) exists: cutcom's channel has X, Y, Z.
  if (n == "AXNAME" || n == "AXSTRING") {
    need(1, 1);
    if (a[0].type != NcValue::Type::kString)
      fail(n == "AXNAME" ? "argument 1 must be a string (the axis' name)" : "argument 1 must be an axis");
    std::string name = a[0].text;
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])) &&
              std::all_of(name.begin(), name.end(),
                          [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (!ok) fail(fmt::format("'{}' is not an axis name", a[0].text));
    return out = NcValue::string(name), true;
  }
  if (n == "ISAXIS") {
    need(1, 1);
    double k = as_number(a[0], line_, at);
    return out = NcValue::boolean(k == 1 || k == 2 || k == 3), true;
  }
  if (n == "STRLEN") return need(1, 1), out = NcValue::integer(static_cast<double>(text(0).size())), true;
  if (n == "INDEX") return need(2, 2), out = position(text(0).find(character(1))), true;
  if (n == "RINDEX") return need(2, 2), out = position(text(0).rfind(character(1))), true;
  if (n == "MINDEX") return need(2, 2), out = position(text(0).find_first_of(text(1))), true;
  if (n == "MATCH") return need(2, 2), out = position(text(0).find(text(1))), true;
  if (n == "SUBSTR") {  // SUBSTR(text, start[, count])
    need(2, 3);
    const std::string& t = text(0);
    double from = as_number(a[1], line_, at), count = a.size() == 3 ? as_number(a[2], line_, at) : 1e9;
    if (from < 0 || from != std::trunc(from) || count < 0 || count != std::trunc(count))
      fail("start and count are whole numbers from 0");
    std::size_t f = static_cast<std::size_t>(std::min(from, static_cast<double>(t.size())));
    out = NcValue::string(t.substr(f, static_cast<std::size_t>(std::min(count, 1e9))));
    return true;
  }
  if (n == "TOUPPER" || n == "TOLOWER") {
    need(1, 1);
    std::string t = text(0);
    for (char& c : t)
      c = n == "TOUPPER" ? static_cast<char>(std::toupper(static_cast<unsigned char>(c)))
                         : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out = NcValue::string(std::move(t)), true;
  }
  if (n == "NUMBER" || n == "ISNUMBER") {  // a decimal number with an optional sign and EX exponent
    need(1, 1);
    std::string t = text(0);
    std::size_t b = t.find_first_not_of(' '), e = t.find_last_not_of(' ');
    t = b == std::string::npos ? std::string() : t.substr(b, e - b + 1);
    std::size_t ex = t.find("EX");
    if (ex != std::string::npos) t.replace(ex, 2, "e");
    double v = 0;
    const char* first = t.data() + (!t.empty() && t[0] == '+' ? 1 : 0);
    auto [end, ec] = std::from_chars(first, t.data() + t.size(), v);
    bool ok = !t.empty() && ec == std::errc() && end == t.data() + t.size() && std::isfinite(v);
    if (n == "ISNUMBER") return out = NcValue::boolean(ok), true;
    if (!ok) fail(fmt::format("\"{}\" is not a number", text(0)));
    return out = NcValue::real(v), true;
  }
  return false;
}

}  // namespace cutcom
