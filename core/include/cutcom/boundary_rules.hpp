// The boundary rule of every traced decision with a margin (PROP-BOUNDARY-1): which sign of its
// margin each branch stands for, so that the branch the exact threshold takes is data, and each
// engine's branch can be checked against its own margin. The rules restate the clauses' text
// (their "Boundary rule" and "Trace" paragraphs); a branch without a rule here is not checked.
#pragma once

#include <span>
#include <string_view>

namespace cutcom {

// The margin a branch requires: > 0, ≥ 0, = 0, ≤ 0, < 0.
enum class MarginRequires { kPositive, kNonNegative, kZero, kNonPositive, kNegative };

struct BoundaryRule {
  std::string_view clause;
  std::string_view branch;
  MarginRequires margin;
};

std::span<const BoundaryRule> boundary_rules();
const BoundaryRule* boundary_rule(std::string_view clause, std::string_view branch);
// `sign`: -1, 0 or +1.
bool satisfies(MarginRequires r, int sign);
std::string_view requirement_text(MarginRequires r);  // "> 0", "≥ 0" …

}  // namespace cutcom
