// NC-PARAM-EXPR-*: the expression parser of the interpreter (interpreter.cpp), a recursive
// descent over the manual's eleven priority levels. Names are read through a Lookup (variables,
// R parameters, system variables), which knows where the value lives.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cutcom/interpreter.hpp"

namespace cutcom {

// NC-PARAM-EXPR-4: an expression of numbers, scalar variables and R parameters with the
// arithmetic and comparison operators, recorded while ExpressionParser evaluates it once, so that
// a loop pass evaluates it again without reading its text. The operations are the parser's own
// (nc_sum, nc_product, …): the value and every error are those of the parser.
struct CompiledExpression {
  enum class Code : std::uint8_t { kConstant, kVariable, kRParameter, kNegate, kSum, kProduct, kCompare };
  struct Op {
    Code code;
    int operation = 0;   // kSum: 1 plus, 0 minus; kProduct, kCompare: the parser's operator number
    std::size_t at = 0;  // column (0-based) the parser names in an error
    int index = 0;       // kVariable: into names; kRParameter: the parameter's number
    NcValue constant;
  };
  std::vector<Op> ops;
  std::vector<std::string> names;  // user variables read, upper case
  std::size_t end = 0;             // where the parser stopped
  bool complete = true;            // false: a construct beyond the above was met

  // The value, with the values of `names` in that order (a scalar's value each).
  NcValue evaluate(const NcValue* const* variables, const std::map<int, double>& r, int line) const;
};

// A value as a REAL (a string or a frame is an error naming the line and column) and as an INT
// (NC-PARAM-TYPE-1: rounded to the nearest, halves away from 0).
double as_number(const NcValue& v, int line, std::size_t at);
std::int64_t as_int(const NcValue& v, int line, std::size_t at);

// The parser's operations, shared by the compiled form (NC-PARAM-EXPR-1/3, NC-PARAM-TYPE-1).
NcValue nc_negate(NcValue v, int line, std::size_t at);
NcValue nc_sum(const NcValue& a, const NcValue& b, bool plus, int line, std::size_t at);
NcValue nc_product(const NcValue& a, const NcValue& b, int op, int line, std::size_t at);
NcValue nc_compare(const NcValue& a, const NcValue& b, int op, int line, std::size_t at);

class ExpressionParser {
 public:
  class Lookup {
   public:
    virtual ~Lookup() = default;
    // The value of a name (upper case) with its indices; throws InputError for an unknown one.
    virtual NcValue read(const std::string& name, const std::vector<NcValue>& indices, std::size_t at) = 0;
    virtual bool is_variable(const std::string& name) const = 0;
  };

  ExpressionParser(std::string_view text, std::size_t start, int line, Lookup& lookup);
  // One expression from the start position; position() is where it ended.
  NcValue parse();
  std::size_t position() const { return i_; }
  // Records the expression as it is parsed (CompiledExpression::complete tells whether it can be
  // evaluated from the record).
  void record(CompiledExpression* into) { record_ = into; }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  void skip_space();
  bool keyword(std::string_view k);
  bool symbol(std::string_view k);
  NcValue chain();
  NcValue comparison();
  NcValue concatenation();
  NcValue logical_or();
  NcValue logical_xor();
  NcValue logical_and();
  NcValue bit_or();
  NcValue bit_xor();
  NcValue bit_and();
  NcValue sum();
  NcValue product();
  NcValue unary();
  NcValue primary();
  NcValue number();
  std::string name();
  std::vector<NcValue> arguments(char close);
  NcValue frame_function(const std::string& name, std::size_t at);
  NcValue function(const std::string& name, const std::vector<NcValue>& args, std::size_t at);
  bool string_function(const std::string& n, const std::vector<NcValue>& args, std::size_t at, NcValue& out);
  static std::string text_of(const NcValue& v);

  static constexpr int kMaxDepth = 64;
  static constexpr std::size_t kMaxChain = 1 << 16;  // characters of a frame chain
  int depth_ = 0, unary_depth_ = 0;
  std::string_view s_;
  std::size_t i_;
  int line_;
  Lookup& lookup_;
  CompiledExpression* record_ = nullptr;
  void emit(CompiledExpression::Op op) {
    if (record_) record_->ops.push_back(std::move(op));
  }
  void beyond_record() {
    if (record_) record_->complete = false;
  }
};

}  // namespace cutcom
