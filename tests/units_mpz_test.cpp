// to_mpz (core/include/cutcom/units_mpz.hpp): the GMP integer of Int128 units is the one their
// decimal text gives, in and beyond the range of long and at Int128's ends.
#include "cutcom/units_mpz.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using cutcom::Int128;
__extension__ typedef unsigned __int128 UInt128;

void expect_same(Int128 v) {
  EXPECT_EQ(cutcom::to_mpz(v), mpz_class(cutcom::int128_to_string(v))) << cutcom::int128_to_string(v);
}

TEST(UnitsMpz, EqualsTheDecimalText) {
  Int128 one = 1, max = ~(one << 127), min = -max - 1;
  for (Int128 v : {Int128(0), Int128(1), Int128(-1), Int128(LONG_MAX), Int128(LONG_MIN), Int128(LONG_MAX) + 1,
                   Int128(LONG_MIN) - 1, one << 64, -(one << 64), (one << 64) - 1, max, min, max - 1, min + 1,
                   cutcom::Decimal::kMaxUnits, -cutcom::Decimal::kMaxUnits})
    expect_same(v);
  std::mt19937_64 rng(20261130);
  for (int i = 0; i < 10000; ++i) {
    Int128 v = static_cast<Int128>((static_cast<UInt128>(rng()) << 64) | rng());
    expect_same(v >> (i % 127));  // every magnitude from 2^127 down
  }
}

TEST(UnitsMpz, OfADecimalIsItsUnits) {
  EXPECT_EQ(cutcom::to_mpz(cutcom::Decimal::from_int(-7)), mpz_class(-7'000'000'000L));
}

}  // namespace
