// Collision detection CDON (TRC-CD-*): the compensated path keeps its distance from the contour.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "cutcom/ref/exact_checks.hpp"
#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

// covers: PROP-CD-1 TRC-CD-1 TRC-CD-2 TRC-CD-3 TRC-CD-4
RC_GTEST_PROP(CollisionProperty, CdonPathKeepsTheRadiusFromTheContourOrRaises10751, ()) {
  ContourCase c = *bottleneck();
  std::string text = to_program(c);
  ref::ClearanceCheck check = ref::exact_clearance(text, machine_data_of(c));
  RC_TAG(check.unsupported ? "not supported" : check.alarm ? "alarm" : "clear");
  if (check.alarm || check.unsupported) return;
  RC_TAG(text.find("G42") != std::string::npos ? "G42" : "G41");
  if (!check.violation.empty()) RC_FAIL(check.violation);
  RC_ASSERT(check.pairs > 0);
}

}  // namespace
}  // namespace cutcom::props
