// A decimal's units (10^-9 mm, Int128) as a GMP integer, for the exact decisions of core and ref.
// Direct, without a detour through text (the conversion ran once per arc and element).
#pragma once

#include <gmpxx.h>

#include <climits>

#include "cutcom/decimal.hpp"

namespace cutcom {

inline mpz_class to_mpz(Int128 v) {
  static_assert(sizeof(unsigned long) == 8, "GMP's unsigned long holds 64 bits here");
  if (v >= LONG_MIN && v <= LONG_MAX) return mpz_class(static_cast<long>(v));
  __extension__ typedef unsigned __int128 UInt128;
  UInt128 magnitude = v < 0 ? UInt128(0) - static_cast<UInt128>(v) : static_cast<UInt128>(v);
  mpz_class z(static_cast<unsigned long>(magnitude >> 64));
  z <<= 64;
  z += static_cast<unsigned long>(magnitude);
  if (v < 0) z = -z;
  return z;
}

inline mpz_class to_mpz(const Decimal& d) { return to_mpz(d.units()); }

}  // namespace cutcom
