// Exact properties of ref's own path, decided before rounding (PROP-EXACT-*).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

// covers: PROP-EXACT-1 PROP-EXACT-2 PROP-EXACT-3 TRC-EQ-1 TRC-G450-1 PATH-CONT-1
RC_GTEST_PROP(ExactReference, OffsetsLieAtTheRadiusCirclesAboutTheCornerPathContinuous, ()) {
  ContourCase c = *any_contour();
  RC_TAG(c.style);
  CaseRuns r = run_case(c, true);
  if (r.ref_unsupported) return;  // TRC-UNSUP-1: rejected, nothing to check
  if (!r.exact.failures.empty()) RC_FAIL(r.exact.failures.front());
  RC_ASSERT(r.exact.joints_checked + 1 >= static_cast<int>(r.ref.path.size()));
}

}  // namespace
}  // namespace cutcom::props
