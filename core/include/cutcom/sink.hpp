// Where an engine delivers its results, in program order. Engines stream into a sink; the
// collecting sink keeps everything (tests, properties, SVG).
#pragma once

#include <vector>

#include "cutcom/alarm.hpp"
#include "cutcom/path.hpp"
#include "cutcom/trace.hpp"

namespace cutcom {

class PathSink {
 public:
  virtual ~PathSink() = default;
  virtual void element(const PathElement& e) = 0;
  virtual void action(const ActionEvent&) {}
  virtual void decision(const Decision&) {}
  virtual void alarm(const Alarm&) {}
  virtual void notice(const Notice&) {}
};

struct RunResult {
  std::vector<PathElement> path;
  std::vector<ActionEvent> actions;
  std::vector<Decision> decisions;
  std::vector<Alarm> alarms;
  std::vector<Notice> notices;
};

class CollectingSink : public PathSink {
 public:
  void element(const PathElement& e) override { result.path.push_back(e); }
  void action(const ActionEvent& a) override { result.actions.push_back(a); }
  void decision(const Decision& d) override { result.decisions.push_back(d); }
  void alarm(const Alarm& a) override { result.alarms.push_back(a); }
  void notice(const Notice& n) override { result.notices.push_back(n); }
  RunResult result;
};

}  // namespace cutcom
