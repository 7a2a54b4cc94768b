// ref: the reference TRC engine in exact arithmetic (CORE::Expr through CGAL's sqrt kernel,
// GMP and MPFR for predicates). Literal, readable, never rounding; slow by design. This header
// is CGAL-free so that the CLI, tests and props can include it; the exact checks the properties
// use are in exact_checks.hpp.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cutcom/block_source.hpp"
#include "cutcom/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::ref {

// Results of the exact self-checks on ref's own path (PROP-EXACT-*), computed before rounding.
struct ExactCheckReport {
  int offset_endpoints_checked = 0;  // TRC-EQ-1: each offset end point at signed distance s r
  int circles_checked = 0;           // TRC-G450-1: centre = programmed corner, radius = r
  int joints_checked = 0;            // PATH-CONT-1: each element starts where the previous ended
  std::vector<std::string> failures;
};

// Reads the program block by block and runs it. Returns false if an alarm stopped it.
// With `checks`, also verifies the exact path (costs exact zero tests: milliseconds each).
bool run(BlockSource& blocks, const MachineData& md, PathSink& sink, ExactCheckReport* checks = nullptr);

}  // namespace cutcom::ref
