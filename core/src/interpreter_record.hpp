// NC-PARAM-EXPR-4: what a cached program line keeps of its first run, so that a loop pass or a
// second call runs it without reading its text again. Every record is taken from the parser's and
// run_line's own work on that first run: the second run gives the same blocks, values and errors.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cutcom/interpreter.hpp"
#include "nc_expression.hpp"

namespace cutcom {

// A line of assignments and address words (no statement, call, label, jump, index or system
// variable): the block's text without its computed values, and the steps that compute them.
struct LinePlan {
  struct Step {
    enum class Kind { kAssignR, kAssignVariable, kValue } kind;
    int expression = 0;        // into LineRecord::expressions
    int r = 0;                 // kAssignR: the parameter
    std::string name;          // kAssignVariable: the variable (upper case)
    std::size_t start = 0;     // the word's column (errors of the assignment)
    std::size_t value_at = 0;  // the value's column (errors of the value)
    std::size_t text_at = 0;   // kValue: where in `text` the value is written
    std::size_t length = 0;    // while recording: the value's length in the block
  };
  std::string text;
  std::vector<Step> steps;
  std::vector<std::string> names;  // the variables assigned, in the order of their steps
  std::vector<std::string> words;  // address words taken as no variable when recorded
};

// Variables a record reads, as last resolved (valid while the interpreter's epoch is the same).
struct ResolvedNames {
  std::uint64_t epoch = ~std::uint64_t{0};
  std::vector<Interpreter::Variable*> variables;
};

struct LineRecord {
  // By the column the expression starts at; empty: it cannot be evaluated from a record.
  std::vector<std::pair<std::size_t, std::optional<CompiledExpression>>> expressions;
  std::vector<ResolvedNames> resolved;  // of each expression
  std::optional<LinePlan> plan;
  ResolvedNames plan_resolved;
  bool plan_tried = false;  // the line ran once: a plan was kept or cannot be
};

}  // namespace cutcom
