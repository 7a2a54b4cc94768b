// Test support: run a program text through both engines and compare with hand-derived paths.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cutcom/fast/engine.hpp"
#include "cutcom/ref/engine.hpp"

namespace cutcom::test {

struct Runs {
  RunResult fast, ref;
  bool fast_ok = false, ref_ok = false;
};

inline RunResult run_engine(const std::string& engine, const std::string& text, const MachineData& md, bool* ok) {
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  CollectingSink sink;
  *ok = engine == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink);
  return sink.result;
}

inline Runs run_both(const std::string& text, const MachineData& md = {}) {
  Runs r;
  r.fast = run_engine("fast", text, md, &r.fast_ok);
  r.ref = run_engine("ref", text, md, &r.ref_ok);
  return r;
}

// An expected element, derived by hand.
struct Expect {
  OriginKind kind;
  PathPoint start, end;
  PathPoint center{};
  bool arc = false;
  bool ccw = false;
};

inline Expect line(OriginKind k, PathPoint s, PathPoint e) { return {k, s, e}; }
inline Expect arc(PathPoint s, PathPoint e, PathPoint c, bool ccw) {
  return {OriginKind::kTransitionCircle, s, e, c, true, ccw};
}

inline void expect_point(const PathPoint& got, const PathPoint& want, const std::string& what) {
  constexpr double kTol = 1e-9;  // mm: hand values are exact; both engines round once or twice
  EXPECT_NEAR(got.x, want.x, kTol) << what;
  EXPECT_NEAR(got.y, want.y, kTol) << what;
  EXPECT_NEAR(got.z, want.z, kTol) << what;
}

inline void expect_path(const RunResult& r, const std::vector<Expect>& want, const std::string& engine) {
  ASSERT_EQ(r.path.size(), want.size()) << engine << ": number of path elements";
  for (std::size_t i = 0; i < want.size(); ++i) {
    const PathElement& e = r.path[i];
    std::string what = engine + " element " + std::to_string(i) + " (" + describe(e.origin) + ")";
    EXPECT_EQ(e.origin.kind, want[i].kind) << what;
    EXPECT_EQ(e.type == ElementType::kArc, want[i].arc) << what;
    expect_point(e.start, want[i].start, what + " start");
    expect_point(e.end, want[i].end, what + " end");
    if (want[i].arc) {
      expect_point(e.center, want[i].center, what + " centre");
      EXPECT_EQ(e.ccw, want[i].ccw) << what;
    }
  }
}

// Both engines give the hand-derived path.
inline void expect_both(const Runs& r, const std::vector<Expect>& want) {
  expect_path(r.fast, want, "fast");
  expect_path(r.ref, want, "ref");
}

// Both engines reject the program as not supported (TRC-UNSUP-1), naming line `line_no`.
inline void expect_not_supported(const std::string& text, int line_no) {
  for (const char* engine : {"fast", "ref"}) {
    bool ok = false;
    try {
      run_engine(engine, text, {}, &ok);
      ADD_FAILURE() << engine << " accepted:\n" << text;
    } catch (const UnsupportedError& e) {
      EXPECT_EQ(e.line(), line_no) << engine << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("not supported"), std::string::npos);
    }
  }
}

inline bool has_decision(const RunResult& r, std::string_view clause, std::string_view branch) {
  for (const auto& d : r.decisions)
    if (d.clause == clause && d.branch == branch) return true;
  return false;
}

}  // namespace cutcom::test
