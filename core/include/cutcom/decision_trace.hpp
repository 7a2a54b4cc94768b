// The engines' channel for decisions and alarms (TRACE-1, ALARM-1), shared by the stages of each
// engine's pipeline: every decision goes to the sink as it is taken; an alarm first lets the
// pipeline put out what was decided before it (its `before_alarm`), then stops the program.
// fast traces margins as doubles, ref as exact decimals (Margins).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "cutcom/alarm.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "cutcom/sink.hpp"

namespace cutcom {

class Trace {
 public:
  enum class Margins { kDouble, kExact };
  Trace(PathSink& sink, Margins margins) : sink_(sink), margins_(margins), keeps_decisions_(sink.keeps_decisions()) {}
  // Whether a decision given to decide() reaches anything (PathSink::keeps_decisions): if not,
  // decide() returns at once.
  bool keeps_decisions() const { return keeps_decisions_; }

  void decide(std::string_view clause, int line, std::string_view branch) {
    if (!keeps_decisions_) return;
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch;
    sink_.decision(d);
  }
  void decide(std::string_view clause, int line, std::string_view branch, double margin) {
    if (!keeps_decisions_) return;
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch, d.has_margin = true, d.margin = margin;
    sink_.decision(d);
  }
  void decide(std::string_view clause, int line, std::string_view branch, std::string exact_margin) {
    if (!keeps_decisions_) return;
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch, d.has_margin = true, d.margin_exact = std::move(exact_margin);
    sink_.decision(d);
  }
  // A decision on programmed decimals, taken in core (programmed_decisions.hpp), with the margin
  // in the engine's kind.
  void decide(const ProgrammedDecision& d, int line) {
    if (!d.has_margin) return decide(d.clause, line, d.branch);
    if (margins_ == Margins::kExact) return decide(d.clause, line, d.branch, d.exact);
    decide(d.clause, line, d.branch, d.approx);
  }

  // ALARM-1: what was decided before the alarm is output first.
  void raise(int number, int line, std::optional<std::int64_t> block, std::string_view clause = {},
             std::uint32_t source = 0) {
    if (before_alarm_) before_alarm_();
    Alarm a = make_alarm(number, line, block, clause);
    a.source = source;  // NC-PARAM-SUB-3
    sink_.alarm(a);
    stopped_ = true;
  }
  void raise(int number, const Block& at, std::string_view clause = {}) {
    raise(number, at.words.line, at.words.number, clause, at.words.source);
  }
  // At a block's words or an engine's copy of a block: anything with line, number and source.
  template <class At>
  void raise(int number, const At& at, std::string_view clause = {}) {
    raise(number, at.line, at.number, clause, at.source);
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
  Margins margins_;
  bool keeps_decisions_;
  std::function<void()> before_alarm_;
  bool stopped_ = false;
};

}  // namespace cutcom
