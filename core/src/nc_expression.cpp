// NC-PARAM-EXPR-*: expressions of the NC language, evaluated as the control does: REAL in
// binary64, the operators' priority of the manual (JOB06 p.1-24, highest first: NOT B_NOT;
// * / DIV MOD; + -; B_AND; B_XOR; B_OR; AND; XOR; OR; <<; comparisons), left to right within a
// level, angles in degrees.
#include "nc_expression.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "cutcom/reader.hpp"
#include "interpreter_text.hpp"
#include "word_lexer.hpp"

namespace cutcom {

using lexer::is_digit;
using lexer::is_letter;
using lexer::is_name_char;
using lexer::upper;

double as_number(const NcValue& v, int line, std::size_t at) {
  if (v.type == NcValue::Type::kString)
    throw InputError(line, static_cast<int>(at) + 1,
                     fmt::format("a number is needed here, not the string \"{}\"", v.text));
  if (v.type == NcValue::Type::kFrame)
    throw InputError(line, static_cast<int>(at) + 1, "a number is needed here, not a frame");
  return v.number;
}
// NC-PARAM-TYPE-1: an INT from a REAL is rounded to the nearest whole number (halves away from 0);
// a value beyond INT's range is an error.
std::int64_t as_int(const NcValue& v, int line, std::size_t at) {
  double d = std::round(as_number(v, line, at));
  if (!NcValue::fits_int(d))
    throw InputError(line, static_cast<int>(at) + 1,
                     fmt::format("{} is outside the range of INT (-2147483648 to 2147483647)", d));
  return static_cast<std::int64_t>(d);
}

namespace {

bool truth(const NcValue& v, int line, std::size_t at) { return as_number(v, line, at) != 0; }
const double kDegree = std::numbers::pi / 180;

}  // namespace

ExpressionParser::ExpressionParser(std::string_view text, std::size_t start, int line, Lookup& lookup)
    : s_(text), i_(start), line_(line), lookup_(lookup) {}

void ExpressionParser::fail(const std::string& what) const { throw InputError(line_, static_cast<int>(i_) + 1, what); }

void ExpressionParser::skip_space() {
  while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
}

// An upper-case keyword operator (AND, DIV, ...) at the current position, not part of a longer name.
bool ExpressionParser::keyword(std::string_view k) {
  skip_space();
  if (i_ + k.size() > s_.size()) return false;
  for (std::size_t j = 0; j < k.size(); ++j)
    if (upper(s_[i_ + j]) != k[j]) return false;
  if (i_ + k.size() < s_.size() && is_name_char(s_[i_ + k.size()])) return false;
  i_ += k.size();
  return true;
}

bool ExpressionParser::symbol(std::string_view k) {
  skip_space();
  if (s_.substr(i_, k.size()) != k) return false;
  i_ += k.size();
  return true;
}

NcValue ExpressionParser::parse() {
  // Nesting (parentheses, arguments, indices) is bounded: no program exhausts the stack.
  if (++depth_ > kMaxDepth) fail(fmt::format("the expression is nested more than {} levels deep", kMaxDepth));
  NcValue v = chain();
  --depth_;
  return v;
}

// NC-PARAM-FRAME-1: frame : frame chains the frames in the programmed order (the second in the
// system of the first), as the additive frame instructions do one after another. Only a frame
// is followed by ':' (a label's colon never stands in an expression).
NcValue ExpressionParser::chain() {
  NcValue a = comparison();
  while (a.type == NcValue::Type::kFrame) {
    skip_space();
    std::size_t at = i_;
    if (!symbol(":")) break;
    beyond_record();
    NcValue b = comparison();
    if (b.type != NcValue::Type::kFrame)
      throw InputError(line_, static_cast<int>(at) + 1, "':' chains frames: a frame is needed after it");
    if (a.text.size() + b.text.size() > kMaxChain)
      throw InputError(line_, static_cast<int>(at) + 1, "the frame chain is too long");
    if (!b.text.empty()) a.text += (a.text.empty() ? "" : "\n") + b.text;
  }
  return a;
}

// NC-PARAM-FRAME-1: CTRANS(axis, value, …), CROT(axis, angle, …), CSCALE(axis, factor, …),
// CMIRROR(axis, …) and CRPL(plane, angle) as the additive frame blocks they stand for, the values
// on the grid (NC-PARAM-GRID-1). Only geometry axes X, Y, Z are frame axes in cutcom.
NcValue ExpressionParser::frame_function(const std::string& n, std::size_t at) {
  bool mirror = n == "CMIRROR";
  std::string words;
  skip_space();
  if (n == "CRPL") {
    std::vector<NcValue> a = arguments(')');
    if (a.size() != 2) throw InputError(line_, static_cast<int>(at) + 1, "CRPL takes 2 arguments");
    double plane = as_number(a[0], line_, at);
    static constexpr std::string_view kAxis[] = {"RPL=", "Z", "Y", "X"};
    if (plane != 0 && plane != 1 && plane != 2 && plane != 3)
      throw InputError(line_, static_cast<int>(at) + 1,
                       "CRPL: the plane is 0 (the working plane), 1 (Z), 2 (Y) or 3 (X)");
    std::string angle = interpreter_text::grid_text(a[1], line_, at);
    return NcValue::frame(angle == "0" ? "" : fmt::format("AROT {}{}", kAxis[static_cast<int>(plane)], angle));
  }
  if (i_ < s_.size() && s_[i_] == ')') {  // CTRANS(): the identity
    ++i_;
    return NcValue::frame("");
  }
  while (true) {
    skip_space();
    std::size_t axis_at = i_;
    std::string axis = name();
    if (lookup_.is_variable(axis)) {  // an AXIS variable holding the axis' name
      NcValue held = lookup_.read(axis, {}, axis_at);
      axis = held.type == NcValue::Type::kString ? held.text : std::string();
      for (char& c : axis) c = upper(c);
    }
    if (axis != "X" && axis != "Y" && axis != "Z")
      throw InputError(line_, static_cast<int>(axis_at) + 1,
                       fmt::format("{}: an axis X, Y or Z is expected{}", n, axis.empty() ? "" : ", not " + axis));
    words += " " + axis;
    if (mirror) {
      words += "0";
    } else {
      if (!symbol(",")) fail(fmt::format("{} needs axis, value pairs", n));
      std::size_t value_at = i_;
      NcValue v = parse();
      if (n == "CSCALE" && as_number(v, line_, value_at) == 0)
        throw InputError(line_, static_cast<int>(value_at) + 1, fmt::format("CSCALE {}: a scale factor of 0", axis));
      words += interpreter_text::grid_text(v, line_, value_at);
    }
    if (symbol(")")) break;
    if (!symbol(",")) fail(fmt::format("',' or ')' expected in {}", n));
  }
  std::string_view block = n == "CTRANS" ? "ATRANS" : n == "CROT" ? "AROT" : n == "CSCALE" ? "ASCALE" : "AMIRROR";
  if (n == "CROT") {  // one AROT per axis: a rotation's axes are turned in the order written
    std::string out;
    for (std::size_t k = 1; k < words.size();) {
      std::size_t e = words.find(' ', k);
      if (e == std::string::npos) e = words.size();
      if (!out.empty()) out += '\n';
      out.append(block).append(" ").append(words, k, e - k);
      k = e + 1;
    }
    return NcValue::frame(out);
  }
  return NcValue::frame(std::string(block) + words);
}

// Level 11: == <> > < >= <= (lowest priority).
NcValue ExpressionParser::comparison() {
  NcValue a = concatenation();
  while (true) {
    skip_space();
    std::size_t at = i_;
    int op = 0;
    if (symbol("=="))
      op = 1;
    else if (symbol("<>"))
      op = 2;
    else if (symbol(">="))
      op = 3;
    else if (symbol("<="))
      op = 4;
    else if (symbol(">"))
      op = 5;
    else if (s_.substr(i_, 2) != "<<" && symbol("<"))
      op = 6;
    if (!op) return a;
    NcValue b = concatenation();
    a = nc_compare(a, b, op, line_, at);
    emit({CompiledExpression::Code::kCompare, op, at, 0, {}});
  }
}

NcValue nc_compare(const NcValue& a, const NcValue& b, int op, int line, std::size_t at) {
  if (a.type == NcValue::Type::kFrame || b.type == NcValue::Type::kFrame)
    throw InputError(line, static_cast<int>(at) + 1, "frames are not compared");
  bool r;
  if (a.type == NcValue::Type::kString || b.type == NcValue::Type::kString) {
    if (a.type != b.type) throw InputError(line, static_cast<int>(at) + 1, "a string is compared with a number");
    int c = a.text.compare(b.text);
    r = op == 1 ? c == 0 : op == 2 ? c != 0 : op == 3 ? c >= 0 : op == 4 ? c <= 0 : op == 5 ? c > 0 : c < 0;
  } else {
    // NC-PARAM-EXPR-3: equality of REALs is relative, to 1e-12 of the larger (PGA19 p.444).
    double x = a.number, y = b.number;
    bool equal = x == y || std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
    r = op == 1   ? equal
        : op == 2 ? !equal
        : op == 3 ? (equal || x > y)
        : op == 4 ? (equal || x < y)
        : op == 5 ? (!equal && x > y)
                  : (!equal && x < y);
  }
  return NcValue::boolean(r);
}

// Level 10: << joins strings (numbers are written as text).
NcValue ExpressionParser::concatenation() {
  NcValue a = logical_or();
  while (symbol("<<")) {
    beyond_record();
    NcValue b = logical_or();
    if (a.type == NcValue::Type::kFrame || b.type == NcValue::Type::kFrame) fail("a frame is not text");
    a = NcValue::string(text_of(a) + text_of(b));
  }
  return a;
}

std::string ExpressionParser::text_of(const NcValue& v) {
  if (v.type == NcValue::Type::kString) return v.text;
  if (v.type == NcValue::Type::kBool) return v.number != 0 ? "TRUE" : "FALSE";
  if (v.type == NcValue::Type::kInt && NcValue::fits_int(v.number))
    return fmt::format("{}", static_cast<std::int64_t>(v.number));
  return fmt::format("{}", v.number);
}

NcValue ExpressionParser::logical_or() {
  NcValue a = logical_xor();
  while (true) {
    std::size_t at = i_;
    if (!keyword("OR")) return a;
    beyond_record();
    NcValue b = logical_xor();
    a = NcValue::boolean(truth(a, line_, at) || truth(b, line_, at));
  }
}
NcValue ExpressionParser::logical_xor() {
  NcValue a = logical_and();
  while (true) {
    std::size_t at = i_;
    if (!keyword("XOR")) return a;
    beyond_record();
    NcValue b = logical_and();
    a = NcValue::boolean(truth(a, line_, at) != truth(b, line_, at));
  }
}
NcValue ExpressionParser::logical_and() {
  NcValue a = bit_or();
  while (true) {
    std::size_t at = i_;
    if (!keyword("AND")) return a;
    beyond_record();
    NcValue b = bit_or();
    a = NcValue::boolean(truth(a, line_, at) && truth(b, line_, at));
  }
}
NcValue ExpressionParser::bit_or() {
  NcValue a = bit_xor();
  while (true) {
    std::size_t at = i_;
    if (!keyword("B_OR")) return a;
    beyond_record();
    NcValue b = bit_xor();
    a = NcValue::integer(static_cast<double>(as_int(a, line_, at) | as_int(b, line_, at)));
  }
}
NcValue ExpressionParser::bit_xor() {
  NcValue a = bit_and();
  while (true) {
    std::size_t at = i_;
    if (!keyword("B_XOR")) return a;
    beyond_record();
    NcValue b = bit_and();
    a = NcValue::integer(static_cast<double>(as_int(a, line_, at) ^ as_int(b, line_, at)));
  }
}
NcValue ExpressionParser::bit_and() {
  NcValue a = sum();
  while (true) {
    std::size_t at = i_;
    if (!keyword("B_AND")) return a;
    beyond_record();
    NcValue b = sum();
    a = NcValue::integer(static_cast<double>(as_int(a, line_, at) & as_int(b, line_, at)));
  }
}

// INT op INT stays INT where the result is whole and within INT's range; otherwise REAL.
static NcValue arithmetic(const NcValue& a, const NcValue& b, double r) {
  if (a.type == NcValue::Type::kInt && b.type == NcValue::Type::kInt && r == std::trunc(r) && NcValue::fits_int(r))
    return NcValue::integer(r);
  return NcValue::real(r);
}

NcValue ExpressionParser::sum() {
  NcValue a = product();
  while (true) {
    std::size_t at = i_;
    skip_space();
    bool plus = symbol("+");
    if (!plus && !symbol("-")) return a;
    NcValue b = product();
    a = nc_sum(a, b, plus, line_, at);
    emit({CompiledExpression::Code::kSum, plus ? 1 : 0, at, 0, {}});
  }
}

NcValue nc_sum(const NcValue& a, const NcValue& b, bool plus, int line, std::size_t at) {
  double x = as_number(a, line, at), y = as_number(b, line, at);
  return arithmetic(a, b, plus ? x + y : x - y);
}

NcValue ExpressionParser::product() {
  NcValue a = unary();
  while (true) {
    std::size_t at = i_;
    int op = symbol("*") ? 1 : symbol("/") ? 2 : keyword("DIV") ? 3 : keyword("MOD") ? 4 : 0;
    if (!op) return a;
    NcValue b = unary();
    a = nc_product(a, b, op, line_, at);
    emit({CompiledExpression::Code::kProduct, op, at, 0, {}});
  }
}

NcValue nc_product(const NcValue& a, const NcValue& b, int op, int line, std::size_t at) {
  double x = as_number(a, line, at), y = as_number(b, line, at);
  if (op == 1) return arithmetic(a, b, x * y);
  // NC-PARAM-ERR-1: division by zero stops the program (alarm 14051 on the control).
  if (y == 0) throw InputError(line, static_cast<int>(at) + 1, "division by zero");
  if (op == 2) return NcValue::real(x / y);
  if (op == 3) {  // DIV: the whole part, an INT where it fits
    double q = std::trunc(x / y);
    return NcValue::fits_int(q) ? NcValue::integer(q) : NcValue::real(q);
  }
  return arithmetic(a, b, std::fmod(x, y));  // MOD: the remainder
}

NcValue nc_negate(NcValue v, int line, std::size_t at) {
  v.number = -as_number(v, line, at);
  if (v.type == NcValue::Type::kBool) v.type = NcValue::Type::kInt;
  return v;
}

NcValue ExpressionParser::unary() {
  std::size_t at = i_;
  if (++unary_depth_ > kMaxDepth * 4) fail("too many signs or NOTs in a row");
  struct Leave {
    int& d;
    ~Leave() { --d; }
  } leave{unary_depth_};
  if (keyword("NOT")) return beyond_record(), NcValue::boolean(!truth(unary(), line_, at));
  if (keyword("B_NOT")) return beyond_record(), NcValue::integer(static_cast<double>(~as_int(unary(), line_, at)));
  if (symbol("-")) {
    NcValue v = nc_negate(unary(), line_, at);
    emit({CompiledExpression::Code::kNegate, 0, at, 0, {}});
    return v;
  }
  if (symbol("+")) return unary();
  return primary();
}

std::string ExpressionParser::name() {
  std::size_t start = i_;
  if (i_ < s_.size() && s_[i_] == '$') ++i_;
  while (i_ < s_.size() && is_name_char(s_[i_])) ++i_;
  std::string n(s_.substr(start, i_ - start));
  for (char& c : n) c = upper(c);
  return n;
}

std::vector<NcValue> ExpressionParser::arguments(char close) {
  std::vector<NcValue> args;
  skip_space();
  if (i_ < s_.size() && s_[i_] == close) {
    ++i_;
    return args;
  }
  while (true) {
    args.push_back(parse());
    skip_space();
    if (i_ < s_.size() && s_[i_] == ',') {
      ++i_;
      continue;
    }
    if (i_ < s_.size() && s_[i_] == close) {
      ++i_;
      return args;
    }
    fail(fmt::format("'{}' or ',' expected", close));
  }
}

NcValue ExpressionParser::primary() {
  skip_space();
  if (i_ >= s_.size()) fail("a value is missing");
  char c = s_[i_];
  std::size_t at = i_;
  if (c == '(') {
    ++i_;
    NcValue v = parse();
    if (!symbol(")")) fail("')' expected");
    return v;
  }
  if (c == '"') {
    beyond_record();
    std::size_t end = s_.find('"', i_ + 1);
    if (end == std::string_view::npos) fail("the string has no closing '\"'");
    NcValue v = NcValue::string(std::string(s_.substr(i_ + 1, end - i_ - 1)));
    i_ = end + 1;
    return v;
  }
  if (is_digit(c) || c == '.') {
    NcValue v = number();
    emit({CompiledExpression::Code::kConstant, 0, at, 0, v});
    return v;
  }
  if (!is_letter(c) && c != '$' && c != '_') fail("unexpected character " + lexer::character_text(s_.substr(i_)));
  std::string n = name();
  skip_space();
  bool call = i_ < s_.size() && s_[i_] == '(';
  bool indexed = i_ < s_.size() && s_[i_] == '[';
  if (call || indexed) beyond_record();
  if (call) {
    ++i_;
    if (n == "CTRANS" || n == "CROT" || n == "CSCALE" || n == "CMIRROR" || n == "CRPL") return frame_function(n, at);
    std::vector<NcValue> args = arguments(')');
    return function(n, args, at);
  }
  std::vector<NcValue> indices;
  if (indexed) {
    ++i_;
    // An axis as an index ($AA_IW[X], $P_EP[Y]) is its name, unless a variable of that name
    // exists; so is a frame component after one ($P_PFRAME[X,TR], $P_UIFR[1,X,TR]), always.
    static constexpr std::string_view kAxes[] = {"X", "Y", "Z"};
    static constexpr std::string_view kComponents[] = {"TR", "FI", "RT", "SC", "MI"};
    bool after_axis = false;
    skip_space();
    if (i_ < s_.size() && s_[i_] == ']') fail("an index is expected");
    while (true) {
      skip_space();
      std::size_t k = i_;
      bool named = false;
      if (i_ < s_.size() && is_letter(s_[i_])) {
        std::string a = name();
        skip_space();
        bool ends = i_ < s_.size() && (s_[i_] == ']' || s_[i_] == ',');
        bool axis = std::find(std::begin(kAxes), std::end(kAxes), a) != std::end(kAxes) && !lookup_.is_variable(a);
        bool component =
            after_axis && std::find(std::begin(kComponents), std::end(kComponents), a) != std::end(kComponents);
        if (ends && (axis || component))
          indices.push_back(NcValue::string(a)), named = true;
        else
          i_ = k;
        after_axis = ends && axis;
      } else {
        after_axis = false;
      }
      if (!named) indices.push_back(parse());
      skip_space();
      if (i_ < s_.size() && s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (i_ < s_.size() && s_[i_] == ']') {
        ++i_;
        break;
      }
      fail("']' or ',' expected");
    }
  }
  if (n == "TRUE" || n == "FALSE") {
    NcValue v = NcValue::boolean(n == "TRUE");
    emit({CompiledExpression::Code::kConstant, 0, at, 0, v});
    return v;
  }
  NcValue v = lookup_.read(n, indices, at);
  if (record_ && !indexed) {
    if (n[0] == '$') {
      beyond_record();
    } else if (interpreter_text::is_r_parameter(n)) {  // read() raised the error of a number too large
      emit({CompiledExpression::Code::kRParameter, 0, at, interpreter_text::r_number(n), {}});
    } else {
      record_->names.push_back(n);
      emit({CompiledExpression::Code::kVariable, 0, at, static_cast<int>(record_->names.size() - 1), {}});
    }
  }
  return v;
}

NcValue CompiledExpression::evaluate(const NcValue* const* variables, const std::map<int, double>& r, int line) const {
  // A stack as deep as the expression; most loop expressions need a few entries.
  NcValue small[8];
  std::vector<NcValue> large;
  NcValue* stack = small;
  if (ops.size() > 8) {
    large.resize(ops.size());
    stack = large.data();
  }
  std::size_t top = 0;
  for (const Op& op : ops) {
    switch (op.code) {
      case Code::kConstant:
        stack[top++] = op.constant;
        break;
      case Code::kVariable:
        stack[top++] = *variables[op.index];
        break;
      case Code::kRParameter: {
        auto it = r.find(op.index);
        stack[top++] = NcValue::real(it == r.end() ? 0.0 : it->second);
        break;
      }
      case Code::kNegate:
        stack[top - 1] = nc_negate(std::move(stack[top - 1]), line, op.at);
        break;
      case Code::kSum:
        stack[top - 2] = nc_sum(stack[top - 2], stack[top - 1], op.operation == 1, line, op.at);
        --top;
        break;
      case Code::kProduct:
        stack[top - 2] = nc_product(stack[top - 2], stack[top - 1], op.operation, line, op.at);
        --top;
        break;
      case Code::kCompare:
        stack[top - 2] = nc_compare(stack[top - 2], stack[top - 1], op.operation, line, op.at);
        --top;
        break;
    }
  }
  return std::move(stack[0]);
}

// Numbers: digits with a decimal point, an exponent written EX (10EX-5).
NcValue ExpressionParser::number() {
  std::size_t start = i_;
  bool point = false;
  while (i_ < s_.size() && (is_digit(s_[i_]) || (s_[i_] == '.' && !point))) point |= s_[i_++] == '.';
  std::string digits(s_.substr(start, i_ - start));
  if (digits == ".") fail("a number is expected");
  int exponent = 0;
  if (i_ + 1 < s_.size() && upper(s_[i_]) == 'E' && upper(s_[i_ + 1]) == 'X') {
    i_ += 2;
    bool negative = false;
    if (i_ < s_.size() && (s_[i_] == '-' || s_[i_] == '+')) negative = s_[i_++] == '-';
    std::size_t e = i_;
    while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    if (e == i_ || i_ - e > 3) fail("an exponent of one to three digits is expected after EX");
    exponent = std::stoi(std::string(s_.substr(e, i_ - e))) * (negative ? -1 : 1);
  }
  double v = std::strtod((digits + "e" + std::to_string(exponent)).c_str(), nullptr);
  return point || exponent < 0 || !NcValue::fits_int(v) ? NcValue::real(v) : NcValue::integer(v);
}

NcValue ExpressionParser::function(const std::string& n, const std::vector<NcValue>& a, std::size_t at) {
  auto need = [&](std::size_t k) {
    if (a.size() != k)
      throw InputError(line_, static_cast<int>(at) + 1, fmt::format("{} takes {} argument{}", n, k, k == 1 ? "" : "s"));
  };
  auto x = [&](std::size_t k) { return as_number(a[k], line_, at); };
  auto domain = [&](bool ok) {
    if (!ok) throw InputError(line_, static_cast<int>(at) + 1, fmt::format("{}: argument outside its domain", n));
  };
  if (n == "SIN") return need(1), NcValue::real(std::sin(x(0) * kDegree));
  if (n == "COS") return need(1), NcValue::real(std::cos(x(0) * kDegree));
  if (n == "TAN") return need(1), NcValue::real(std::tan(x(0) * kDegree));
  if (n == "ASIN") return need(1), domain(std::fabs(x(0)) <= 1), NcValue::real(std::asin(x(0)) / kDegree);
  if (n == "ACOS") return need(1), domain(std::fabs(x(0)) <= 1), NcValue::real(std::acos(x(0)) / kDegree);
  if (n == "ATAN2") return need(2), NcValue::real(std::atan2(x(0), x(1)) / kDegree);
  if (n == "SQRT") return need(1), domain(x(0) >= 0), NcValue::real(std::sqrt(x(0)));
  if (n == "ABS") {
    need(1);
    NcValue v = a[0];
    v.number = std::fabs(x(0));
    return v;
  }
  if (n == "POT") return need(1), arithmetic(a[0], a[0], x(0) * x(0));
  if (n == "TRUNC") return need(1), NcValue::real(std::trunc(x(0)));
  if (n == "ROUND") return need(1), NcValue::real(std::round(x(0)));
  if (n == "ROUNDUP") return need(1), NcValue::real(x(0) > 0 ? std::ceil(x(0)) : std::floor(x(0)));
  if (n == "LN") return need(1), domain(x(0) > 0), NcValue::real(std::log(x(0)));
  if (n == "EXP") return need(1), NcValue::real(std::exp(x(0)));
  if (n == "MINVAL") return need(2), NcValue::real(std::min(x(0), x(1)));
  if (n == "MAXVAL") return need(2), NcValue::real(std::max(x(0), x(1)));
  if (n == "BOUND") {
    need(3);  // BOUND(minimum, maximum, value)
    return NcValue::real(std::min(std::max(x(2), x(0)), x(1)));
  }
  if (NcValue v; string_function(n, a, at, v)) return v;
  throw InputError(line_, static_cast<int>(at) + 1,
                   fmt::format("'{}(' is not a function cutcom evaluates (NC-PARAM-EXPR-2 lists them)", n));
}

}  // namespace cutcom
