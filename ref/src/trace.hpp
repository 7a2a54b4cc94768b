// ref's trace and alarm channel, shared by the stages (as fast/src/trace.hpp; no code is shared):
// every decision goes to the sink as it is taken, its margin exact; an alarm first lets the
// pipeline put out what was decided before it (ALARM-1), then stops the program.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "cutcom/alarm.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::ref::detail {

class Trace {
 public:
  explicit Trace(PathSink& sink) : sink_(sink) {}

  void decide(std::string_view clause, int line, std::string_view branch) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch;
    sink_.decision(d);
  }
  void decide(std::string_view clause, int line, std::string_view branch, std::string margin) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch, d.has_margin = true, d.margin_exact = std::move(margin);
    sink_.decision(d);
  }
  // A decision on programmed decimals, taken in core (programmed_decisions.hpp): its exact margin.
  void decide(const ProgrammedDecision& d, int line) {
    if (d.has_margin) return decide(d.clause, line, d.branch, d.exact);
    decide(d.clause, line, d.branch);
  }

  // ALARM-1: what was decided before the alarm is output first (the pipeline's `before_alarm`).
  void raise(int number, const Block& at, std::string_view clause = {}) {
    if (before_alarm_) before_alarm_();
    sink_.alarm(make_alarm(number, at.words.line, at.words.number, clause));
    stopped_ = true;
  }
  // An alarm whose clause is the catalogue's.
  void raise_catalogued(int number, const Block& at) {
    const AlarmInfo* info = find_alarm(number);
    raise(number, at, info ? info->clause : std::string_view{});
  }

  bool stopped() const { return stopped_; }
  void set_before_alarm(std::function<void()> f) { before_alarm_ = std::move(f); }

 private:
  PathSink& sink_;
  std::function<void()> before_alarm_;
  bool stopped_ = false;
};

}  // namespace cutcom::ref::detail
