// TRC-CORNER-1 and TRC-KONT-1 exactly at CR= circles. A CR= circle's centre carries a square root
// (ARC-CR-1), so its tangent is p + √Q·r with integer vectors p, r and an integer Q ≥ 0:
//   start: σ(k√Q d − L perp d),  end: σ(k√Q d + L perp d),  L = |d|², Q = L·max(0, 4CR² − L)
// (σ·perp(P − c) times 2L, k the side of the centre, d the chord in units of 1e-9 mm). The sign of
// a cross or dot product of two such tangents is a + b√x + c√y + e√(xy), decided by squaring.
// fast asks only where its double sine is too small to be sure of (a corner at a CR= circle
// within a few thousand roundings of tangent); the GMP numbers are kept between calls, so once
// they have grown a decision allocates nothing. Private to fast.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>

#include "block_copy.hpp"

namespace cutcom::fast {

class RootTangents {
 public:
  struct Signs {
    int cross = 0, dot = 0;  // of the first block's end tangent with the second's start tangent
  };
  // Both tangents exact (lines, circles with a centre, CR= circles, whatever their size): the
  // signs of their cross and dot products. Empty where a block's points are not its decimals.
  std::optional<Signs> corner(const BlockCopy& first, const BlockCopy& second, PlaneAxes axes);
  // The sign of t × u, t the tangent of `block` at its start (or end), u an integer vector.
  std::optional<int> side(const BlockCopy& block, bool at_end, PlaneAxes axes, const std::array<Int128, 3>& u);

  // sign(a + b√x), x ≥ 0.
  int sign_of(const mpz_class& a, const mpz_class& b, const mpz_class& x);
  // sign(a + b√x + c√y + e√(xy)), x, y ≥ 0.
  int sign_of(const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& e, const mpz_class& x,
              const mpz_class& y);

 private:
  struct Tangent {
    std::array<mpz_class, 2> p, r;  // p + √q·r
    mpz_class q;
  };
  bool tangent_of(const BlockCopy& c, PlaneAxes axes, bool at_end, Tangent& t);

  Tangent first_, second_;
  mpz_class d0_, d1_, k0_, k1_, length2_, n_;  // tangent_of's
  mpz_class a_, b_, c_, e_;                    // the terms of a product
  mpz_class s_, t_, u_, v_;                    // sign_of's
};

}  // namespace cutcom::fast
