// The square root of a number known to be >= 0, taken as 0 when it is exactly 0. CORE's
// floating-point filter may approximate an exact 0 (or a tiny positive) by a negative double and
// then appends a warning to a file "Core_Diagnostics" in the working directory: harmless for the
// result, but a stray file in the user's directory. The exact sign test avoids the common case.
#pragma once

#include <CGAL/number_utils.h>

namespace cutcom::ref {

template <class FT>
FT exact_root(const FT& v) {
  return CGAL::sign(v) == CGAL::ZERO ? FT(0) : CGAL::sqrt(v);
}

}  // namespace cutcom::ref
