// Where an engine delivers its results, in program order. Engines stream into a sink; the
// collecting sink keeps everything (tests, properties, SVG).
#pragma once

#include <vector>

#include "cutcom/alarm.hpp"
#include "cutcom/path.hpp"
#include "cutcom/trace.hpp"

namespace cutcom {

// SAR-VAR-1: $P_APR (P3) and $P_AEP (P4) of a SAR approach block, programmed-contour positions in
// workpiece coordinates (decision 16); $P_APDV = 1: they belong to the last SAR approach programmed.
struct SarVariables {
  int line = 0;
  std::optional<std::int64_t> block;
  PathPoint p_apr, p_aep;
  int p_apdv = 1;
};

class PathSink {
 public:
  virtual ~PathSink() = default;
  virtual void element(const PathElement& e) = 0;
  virtual void action(const ActionEvent&) {}
  virtual void decision(const Decision&) {}
  // Whether decisions reach anything: where they do not, the trace does not put them out (seven a
  // block under CDON, a tenth of fast's time) and an engine may leave out the work only their
  // margins need (ref's exact margins as text).
  virtual bool keeps_decisions() const { return true; }
  virtual void alarm(const Alarm&) {}
  virtual void notice(const Notice&) {}
  virtual void sar_variables(const SarVariables&) {}
};

struct RunResult {
  std::vector<PathElement> path;
  std::vector<ActionEvent> actions;
  std::vector<Decision> decisions;
  std::vector<Alarm> alarms;
  std::vector<Notice> notices;
  std::vector<SarVariables> variables;  // one per SAR approach, in program order
};

class CollectingSink : public PathSink {
 public:
  void element(const PathElement& e) override { result.path.push_back(e); }
  void action(const ActionEvent& a) override { result.actions.push_back(a); }
  void decision(const Decision& d) override { result.decisions.push_back(d); }
  void alarm(const Alarm& a) override { result.alarms.push_back(a); }
  void notice(const Notice& n) override { result.notices.push_back(n); }
  void sar_variables(const SarVariables& v) override { result.variables.push_back(v); }
  RunResult result;
};

}  // namespace cutcom
