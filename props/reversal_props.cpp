// PROP-META-6: approach and retraction are mirror images. Running a contour backwards (the side
// swapped, start and end positions swapped, NORM/KONT and G450/G451 of the selection and
// deselection blocks swapped) turns its approach into the retraction and back, exactly in ref.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "cutcom/ref/exact_checks.hpp"
#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

// covers: PROP-META-6 TRC-KONT-1 TRC-KONT-3 TRC-KONT-4 TRC-APPR-NORM-1 TRC-RETR-NORM-1
RC_GTEST_PROP(Metamorphic, ReversingTheContourSwapsApproachAndRetraction, ()) {
  ContourCase c = *around_ends();
  for (Step& s : c.steps) s.dummies = 0, s.flip = s.again = false;  // one selection, one deselection
  c.plane_only = true;
  RC_TAG(c.style);
  // A full circle next to a too-short end block is measured from its normal start on approach
  // (its end is not known yet) and from the open element's start on retraction: the two may pick
  // different intersections (TRC-EDGE-5). Not a mirror case.
  std::size_t n = c.steps.size();
  for (std::size_t i = 0; i < n; ++i)
    if ((i < 2 || i + 2 >= n) && c.steps[i].arc && c.steps[i].dx == 0 && c.steps[i].dy == 0) {
      RC_TAG("full circle at an end");
      return;
    }
  int deselection_line = 5 + static_cast<int>(c.steps.size());  // $TC lines, N10, N20, the steps
  std::optional<std::string> why;
  try {
    why = ref::exact_reversal_mismatch(to_program(c), to_program(reversed_contour(c)), machine_data_of(c), 4,
                                       deselection_line);
  } catch (const UnsupportedError&) {  // TRC-UNSUP-1: not comparable
    RC_TAG("not supported");
    return;
  }
  RC_TAG(why ? "compared" : "alarm");
  if (why && !why->empty()) RC_FAIL(*why + "\nreversed program:\n" + to_program(reversed_contour(c)));
}

}  // namespace
}  // namespace cutcom::props
