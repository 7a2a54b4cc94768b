// NC-PARAM-EXPR-4: running a cached line again from what its first run recorded
// (interpreter_record.hpp): its expressions without reading their text, and a line of
// assignments and words from its plan.
#include "interpreter_record.hpp"

#include "cutcom/interpreter.hpp"
#include "interpreter_lookup.hpp"
#include "interpreter_text.hpp"

namespace cutcom {

using namespace interpreter_text;

LineRecord& Interpreter::record_of(CachedLine& line) {
  if (!line.record) line.record.reset(new LineRecord);
  return *line.record;
}

bool Interpreter::resolve(const std::vector<std::string>& names, std::vector<Variable*>& into) {
  into.resize(names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    Variable* v = find_variable(names[k]);
    if (!v || !v->dims.empty()) return false;  // the text says what is wrong
    into[k] = v;
  }
  return true;
}

namespace {

// A record's values from its resolved variables (a few; more than 16 are read from the text).
struct Values {
  const NcValue* at[16];
  explicit Values(const std::vector<Interpreter::Variable*>& vars) {
    for (std::size_t k = 0; k < vars.size(); ++k) at[k] = &vars[k]->values[0];
  }
};
constexpr std::size_t kMaxNames = 16;

}  // namespace

NcValue Interpreter::expression(std::string_view s, std::size_t from, InterpreterLookup& lookup, std::size_t& end,
                                int* recorded) {
  if (recorded) *recorded = -1;
  // Only the text of the line next() runs has a record (not arguments, definitions files, …).
  if (current_cached_ && s.data() == raw_.data() && s.size() == raw_.size()) {
    LineRecord& rec = record_of(*current_cached_);
    std::size_t k = 0;
    while (k < rec.expressions.size() && rec.expressions[k].first != from) ++k;
    if (k < rec.expressions.size()) {  // recorded before: evaluated from the record if it applies
      const std::optional<CompiledExpression>& ce = rec.expressions[k].second;
      ResolvedNames& r = rec.resolved[k];
      if (ce && r.epoch != variables_epoch_ && resolve(ce->names, r.variables)) r.epoch = variables_epoch_;
      if (ce && r.epoch == variables_epoch_) {
        if (recorded) *recorded = static_cast<int>(k);
        end = ce->end;
        return ce->evaluate(Values(r.variables).at, r_, cx().line);
      }
    } else {  // the first run: parsed and recorded
      CompiledExpression ce;
      ExpressionParser p(s, from, cx().line, lookup);
      p.record(&ce);
      NcValue v = p.parse();
      end = ce.end = p.position();
      // Records count against the line cache's bytes: memory stays bounded.
      std::size_t bytes = sizeof ce + ce.ops.size() * sizeof(CompiledExpression::Op) + 32 * ce.names.size();
      bool usable = ce.complete && ce.names.size() <= kMaxNames && cached_bytes_ + bytes <= limits_.line_cache_bytes;
      if (usable) cached_bytes_ += bytes;
      rec.expressions.emplace_back(from, usable ? std::optional<CompiledExpression>(std::move(ce)) : std::nullopt);
      rec.resolved.emplace_back();
      if (recorded && usable) *recorded = static_cast<int>(rec.expressions.size() - 1);
      return v;
    }
  }
  ExpressionParser p(s, from, cx().line, lookup);
  NcValue v = p.parse();
  end = p.position();
  return v;
}

bool Interpreter::run_plan(LineRecord& record, std::string& out) {
  const LinePlan& plan = *record.plan;
  ResolvedNames& r = record.plan_resolved;
  if (r.epoch != variables_epoch_) {
    for (const std::string& w : plan.words)  // an address word must not have become a variable
      if (find_variable(w)) return false;
    if (!resolve(plan.names, r.variables)) return false;
    for (std::size_t k = 0; k < record.expressions.size(); ++k) {
      const std::optional<CompiledExpression>& ce = record.expressions[k].second;
      ResolvedNames& e = record.resolved[k];
      if (ce && !resolve(ce->names, e.variables)) return false;
      e.epoch = variables_epoch_;
    }
    r.epoch = variables_epoch_;
  }
  out.clear();
  std::size_t from = 0;
  std::size_t target = 0;
  for (const LinePlan::Step& step : plan.steps) {
    const CompiledExpression& ce = *record.expressions[static_cast<std::size_t>(step.expression)].second;
    NcValue value =
        ce.evaluate(Values(record.resolved[static_cast<std::size_t>(step.expression)].variables).at, r_, cx().line);
    switch (step.kind) {
      case LinePlan::Step::Kind::kValue:
        out.append(plan.text, from, step.text_at - from);
        out += grid_text(value, cx().line, step.value_at);
        from = step.text_at;
        break;
      case LinePlan::Step::Kind::kAssignR:
        if (value.type == NcValue::Type::kString)
          throw InputError(cx().line, static_cast<int>(step.value_at) + 1,
                           "an R parameter holds a number, not a string");
        r_[step.r] = value.number;
        break;
      case LinePlan::Step::Kind::kAssignVariable:
        store(*r.variables[target++], 0, value, step.start);
        break;
    }
  }
  out.append(plan.text, from, std::string::npos);
  return true;
}

}  // namespace cutcom
