// Decisions are data (spec TRACE-1): every rule decision an engine takes, with its clause, block
// and branch. ref adds the exact margin (how far the deciding quantity was from its threshold);
// fast adds its double estimate of the same quantity.
#pragma once

#include <string>
#include <string_view>

namespace cutcom {

struct Decision {
  std::string_view clause;  // e.g. "TRC-CORNER-1"
  int line = 0;             // source line of the block the decision is about
  std::string_view branch;  // e.g. "outer", "inner", "tangent"
  bool has_margin = false;
  double margin = 0;         // fast: estimate in the clause's margin unit
  std::string margin_exact;  // ref: the exact margin, as a decimal with its sign exact
};

}  // namespace cutcom
