// Text helpers of the interpreter layer (interpreter.hpp): the start of a block, names, literals
// and R parameter names, and how a computed value is written for the reader (NC-PARAM-GRID-1).
#pragma once

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "cutcom/input_error.hpp"
#include "cutcom/interpreter.hpp"
#include "word_lexer.hpp"

namespace cutcom::interpreter_text {

using lexer::is_digit;
using lexer::is_letter;
using lexer::is_name_char;
using lexer::upper;

inline std::string upper_text(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = upper(c);
  return u;
}

inline std::size_t skip_space(std::string_view s, std::size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
  return i;
}

inline std::size_t name_end(std::string_view s, std::size_t i) {
  if (i < s.size() && s[i] == '$') ++i;
  while (i < s.size() && is_name_char(s[i])) ++i;
  return i;
}

// The start of a block (NC-WORD-2): block skip, block number, and a label. Returns where the
// words begin; `number` and `label` (upper case) as found.
inline std::size_t block_prefix(std::string_view s, std::string* number, std::string* label) {
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
inline std::string first_word(std::string_view s, std::size_t& rest) {
  std::size_t i = block_prefix(s, nullptr, nullptr);
  std::size_t j = name_end(s, i);
  rest = j;
  return upper_text(s.substr(i, j - i));
}

inline bool has_jump(std::string_view s) {
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
inline std::string grid_text(const NcValue& v, int line, std::size_t at) {
  if (v.type == NcValue::Type::kString) return "\"" + v.text + "\"";
  if (v.type == NcValue::Type::kFrame)
    throw InputError(line, static_cast<int>(at) + 1, "a number is needed here, not a frame");
  if (!std::isfinite(v.number)) throw InputError(line, static_cast<int>(at) + 1, "the value is not a finite number");
  if (std::fabs(v.number) >= 1e12)
    throw InputError(line, static_cast<int>(at) + 1,
                     fmt::format("the value {} is out of the range of a position", v.number));
  char buffer[40];  // |value| < 1e12: at most 13 digits, the point and nine places
  char* e = std::to_chars(buffer, buffer + sizeof buffer, v.number, std::chars_format::fixed, 9).ptr;
  while (e[-1] == '0') --e;
  if (e[-1] == '.') --e;
  std::string t(buffer, e);
  if (t == "-0") t = "0";
  return t;
}

// A plain literal: [+-]digits[.digits], or a quoted string; where it ends.
inline std::optional<std::size_t> literal_end(std::string_view s, std::size_t i) {
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

inline bool is_r_parameter(const std::string& n) {
  if (n.size() < 2 || n[0] != 'R') return false;
  for (std::size_t k = 1; k < n.size(); ++k)
    if (!is_digit(n[k])) return false;
  return true;
}

inline constexpr int kRParameters = 1000;  // R0 … R999 (NC-PARAM-VAR-1)

// The number of "Rn" (is_r_parameter), or kRParameters when it is too large to exist.
inline int r_number(const std::string& n) {
  if (n.size() > 5) return kRParameters;
  return std::stoi(n.substr(1));
}

// NC-PARAM-VAR-2: the value type of a DEF or PROC type name (CHAR is a code, AXIS a name).
inline std::optional<NcValue::Type> value_type(std::string_view type) {
  if (type == "REAL") return NcValue::Type::kReal;
  if (type == "INT" || type == "CHAR") return NcValue::Type::kInt;
  if (type == "BOOL") return NcValue::Type::kBool;
  if (type == "STRING" || type == "AXIS") return NcValue::Type::kString;
  if (type == "FRAME") return NcValue::Type::kFrame;  // NC-PARAM-FRAME-1
  return std::nullopt;
}

}  // namespace cutcom::interpreter_text
