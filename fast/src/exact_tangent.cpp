#include "exact_tangent.hpp"

namespace cutcom::fast {

namespace {
__extension__ typedef unsigned __int128 U128;

struct U256 {
  U128 high = 0, low = 0;
};

U128 magnitude(Int128 v) { return v < 0 ? U128(0) - static_cast<U128>(v) : static_cast<U128>(v); }

// |x|·|y| in 256 bits, from four 64-bit partial products.
U256 product(U128 x, U128 y) {
  const U128 mask = ~std::uint64_t{0};
  U128 x0 = x & mask, x1 = x >> 64, y0 = y & mask, y1 = y >> 64;
  U128 low = x0 * y0, mid1 = x0 * y1, mid2 = x1 * y0, high = x1 * y1;
  U128 mid = (low >> 64) + (mid1 & mask) + (mid2 & mask);  // at most 3·(2^64 − 1): no overflow
  U256 r;
  r.low = (low & mask) | (mid << 64);
  r.high = high + (mid1 >> 64) + (mid2 >> 64) + (mid >> 64);
  return r;
}

int compare(const U256& x, const U256& y) {
  if (x.high != y.high) return x.high < y.high ? -1 : 1;
  if (x.low != y.low) return x.low < y.low ? -1 : 1;
  return 0;
}

int sign(Int128 v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

bool below(Int128 v, int bits) {
  const Int128 limit = Int128(1) << bits;
  return v < limit && v > -limit;
}
}  // namespace

int sign_of_difference(Int128 p, Int128 q, Int128 r, Int128 t) {
  if (below(p, 62) && below(q, 62) && below(r, 62) && below(t, 62)) {  // each product below 2^124
    Int128 d = p * q - r * t;
    return (d > 0) - (d < 0);
  }
  int s1 = sign(p) * sign(q), s2 = sign(r) * sign(t);  // signs of p·q and r·t
  if (s1 != s2) return s1 > s2 ? 1 : -1;               // (covers either product being 0)
  if (s1 == 0) return 0;
  int c = compare(product(magnitude(p), magnitude(q)), product(magnitude(r), magnitude(t)));
  return s1 > 0 ? c : -c;
}

std::optional<IntVec> exact_tangent(const BlockCopy& c, PlaneAxes axes, bool at_end) {
  if (!c.exact) return std::nullopt;
  const auto ia = static_cast<std::size_t>(axes.abscissa), io = static_cast<std::size_t>(axes.ordinate);
  IntVec d{c.delta[ia], c.delta[io]};
  if (!c.arc) {  // a line: its displacement (TRC-CORNER-1 between straight blocks: below 2^62)
    if (!in_exact_range(d.a) || !in_exact_range(d.b)) return std::nullopt;
    return d;
  }
  if (!c.has_centre) return std::nullopt;      // CR=: the centre is irrational (ref decides it with roots)
  IntVec k{c.to_centre[ia], c.to_centre[io]};  // c − start
  for (Int128 v : {d.a, d.b, k.a, k.b})
    if (!below(v, 40)) return std::nullopt;
  const Int128 sigma = c.sense;
  if (d.a == 0 && d.b == 0) return IntVec{sigma * k.b, -sigma * k.a};  // σ·perp(start − c)
  // Below 2^40 each: n and |d|² below 2^82, each component below 2^124.
  const Int128 n = -k.a * d.b + k.b * d.a, length2 = d.a * d.a + d.b * d.b;
  const Int128 along = 2 * n, across = at_end ? length2 : -length2;  // 2n·d ± |d|²·perp d
  return IntVec{sigma * (along * d.a - across * d.b), sigma * (along * d.b + across * d.a)};
}

std::optional<LineProducts> line_products(const std::array<Int128, 3>& t, const std::array<Int128, 3>& u,
                                          PlaneAxes axes) {
  const auto ia = static_cast<std::size_t>(axes.abscissa), io = static_cast<std::size_t>(axes.ordinate);
  const Int128 a1 = t[ia], b1 = t[io], a2 = u[ia], b2 = u[io];
  if (!in_exact_range(a1) || !in_exact_range(b1) || !in_exact_range(a2) || !in_exact_range(b2)) return std::nullopt;
  auto wide = [](Int128 x, Int128 y) {  // both below 2^62: one widening multiply
    return static_cast<Int128>(static_cast<std::int64_t>(x)) * static_cast<std::int64_t>(y);
  };
  return LineProducts{wide(a1, b2) - wide(b1, a2), wide(a1, a2) + wide(b1, b2)};  // below 2^125
}

bool CornerSignsMemo::signs(const BlockCopy& first, const BlockCopy& second, PlaneAxes axes, int& cross, int& dot) {
  if (!first.exact || !second.exact) return false;  // exact_tangent's first test
  if (first.block != first_ || second.block != second_ || first.seq != first_seq_ || second.seq != second_seq_ ||
      axes.abscissa != abscissa_ || axes.ordinate != ordinate_) {
    first_ = first.block, second_ = second.block, first_seq_ = first.seq, second_seq_ = second.seq;
    abscissa_ = axes.abscissa, ordinate_ = axes.ordinate;
    if (!first.arc && !second.arc) {  // two lines (a CAM program's collinear runs): 128 bits suffice
      std::optional<LineProducts> p = line_products(first.delta, second.delta, axes);
      found_ = p.has_value();
      if (found_) cross_ = (p->cross > 0) - (p->cross < 0), dot_ = (p->dot > 0) - (p->dot < 0);
    } else {
      std::optional<IntVec> t1 = exact_tangent(first, axes, true), t2 = exact_tangent(second, axes, false);
      found_ = t1 && t2;
      if (found_) {
        cross_ = sign_of_difference(t1->a, t2->b, t1->b, t2->a);
        dot_ = sign_of_difference(t1->a, t2->a, -t1->b, t2->b);
      }
    }
  }
  if (found_) cross = cross_, dot = dot_;
  return found_;
}

}  // namespace cutcom::fast
