// PROP-PARAM-1: a generated contour written as a parametric program (every coordinate an
// expression of variables, the contour inside an IF and a FOR loop that runs once, a mirrored
// copy of a value through an array) gives exactly the plain program's path, decisions and
// alarms, in each engine. The interpreter's arithmetic and the grid rule (NC-PARAM-GRID-1) are
// certified on every generator's programs.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

void expect_same(const RunResult& a, const RunResult& b, const char* engine) {
  RC_ASSERT(a.path.size() == b.path.size());
  RC_ASSERT(a.alarms.size() == b.alarms.size());
  for (std::size_t i = 0; i < a.alarms.size(); ++i) RC_ASSERT(a.alarms[i].number == b.alarms[i].number);
  for (std::size_t i = 0; i < a.path.size(); ++i) {
    const PathElement &x = a.path[i], &y = b.path[i];
    RC_ASSERT(x.type == y.type);
    RC_ASSERT(x.origin.kind == y.origin.kind);
    RC_ASSERT(x.ccw == y.ccw);
    for (auto [p, q] : {std::pair{x.start, y.start}, {x.end, y.end}, {x.center, y.center}})
      if (!(p.x == q.x && p.y == q.y && p.z == q.z))
        RC_FAIL(std::string(engine) + ": element " + std::to_string(i) + " differs");
  }
  RC_ASSERT(a.decisions.size() == b.decisions.size());
  for (std::size_t i = 0; i < a.decisions.size(); ++i) {
    RC_ASSERT(a.decisions[i].clause == b.decisions[i].clause);
    RC_ASSERT(a.decisions[i].branch == b.decisions[i].branch);
  }
}

// covers: PROP-PARAM-1 NC-PARAM-GRID-1 NC-PARAM-FLOW-2 NC-PARAM-FLOW-4 NC-PARAM-VAR-2
RC_GTEST_PROP(ParametricProperty, ParametricProgramGivesThePlainPath, ()) {
  ContourCase c = *any_contour();
  std::string plain = to_program(c);
  std::string param = to_parametric_program(plain);
  RC_TAG(param.size() > plain.size() ? "rewritten" : "unchanged");
  MachineData md = machine_data_of(c);
  CaseRuns p = run_program(plain, md, false), q = run_program(param, md, false);
  RC_ASSERT(p.fast_unsupported == 0 || q.fast_unsupported != 0);
  expect_same(p.fast, q.fast, "fast");
  expect_same(p.ref, q.ref, "ref");
}

}  // namespace
}  // namespace cutcom::props
