// How expressions read names (ExpressionParser::Lookup) in the interpreter's variables: R
// parameters (global), user variables of the running level, system variables (NC-PARAM-SYS-1).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "cutcom/interpreter.hpp"
#include "cutcom/machine_data.hpp"
#include "interpreter_text.hpp"
#include "nc_expression.hpp"

namespace cutcom {

class InterpreterLookup : public ExpressionParser::Lookup {
 public:
  InterpreterLookup(Interpreter& it, int line) : it_(it), line_(line) {}
  NcValue read(const std::string& n, const std::vector<NcValue>& idx, std::size_t at) override {
    if (n == "R" && idx.size() == 1) return NcValue::real(r_value(idx[0], at));
    if (interpreter_text::is_r_parameter(n) && idx.empty()) {
      int k = interpreter_text::r_number(n);
      if (k >= interpreter_text::kRParameters)
        fail(at, fmt::format("R parameter {} does not exist (R0 to R{})", n, interpreter_text::kRParameters - 1));
      auto it = it_.r_.find(k);
      return NcValue::real(it == it_.r_.end() ? 0.0 : it->second);
    }
    if (n == "$P_PFRAME" && idx.empty()) {  // NC-PARAM-FRAME-1
      std::optional<std::string> chain = it_.system_ ? it_.system_->programmable_frame() : std::nullopt;
      if (!chain) fail(at, "$P_PFRAME cannot be read here (a translation under inch units G70/G700 is not simulated)");
      return NcValue::frame(*chain);
    }
    // NC-PARAM-FRAME-2: a settable offset ($P_UIFR[n]) or the one in force ($P_IFRAME) as a frame.
    if ((n == "$P_UIFR" && idx.size() == 1) || (n == "$P_IFRAME" && idx.empty())) {
      int k = -1;
      if (!idx.empty()) {
        if (idx[0].type == NcValue::Type::kString || idx[0].number != std::trunc(idx[0].number) || idx[0].number < 0 ||
            idx[0].number > 99)
          fail(at, "$P_UIFR takes the offset's number, 0 to 99 (G54 = 1)");
        k = static_cast<int>(idx[0].number);
      }
      std::optional<std::string> chain = it_.system_ ? it_.system_->settable_frame(k) : std::nullopt;
      if (!chain) fail(at, fmt::format("{} cannot be read here", n));
      return NcValue::frame(*chain);
    }
    if (n == "$P_SUBPAR") {  // NC-PARAM-SYS-3: was parameter k given in the call?
      if (idx.size() != 1 || idx[0].type == NcValue::Type::kString || idx[0].number < 1 ||
          idx[0].number != std::trunc(idx[0].number))
        fail(at, "$P_SUBPAR takes one index, the parameter's number from 1");
      std::size_t k = static_cast<std::size_t>(idx[0].number) - 1;
      const auto& args = it_.cx().args;
      return NcValue::boolean(k < args.size() && args[k].has_value());
    }
    if (is_machine_or_setting_datum(n)) return machine_datum(n, idx, at);  // NC-PARAM-SYS-4
    if (n == "$TC_TP2") {                                                  // NC-PARAM-SYS-1: the tool's name
      if (idx.size() != 1 || idx[0].type == NcValue::Type::kString)
        fail(at, "$TC_TP2 takes one index, the tool number");
      std::optional<std::string> name = it_.system_ ? it_.system_->tool_name(idx[0].number) : std::nullopt;
      if (!name)
        fail(at, fmt::format("$TC_TP2[{}]: tool {} has no name ($TC_TP2[t]=\"NAME\" or --tools)", idx[0].number,
                             idx[0].number));
      return NcValue::string(*name);
    }
    if (!n.empty() && n[0] == '$') {
      std::optional<double> v = it_.system_ ? it_.system_->system_value(n, idx) : std::nullopt;
      bool frame = n == "$P_PFRAME" || n == "$P_UIFR" || n == "$P_IFRAME";
      if (!v && frame)  // NC-PARAM-FRAME-2
        fail(at, fmt::format("{} is read as a frame or by a component: {}[{}X,TR] (TR, FI, RT, SC, MI of X, Y, Z)", n,
                             n, n == "$P_UIFR" ? "n," : ""));
      if (!v && n.find("FRAME") != std::string::npos)
        fail(at, fmt::format("the frame variable {} is not simulated ($P_PFRAME, $P_UIFR and $P_IFRAME are)", n));
      if (!v && n.rfind("$TC_DP", 0) == 0 && idx.size() == 2 && idx[0].type != NcValue::Type::kString &&
          idx[1].type != NcValue::Type::kString)
        fail(at, fmt::format("{}[{},{}]: tool {} has no edge {} (no data was assigned to it)", n, idx[0].number,
                             idx[1].number, idx[0].number, idx[1].number));
      if (!v) {  // NC-PARAM-SYS-4: a value the user gave for it (--sysvar)
        auto given = it_.machine_values_.find(datum_key(n, idx, at));
        if (given != it_.machine_values_.end()) return given->second;
        fail(at, fmt::format("system variable {} is not one cutcom knows (NC-PARAM-SYS-1 lists them); give the "
                             "value the program should read with --sysvar '{}=VALUE' (NC-PARAM-SYS-4)",
                             n, datum_key(n, idx, at)));
      }
      return NcValue::real(*v);
    }
    Interpreter::Variable* v = it_.find_variable(n);
    if (!v) fail(at, fmt::format("undefined variable '{}'", n));
    return v->values[offset(n, *v, idx, at)];
  }
  // The name with its index as the machine data and --sysvar give it: "$A_IN[1]", "$SA_X[Z]".
  std::string datum_key(const std::string& n, const std::vector<NcValue>& idx, std::size_t at) const {
    std::string key = n;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      key += k == 0 ? '[' : ',';
      if (idx[k].type == NcValue::Type::kString)
        key += idx[k].text;
      else if (idx[k].number == std::trunc(idx[k].number) && std::abs(idx[k].number) < 1e15)
        key += fmt::format("{}", static_cast<long long>(idx[k].number));
      else
        fail(at, fmt::format("an index of {} must be a whole number or an axis name", n));
    }
    if (!idx.empty()) key += ']';
    return key;
  }
  NcValue machine_datum(const std::string& n, const std::vector<NcValue>& idx, std::size_t at) const {
    std::string key = datum_key(n, idx, at);
    auto v = it_.machine_values_.find(key);
    if (v == it_.machine_values_.end())
      fail(at, fmt::format("{} is {} data that cutcom has no value for: give it with --md '{}=VALUE' (a number or "
                           "\"text\", NC-PARAM-SYS-4)",
                           key, n[1] == 'M' ? "machine" : "setting", key));
    return v->second;
  }
  // A user variable; or a system variable with a value given for it, with any index (NC-PARAM-SYS-4).
  bool is_variable(const std::string& n) const override {
    if (!n.empty() && n[0] == '$') {
      if (it_.machine_values_.count(n)) return true;
      const std::string indexed = n + "[";
      auto given = it_.machine_values_.lower_bound(indexed);
      return given != it_.machine_values_.end() && given->first.compare(0, indexed.size(), indexed) == 0;
    }
    return it_.find_variable(n) != nullptr;
  }

  double r_value(const NcValue& index, std::size_t at) {
    int k = r_index(index, at);
    auto it = it_.r_.find(k);
    return it == it_.r_.end() ? 0.0 : it->second;
  }
  int r_index(const NcValue& index, std::size_t at) {
    if (index.type == NcValue::Type::kString) fail(at, "an R parameter's index must be a number");
    double k = std::round(index.number);
    if (k < 0 || k >= interpreter_text::kRParameters)
      fail(at, fmt::format("R parameter R[{}] does not exist (R0 to R{})", k, interpreter_text::kRParameters - 1));
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

}  // namespace cutcom
