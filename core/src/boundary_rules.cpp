#include "cutcom/boundary_rules.hpp"

#include <array>

namespace cutcom {

namespace {
using enum MarginRequires;
// clause, branch, the margin's sign it stands for; grouped as in the spec.
constexpr std::array kRules{
    // arcs.md
    BoundaryRule{"ARC-CENTRE-2", "within", kNonPositive},  // exactly the tolerance is within
    BoundaryRule{"ARC-CENTRE-2", "beyond", kPositive},
    BoundaryRule{"ARC-CR-1", "circle", kNonNegative},  // a chord of exactly 2|CR| is a circle
    BoundaryRule{"TRC-ARC-EQ-1", "concentric", kPositive},
    BoundaryRule{"TRC-ARC-EQ-1", "collapses", kNonPositive},         // radius 0 collapses
    BoundaryRule{"TRC-ARC-CORNER-1", "intersection", kNonPositive},  // carriers that touch meet
    BoundaryRule{"TRC-ARC-CORNER-1", "none", kPositive},
    BoundaryRule{"TRC-ARC-ELEMENT-1", "fits", kPositive},
    BoundaryRule{"TRC-ARC-ELEMENT-1", "vanishes", kZero},
    BoundaryRule{"TRC-ARC-ELEMENT-1", "reverses", kNegative},
    // trc-lines.md
    BoundaryRule{"TRC-ELEMENT-1", "fits", kPositive},
    BoundaryRule{"TRC-ELEMENT-1", "vanishes", kZero},  // a zero-length equidistant never reverses
    BoundaryRule{"TRC-ELEMENT-1", "reverses", kNegative},
    BoundaryRule{"TRC-CORNER-1", "inner", kPositive},  // margin s·c/(|d1||d2|): the signed sine
    BoundaryRule{"TRC-CORNER-1", "outer", kNegative},
    BoundaryRule{"TRC-CORNER-1", "tangent", kZero},
    BoundaryRule{"TRC-CORNER-1", "reversal", kZero},
    BoundaryRule{"TRC-CORNER-3", "switch-to-G450", kPositive},  // equal to MD20210 is not greater
    BoundaryRule{"TRC-CORNER-3", "keep-G451", kNonPositive},
    BoundaryRule{"TRC-CORNER-4", "keep-G450", kNonNegative},  // equal to MD20230 is not less
    BoundaryRule{"TRC-CORNER-4", "switch-to-G451", kNegative},
    BoundaryRule{"TRC-LOOK-1", "reaches", kNonNegative},  // the intersection at the normal end reaches
    BoundaryRule{"TRC-LOOK-1", "too-short", kNegative},
    BoundaryRule{"TRC-LOOK-2", "intersection", kNonNegative},  // an intersection at the equidistant's start is valid
    BoundaryRule{"TRC-LOOK-2", "none", kNegative},
    BoundaryRule{"TRC-LOOK-4", "first", kPositive},  // the first point nearer
    BoundaryRule{"TRC-LOOK-4", "second", kNegative},
    BoundaryRule{"TRC-LOOK-4", "tie", kZero},  // equally near (or one point): the one further along
    BoundaryRule{"TRC-APPR-NORM-1", "line", kPositive},
    BoundaryRule{"TRC-APPR-NORM-1", "zero-length", kZero},
    BoundaryRule{"TRC-RETR-NORM-1", "line", kPositive},
    BoundaryRule{"TRC-RETR-NORM-1", "zero-length", kZero},
    // approach-retraction.md
    BoundaryRule{"TRC-KONT-1", "in-front", kNonNegative},  // on the tangent line counts as in front
    BoundaryRule{"TRC-KONT-1", "behind", kNegative},
    BoundaryRule{"TRC-KONT-2", "room", kNonNegative},  // on the circle of radius r leaves room
    BoundaryRule{"TRC-KONT-2", "inside", kNegative},
    BoundaryRule{"TRC-CD-2", "inner", kPositive},  // the corner kind at a collision entry, as TRC-CORNER-1
    BoundaryRule{"TRC-CD-2", "outer", kNegative},
    BoundaryRule{"TRC-CD-2", "tangent", kZero},
    BoundaryRule{"TRC-CD-2", "reversal", kZero},
    BoundaryRule{"TRC-CD-2", "collapsed", kNonPositive},
    BoundaryRule{"TRC-CD-2", "entry", kNonNegative},       // (no-entry: a negative extent or carriers that miss)
    BoundaryRule{"TRC-CD-2", "g451-meets", kNonPositive},  // the carriers' gap, as TRC-ARC-CORNER-1
    BoundaryRule{"TRC-CD-2", "g451-misses", kPositive},
    BoundaryRule{"TRC-CD-3", "cut", kNonNegative},  // a point on both pieces, ends included, is a crossing
    BoundaryRule{"TRC-CD-3", "none", kNegative},
    BoundaryRule{"TRC-CD-3", "overlap", kZero},  // collinear pieces that overlap: no crossing, the knife edge
    BoundaryRule{"TRC-CD-5", "earlier-block", kNonNegative},
    BoundaryRule{"TRC-CD-5", "open-element", kNonPositive},  // (0: collinear pieces)
    BoundaryRule{"TRC-CD-6", "later-block", kNonNegative},
    BoundaryRule{"TRC-CD-6", "none", kNegative},
    BoundaryRule{"TRC-EDGE-5", "hit", kNonNegative},  // a hit exactly at an end of the curve or piece is a hit
    BoundaryRule{"TRC-EDGE-5", "none", kNegative},
    BoundaryRule{"TRC-EDGE-6", "circle", kNonNegative},
    BoundaryRule{"TRC-EDGE-6", "line", kNegative},
    // sar.md
    BoundaryRule{"SAR-SIDE-2", "left", kPositive},
    BoundaryRule{"SAR-SIDE-2", "right", kNegative},
    BoundaryRule{"SAR-SIDE-2", "on-tangent", kZero},
    BoundaryRule{"SAR-DISR-1", "valid", kPositive},
    BoundaryRule{"SAR-DISR-1", "not-positive", kNonPositive},  // L = 0 exactly is not positive
    BoundaryRule{"SAR-DISR-2", "valid", kPositive},
    BoundaryRule{"SAR-DISR-2", "not-positive", kNonPositive},
    BoundaryRule{"SAR-DISCL-3", "between", kNonNegative},
    BoundaryRule{"SAR-DISCL-3", "clamped", kNonNegative},  // exactly MD20204 outside is clamped
    BoundaryRule{"SAR-DISCL-3", "reversal", kNegative},
    BoundaryRule{"SAR-SUB-1", "lead", kPositive},
    BoundaryRule{"SAR-SUB-1", "no-lead", kZero},
};
}  // namespace

std::span<const BoundaryRule> boundary_rules() { return kRules; }

const BoundaryRule* boundary_rule(std::string_view clause, std::string_view branch) {
  for (const BoundaryRule& r : kRules)
    if (r.clause == clause && r.branch == branch) return &r;
  return nullptr;
}

bool satisfies(MarginRequires r, int sign) {
  switch (r) {
    case kPositive:
      return sign > 0;
    case kNonNegative:
      return sign >= 0;
    case kZero:
      return sign == 0;
    case kNonPositive:
      return sign <= 0;
    case kNegative:
      return sign < 0;
  }
  return false;
}

std::string_view requirement_text(MarginRequires r) {
  switch (r) {
    case kPositive:
      return "> 0";
    case kNonNegative:
      return ">= 0";
    case kZero:
      return "= 0";
    case kNonPositive:
      return "<= 0";
    case kNegative:
      return "< 0";
  }
  return "?";
}

}  // namespace cutcom
