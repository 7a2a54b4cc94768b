// A sink that hands what an engine delivers to another sink running on a second thread: the
// writer formats text or JSON while the reader and the engine go on (issue "Performance": the
// writer took a quarter of a run). Order is kept; memory is bounded (a few batches of events).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <variant>
#include <vector>

#include "cutcom/output.hpp"
#include "cutcom/sink.hpp"

namespace cutcom {

class BackgroundSink : public PathSink {
 public:
  // `decisions`: whether the target wants the decision trace (most runs do not: not copied).
  BackgroundSink(PathSink& target, bool decisions);
  ~BackgroundSink() override;  // finishes; an error of the target is then lost (call finish())
  BackgroundSink(const BackgroundSink&) = delete;
  BackgroundSink& operator=(const BackgroundSink&) = delete;

  void element(const PathElement& e) override;
  void action(const ActionEvent& a) override;
  void decision(const Decision& d) override;
  bool keeps_decisions() const override { return decisions_; }
  void alarm(const Alarm& a) override;
  void notice(const Notice& n) override;
  void sar_variables(const SarVariables& v) override;

  // NC-PARAM-SUB-3: the names of subprogram sources. The reader grows its table while the target
  // writes, so the names are copied on this thread (from `upstream`) and the target reads the copy.
  void set_upstream_sources(SourceNames upstream) { upstream_ = std::move(upstream); }
  SourceNames sources();

  // Everything handed over is written when it returns; an exception of the target is rethrown.
  void finish();
  // The processor time the writer's thread used (cutcom run --stage-times), once finish() returned.
  double writer_cpu_seconds() const { return writer_seconds_; }

 private:
  // A decision's clause and branch are views an engine may build for the call: copied.
  struct OwnedDecision {
    Decision decision;
    std::string clause, branch;
  };
  using Event = std::variant<PathElement, ActionEvent, OwnedDecision, Alarm, Notice, SarVariables>;
  using Batch = std::vector<Event>;
  static constexpr std::size_t kBatch = 4096;
  static constexpr std::size_t kQueued = 2;  // batches waiting at most: the memory bound

  template <class T>
  void push(T&& e);  // one event, of the variant's type T
  void copy_sources(std::uint32_t up_to);
  void hand_over();
  void write();  // the second thread

  PathSink& target_;
  bool decisions_;
  Batch filling_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Batch> full_, empty_;
  bool closing_ = false, failed_ = false;
  std::exception_ptr error_;
  SourceNames upstream_;
  std::mutex names_mutex_;
  std::deque<std::string> names_{""};  // copies of upstream's names (0: none); references stay valid
  std::uint32_t copied_ = 1;
  double writer_seconds_ = 0;  // written by the writer's thread as it ends (the join orders it)
  std::thread writer_;
};

}  // namespace cutcom
