#include "piece_box.hpp"

#include <algorithm>
#include <cmath>

#include "filtered.hpp"

namespace cutcom::ref {

namespace {
PieceBox join(const PieceBox& u, const PieceBox& v) {
  return {{std::min(u.lo[0], v.lo[0]), std::min(u.lo[1], v.lo[1])},
          {std::max(u.hi[0], v.hi[0]), std::max(u.hi[1], v.hi[1])}};
}

std::optional<PieceBox> around_point(const Point& p) {
  std::optional<CertifiedBounds> x = certified_bounds(p.x()), y = certified_bounds(p.y());
  if (!x || !y) return std::nullopt;
  return PieceBox{{x->lo, y->lo}, {x->hi, y->hi}};
}
}  // namespace

std::optional<PieceBox> PieceBox::of(const PathPiece& p) {
  if (!p.arc) {
    std::optional<PieceBox> a = around_point(p.a), b = around_point(p.b);
    if (!a || !b) return std::nullopt;
    return join(*a, *b);
  }
  std::optional<PieceBox> c = around_point(p.centre);
  std::optional<CertifiedBounds> r = certified_bounds(p.radius);
  if (!c || !r) return std::nullopt;
  // Sums rounded to nearest may fall short of the exact sum by half an ulp: one step outward.
  auto down = [](double x) { return std::nextafter(x, -HUGE_VAL); };
  auto up = [](double x) { return std::nextafter(x, HUGE_VAL); };
  double radius = std::fabs(r->lo) > std::fabs(r->hi) ? std::fabs(r->lo) : std::fabs(r->hi);
  return PieceBox{{down(c->lo[0] - radius), down(c->lo[1] - radius)}, {up(c->hi[0] + radius), up(c->hi[1] + radius)}};
}

std::optional<PieceBox> PieceBox::around(const std::vector<PathPiece>& pieces) {
  std::optional<PieceBox> out;
  for (const PathPiece& p : pieces) {
    std::optional<PieceBox> b = of(p);
    if (!b) return std::nullopt;
    out = out ? join(*out, *b) : *b;
  }
  return out;
}

}  // namespace cutcom::ref
