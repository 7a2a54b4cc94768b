// TRACE-1: a sink that keeps no decisions (a run without --trace) gets none, and ref leaves out
// the text of its exact margins; the path, actions and alarms are the same as with every decision
// and margin written.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "cutcom/fast/engine.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

class PathOnly : public CollectingSink {
 public:
  bool keeps_decisions() const override { return false; }
};

RunResult run_ref(const std::string& text, CollectingSink& sink) {
  MachineData md;
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  ref::run(reader, md, sink);
  return sink.result;
}

const char* kProgram =
    "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n"
    "N10 G17 G90 G0 X-20 Y-10 Z0 T1 D1\n"
    "N20 G1 G41 G450 CDON X0 Y0 F500\n"
    "N30 G1 X30 Y0 M8\n"
    "N40 G3 X40 Y10 CR=10\n"
    "N50 G1 X40 Y30 Z-1\n"
    "N60 G3 X30 Y40 I-10 J0\n"
    "N70 G1 X10 Y40\n"
    "N80 G1 X0 Y20 G451\n"
    "N90 G1 X-5 Y25\n"
    "N100 G1 G40 X-20 Y20\n"
    "N110 M30\n";

// A groove narrower than the tool under CDON: the entry of N80 cuts the held output (TRC-CD-3).
const char* kBottleneck =
    "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n"
    "N10 G17 G90 G0 X-10 Y10 Z0 T1 D1\n"
    "N20 G1 G41 G450 CDON X0 Y0 F500\n"
    "N30 G1 X10 Y0\n"
    "N40 G1 X10 Y-10\n"
    "N50 G1 X11 Y-10\n"
    "N60 G1 X11 Y0\n"
    "N70 G1 X20 Y0\n"
    "N80 G3 X30 Y0 CR=5\n"
    "N90 G1 X40 Y0\n"
    "N100 G1 G40 X50 Y-10\n"
    "N110 M30\n";

void expect_same_without_margins(const char* program, std::string_view clause, std::string_view branch) {
  SCOPED_TRACE(program);
  CollectingSink all;
  PathOnly path_only;
  RunResult a = run_ref(program, all), b = run_ref(program, path_only);
  ASSERT_FALSE(a.path.empty());
  ASSERT_EQ(a.path.size(), b.path.size());
  for (std::size_t k = 0; k < a.path.size(); ++k) {
    EXPECT_EQ(a.path[k].start.x, b.path[k].start.x) << k;
    EXPECT_EQ(a.path[k].start.y, b.path[k].start.y) << k;
    EXPECT_EQ(a.path[k].end.x, b.path[k].end.x) << k;
    EXPECT_EQ(a.path[k].end.y, b.path[k].end.y) << k;
    EXPECT_EQ(a.path[k].end.z, b.path[k].end.z) << k;
    EXPECT_EQ(a.path[k].type, b.path[k].type) << k;
  }
  ASSERT_EQ(a.actions.size(), b.actions.size());
  EXPECT_EQ(a.alarms.size(), b.alarms.size());
  // The decisions nobody keeps are not even put out; the run that keeps them has the exact margins.
  EXPECT_TRUE(b.decisions.empty());
  int seen = 0;
  for (std::size_t k = 0; k < a.decisions.size(); ++k) {
    if (a.decisions[k].clause != clause || a.decisions[k].branch != branch) continue;
    ++seen;
    EXPECT_FALSE(a.decisions[k].margin_exact.empty()) << k;
  }
  EXPECT_GE(seen, 1) << clause << " " << branch;
}

// covers: TRACE-1 TRC-CD-3
TEST(TraceMargins, RefLeavesOutMarginsNobodyKeepsAndThePathStays) {
  expect_same_without_margins(kProgram, "TRC-CORNER-1", "outer");
  expect_same_without_margins(kProgram, "TRC-CORNER-1", "inner");
  expect_same_without_margins(kBottleneck, "TRC-CD-3", "cut");
  expect_same_without_margins(kBottleneck, "TRC-CD-3", "none");
}

RunResult run_fast(const std::string& text, const MachineData& md, CollectingSink& sink) {
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  fast::run(reader, md, sink);
  return sink.result;
}

// covers: TRACE-1 TRC-CORNER-3 TRC-CORNER-4
// fast untraced tells a corner's side of MD20210 / MD20230 by its cosine where it is far from the
// limit (no atan2): the same path as the traced run, which takes the angle, at contour angles on,
// a hair off and far from each limit, turning either way, under G450 and G451.
TEST(TraceMargins, FastUntracedTakesTheCornerLimitsAsTraced) {
  MachineData md;
  md.cutcom_corner_limit = *Decimal::parse("100").value;
  md.cutcom_curve_insert_limit = *Decimal::parse("10").value;
  int compared = 0;
  for (double angle : {9.9999999, 10.0, 10.0000001, 9.99, 10.01, 45.0, 99.9999999, 100.0, 100.0000001, 150.0, 179.9})
    for (int turn : {1, -1})
      for (const char* mode : {"G450", "G451"}) {
        double a = turn * angle * std::numbers::pi / 180;
        std::string text = fmt::format(
            "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G17 G90 G0 X-20 Y5 T1 D1\nN20 G1 G41 {} X0 Y0 F500\n"
            "N30 X20\nN40 X{:.9f} Y{:.9f}\nN50 G40 X{:.9f} Y{:.9f}\nM30\n",
            mode, 20 + 30 * std::cos(a), 30 * std::sin(a), 20 + 60 * std::cos(a), 60 * std::sin(a) + 20);
        SCOPED_TRACE(text);
        CollectingSink all;
        PathOnly path_only;
        RunResult r = run_fast(text, md, all), p = run_fast(text, md, path_only);
        ASSERT_EQ(r.path.size(), p.path.size());
        for (std::size_t k = 0; k < r.path.size(); ++k) {
          EXPECT_EQ(r.path[k].type, p.path[k].type) << k;
          EXPECT_EQ(r.path[k].end.x, p.path[k].end.x) << k;
          EXPECT_EQ(r.path[k].end.y, p.path[k].end.y) << k;
        }
        EXPECT_EQ(r.alarms.size(), p.alarms.size());
        EXPECT_TRUE(p.decisions.empty());
        compared += has_decision(r, "TRC-CORNER-3", "switch-to-G450") || has_decision(r, "TRC-CORNER-3", "keep-G451") ||
                    has_decision(r, "TRC-CORNER-4", "keep-G450") || has_decision(r, "TRC-CORNER-4", "switch-to-G451");
      }
  EXPECT_GE(compared, 20);  // most corners are outer ones that meet a limit
}

}  // namespace
}  // namespace cutcom::test
