// NC-PARAM-EXPR-*: the expression parser of the interpreter (interpreter.cpp), a recursive
// descent over the manual's eleven priority levels. Names are read through a Lookup (variables,
// R parameters, system variables), which knows where the value lives.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cutcom/interpreter.hpp"

namespace cutcom {

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
  static std::string text_of(const NcValue& v);

  static constexpr int kMaxDepth = 64;
  static constexpr std::size_t kMaxChain = 1 << 16;  // characters of a frame chain
  int depth_ = 0, unary_depth_ = 0;
  std::string_view s_;
  std::size_t i_;
  int line_;
  Lookup& lookup_;
};

}  // namespace cutcom
