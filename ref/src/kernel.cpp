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

namespace {
// Units (10^-9 mm) to millimetres, rounded once to the nearest output value.
auto output_mm(const FT& units) { return CGAL::to_double(units / FT(1'000'000'000L)); }
}  // namespace

PathPoint to_output(const Point& p, const Decimal& applicate, PlaneAxes axes) {
  PathPoint out;
  auto set = [&](int axis, auto v) { (axis == 0 ? out.x : axis == 1 ? out.y : out.z) = v; };
  set(axes.abscissa, output_mm(p.x()));
  set(axes.ordinate, output_mm(p.y()));
  set(axes.applicate, applicate.to_double());  // output: exact decimal, correctly rounded
  return out;
}

PathPoint to_output(const Point3& p) { return {p.x.to_double(), p.y.to_double(), p.z.to_double()}; }

std::string exact_text(const FT& value) {
  if (CGAL::sign(value) == CGAL::ZERO) return "0";
  // The sign is exact (CORE); the digits are the nearest double's 17 (output boundary). Not
  // Expr::toString: after exact zero tests an approximation may hold thousands of bits, and
  // printing all of them dominated ref's run time.
  auto magnitude = std::fabs(CGAL::to_double(value));
  return fmt::format("{}{:.17g}", CGAL::sign(value) == CGAL::NEGATIVE ? "-" : "", magnitude);
}

std::string exact_mm(const FT& units) { return exact_text(units / FT(1'000'000'000L)); }

std::string exact_text(const mpq_class& value) {
  if (sgn(value) == 0) return "0";
  return exact_text(FT(CORE::BigRat(value.get_mpq_t())));
}

}  // namespace cutcom::ref
