// The writer's second thread (core BackgroundSink): everything arrives, in order, the names of
// subprogram sources as they were, and a failing writer's error reaches the caller.
#include "cutcom/background_sink.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace {

using cutcom::BackgroundSink;

// Records every event as a line of text, the source names read from the sink's copy.
class Recorder : public cutcom::PathSink {
 public:
  void element(const cutcom::PathElement& e) override {
    std::string where = e.origin.source != 0 && names ? " in " + names(e.origin.source) : "";
    lines.push_back("element " + std::to_string(e.origin.line) + where);
  }
  void action(const cutcom::ActionEvent& a) override { lines.push_back("action " + std::to_string(a.line)); }
  void decision(const cutcom::Decision& d) override { lines.push_back("decision " + std::to_string(d.line)); }
  void alarm(const cutcom::Alarm& a) override { lines.push_back("alarm " + std::to_string(a.number)); }
  void notice(const cutcom::Notice& n) override { lines.push_back("notice " + n.text); }
  std::vector<std::string> lines;
  cutcom::SourceNames names;
};

cutcom::PathElement element(int line, std::uint32_t source = 0) {
  cutcom::PathElement e;
  e.origin.line = line;
  e.origin.source = source;
  return e;
}

TEST(BackgroundSink, EverythingArrivesInOrder) {
  Recorder target;
  std::vector<std::string> expected;
  {
    BackgroundSink sink(target, false);
    for (int k = 1; k <= 10000; ++k) {  // several batches
      sink.element(element(k));
      expected.push_back("element " + std::to_string(k));
      if (k % 997 == 0) {
        cutcom::ActionEvent a;
        a.line = k;
        sink.action(a);
        expected.push_back("action " + std::to_string(k));
        sink.decision(cutcom::Decision{"TRC-CORNER-1", k, "outer"});  // not wanted: dropped
      }
    }
    cutcom::Alarm a;
    a.number = 10751;
    sink.alarm(a);
    expected.push_back("alarm 10751");
    sink.finish();
    EXPECT_EQ(target.lines, expected);  // all written when finish() returns
  }
  EXPECT_EQ(target.lines.size(), expected.size());
}

TEST(BackgroundSink, DecisionsWhenWanted) {
  Recorder target;
  BackgroundSink sink(target, true);
  sink.decision(cutcom::Decision{"TRC-CORNER-1", 7, "outer"});
  sink.finish();
  EXPECT_EQ(target.lines, std::vector<std::string>{"decision 7"});
}

// NC-PARAM-SUB-3: the reader's table of names grows while the writer reads; the writer reads the
// copy the sink made when the element was handed over.
TEST(BackgroundSink, SourceNamesAreCopiedWhenHandedOver) {
  Recorder target;
  std::vector<std::string> upstream{""};
  BackgroundSink sink(target, false);
  sink.set_upstream_sources([&upstream](std::uint32_t id) -> const std::string& { return upstream[id]; });
  target.names = sink.sources();
  for (std::uint32_t k = 1; k <= 3000; ++k) {
    upstream.push_back("SUB" + std::to_string(k) + ".SPF line 1");
    sink.element(element(static_cast<int>(k), k));
  }
  sink.finish();
  ASSERT_EQ(target.lines.size(), 3000u);
  EXPECT_EQ(target.lines[0], "element 1 in SUB1.SPF line 1");
  EXPECT_EQ(target.lines[2999], "element 3000 in SUB3000.SPF line 1");
}

class FailingWriter : public cutcom::PathSink {
 public:
  void element(const cutcom::PathElement& e) override {
    if (e.origin.line == 1500) throw std::runtime_error("disk full");
  }
};

TEST(BackgroundSink, AWritersErrorReachesTheCaller) {
  FailingWriter target;
  BackgroundSink sink(target, false);
  for (int k = 1; k <= 20000; ++k) sink.element(element(k));  // never blocks after the failure
  EXPECT_THROW(sink.finish(), std::runtime_error);
}

}  // namespace
