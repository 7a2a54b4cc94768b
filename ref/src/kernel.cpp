#include "kernel.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace cutcom::ref {

mpz_class units_of(const Decimal& d) { return mpz_class(int128_to_string(d.units())); }

FT leaf(const Decimal& d) {
  Int128 u = d.units();
  if (u >= LONG_MIN && u <= LONG_MAX) return FT(static_cast<long>(u));
  return FT(CORE::BigInt(units_of(d).get_mpz_t()));
}

Point plane_point(const Point3& p, PlaneAxes axes) {
  return Point(leaf(coord(p, axes.abscissa)), leaf(coord(p, axes.ordinate)));
}

std::string exact_text(const FT& value) {
  if (CGAL::sign(value) == CGAL::ZERO) return "0";
  // The sign is exact (CORE); the digits are the nearest double's 17 (output boundary). Not
  // Expr::toString: after exact zero tests an approximation may hold thousands of bits, and
  // printing all of them dominated ref's run time.
  auto magnitude = std::fabs(CGAL::to_double(value));
  return fmt::format("{}{:.17g}", CGAL::sign(value) == CGAL::NEGATIVE ? "-" : "", magnitude);
}

std::string exact_mm(const FT& units) { return exact_text(units / FT(1'000'000'000L)); }

}  // namespace cutcom::ref
