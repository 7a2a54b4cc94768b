// TRC-CD-3 without margins: a box around a piece of the tool-centre path, with double bounds
// certified by the floating-point filter (certified_bounds). Two pieces whose boxes are apart share
// no point, so piece_crossing finds no crossing there, exactly; fast passes over such pieces the
// same way. ref's exact location of the carriers' common points on the pieces was 58 % of a CDON
// run, and most held pieces lie plainly away from a block's entry.
#pragma once

#include <optional>
#include <vector>

#include "bottleneck.hpp"

namespace cutcom::ref {

struct PieceBox {
  double lo[2], hi[2];  // every point of the piece lies strictly inside
  // A segment: around its ends. A circle: around the whole circle. Empty where the filter is not
  // sure of a bound.
  static std::optional<PieceBox> of(const PathPiece& p);
  // Around all `pieces` (empty where one has no box).
  static std::optional<PieceBox> around(const std::vector<PathPiece>& pieces);
  static bool apart(const PieceBox& u, const PieceBox& v) {
    return u.hi[0] <= v.lo[0] || v.hi[0] <= u.lo[0] || u.hi[1] <= v.lo[1] || v.hi[1] <= u.lo[1];
  }
};

}  // namespace cutcom::ref
