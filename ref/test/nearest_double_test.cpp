// PATH-ELEMENT-2: ref's output boundary, the double nearest to an exact value (ties to even),
// against MPFR's correctly rounded conversions, on values where the approximation decides and on
// midpoints between doubles (and a hair beside them), where the exact comparisons decide.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>

#include "kernel.hpp"

namespace cutcom::ref {
namespace {

FT exact(double d) { return FT(d); }  // a double is a dyadic rational: exact in CORE

// The midpoint between d and the next double up, exactly; and of d and that neighbour the one a
// tie rounds to (the even last digit).
FT midpoint_above(double d) { return (exact(d) + exact(std::nextafter(d, HUGE_VAL))) / FT(2); }
double even_of(double d, double above) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1U) == 0 ? d : above;
}

double mpfr_nearest_sqrt(unsigned long n, long halvings) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_sqrt_ui(x, n, MPFR_RNDN);  // correctly rounded; halving is exact in the normal range
  mpfr_div_2si(x, x, halvings, MPFR_RNDN);
  double d = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return d;
}

double mpfr_nearest_ratio(long p, long q) {
  mpq_class r(p, q);
  r.canonicalize();
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, r.get_mpq_t(), MPFR_RNDN);
  double d = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return d;
}

TEST(NearestDouble, RatiosAndRootsRoundAsMpfr) {
  std::mt19937_64 random(20261127);
  for (int i = 0; i < 20000; ++i) {
    long p = static_cast<long>(random() % 2'000'000'000'001) - 1'000'000'000'000;
    long q = static_cast<long>(random() % 999'999'999) + 1;
    EXPECT_EQ(nearest_double(FT(p) / FT(q)), mpfr_nearest_ratio(p, q)) << p << "/" << q;
    unsigned long n = random() % 1'000'000'000'000 + 1;
    long k = static_cast<long>(random() % 40);
    EXPECT_EQ(nearest_double(CGAL::sqrt(FT(static_cast<double>(n))) / FT(std::ldexp(1.0, static_cast<int>(k)))),
              mpfr_nearest_sqrt(n, k))
        << "sqrt(" << n << ") / 2^" << k;
  }
}

TEST(NearestDouble, MidpointsTieToEvenAndAHairBesideThemDoNot) {
  std::mt19937_64 random(1127);
  std::uniform_real_distribution<double> any(-1e4, 1e4);
  for (int i = 0; i < 2000; ++i) {
    double d = any(random), above = std::nextafter(d, HUGE_VAL);
    FT mid = midpoint_above(d);
    EXPECT_EQ(nearest_double(mid), even_of(d, above)) << d;
    FT hair = FT(1) / FT(1e30);
    EXPECT_EQ(nearest_double(mid - hair * FT(std::fabs(d))), d) << d;
    EXPECT_EQ(nearest_double(mid + hair * FT(std::fabs(d))), above) << d;
    // A midpoint reached through square roots: sqrt(mid^2) is mid, exactly.
    EXPECT_EQ(nearest_double(CGAL::sqrt(mid * mid) * FT(d < 0 ? -1 : 1)), nearest_double(mid)) << d;
  }
}

TEST(NearestDouble, ZeroAndExactDoublesStay) {
  EXPECT_EQ(nearest_double(FT(0)), 0.0);
  EXPECT_EQ(nearest_double(CGAL::sqrt(FT(2)) * CGAL::sqrt(FT(2)) - FT(2)), 0.0);
  for (double d : {1.0, -0.1, 123456.789, 1e-9, -4.5e9, DBL_MIN, 0x1.fffffffffffffp+1000})
    EXPECT_EQ(nearest_double(FT(d)), d);
}

// PATH-ELEMENT-2: the output's millimetres, units / 10^9 rounded once, as nearest_double rounds the
// quotient: on roots, ratios and on midpoints between doubles times 10^9 (the interval cannot
// decide there; the exact comparisons do).
TEST(NearestDouble, MillimetresOfUnitsRoundAsTheQuotient) {
  std::mt19937_64 random(20261129);
  for (int i = 0; i < 5000; ++i) {
    long p = static_cast<long>(random() % 2'000'000'000'001) - 1'000'000'000'000;
    long q = static_cast<long>(random() % 999'999) + 1;
    FT ratio = FT(p) / FT(q), root = CGAL::sqrt(FT(static_cast<double>(random() % 1'000'000'000'000 + 1)));
    for (const FT& units : {ratio, root, -root, ratio * root})
      EXPECT_EQ(nearest_mm(units), nearest_double(units / FT(1'000'000'000L))) << p << "/" << q;
  }
  std::uniform_real_distribution<double> any(-1e4, 1e4);
  for (int i = 0; i < 500; ++i) {
    double d = any(random), above = std::nextafter(d, HUGE_VAL);
    EXPECT_EQ(nearest_mm(midpoint_above(d) * FT(1'000'000'000L)), even_of(d, above)) << d;
  }
  EXPECT_EQ(nearest_mm(FT(0)), 0.0);
  EXPECT_EQ(nearest_mm(FT(-1'500'000'000L)), -1.5);
}

}  // namespace
}  // namespace cutcom::ref
