// NC-GRID-1: interval enclosures (MPFI) and their correct rounding onto the 10^-9 grid.
#include "grid_value.hpp"

#include <gmp.h>

#include <string>
#include <vector>

namespace cutcom::grid {

namespace {
thread_local mpfr_prec_t current_precision = detail::kFirstPrecision;

// Enclosures of the current precision that were released, kept for the next ones: an evaluation
// makes and drops hundreds of intervals, and each would otherwise cost two allocations.
class IntervalPool {
 public:
  ~IntervalPool() { drop(); }
  void init(mpfi_t v) {
    if (free_.empty()) {
      mpfi_init2(v, current_precision);
      return;
    }
    *v = free_.back();
    free_.pop_back();
  }
  void release(mpfi_t v) {
    if (mpfi_get_prec(v) == current_precision && free_.size() < kKept)
      free_.push_back(*v);
    else
      mpfi_clear(v);
  }
  void drop() {  // on a change of precision
    for (auto& v : free_) mpfi_clear(&v);
    free_.clear();
  }

 private:
  static constexpr std::size_t kKept = 1024;
  std::vector<__mpfi_struct> free_;
};
thread_local IntervalPool pool;

void set_int128(mpz_t z, Int128 v) {
  std::string text = int128_to_string(v);
  mpz_set_str(z, text.c_str(), 10);
}

// The decimal's units (an integer) from an integral mpfr value; false if out of range.
bool units_of(const mpfr_t integral, Int128& units) {
  if (mpfr_fits_slong_p(integral, MPFR_RNDN)) {  // the usual case, without a detour through text
    units = mpfr_get_si(integral, MPFR_RNDN);
    return true;
  }
  mpz_t z;
  mpz_init(z);
  mpfr_get_z(z, integral, MPFR_RNDN);
  bool ok = mpz_sizeinbase(z, 2) < 120;
  if (ok) {
    char* text = mpz_get_str(nullptr, 10, z);
    std::string s(text);
    void (*release)(void*, std::size_t);
    mp_get_memory_functions(nullptr, nullptr, &release);
    release(text, s.size() + 1);
    bool negative = !s.empty() && s[0] == '-';
    Int128 v = 0;
    for (std::size_t k = negative ? 1 : 0; k < s.size(); ++k) v = v * 10 + (s[k] - '0');
    units = negative ? -v : v;
  }
  mpz_clear(z);
  return ok;
}

bool last_precision() { return current_precision >= detail::kLastPrecision; }
}  // namespace

mpfr_prec_t precision() { return current_precision; }

void detail::set_precision(mpfr_prec_t bits) {
  if (bits != current_precision) pool.drop();
  current_precision = bits;
}

Interval::Interval() {
  pool.init(value);
  mpfi_set_ui(value, 0);
}
Interval::Interval(Decimal d) {
  pool.init(value);
  const Int128 units = d.units();
  if (units >= -(Int128(1) << 62) && units <= (Int128(1) << 62)) {  // fits a long: no detour through text
    mpfi_set_si(value, static_cast<long>(units));
    mpfi_div_ui(value, value, static_cast<unsigned long>(Decimal::kUnitsPerOne));
    return;
  }
  mpz_t z;
  mpz_init(z);
  set_int128(z, d.units());
  mpfi_set_z(value, z);
  mpz_clear(z);
  mpfi_div_ui(value, value, static_cast<unsigned long>(Decimal::kUnitsPerOne));
}
Interval Interval::integer(long v) {
  Interval r;
  mpfi_set_si(r.value, v);
  return r;
}
Interval::Interval(const Interval& o) {
  if (mpfi_get_prec(o.value) == current_precision)
    pool.init(value);
  else
    mpfi_init2(value, mpfi_get_prec(o.value));
  mpfi_set(value, o.value);
}
Interval& Interval::operator=(const Interval& o) {
  if (this != &o) {
    mpfi_set_prec(value, mpfi_get_prec(o.value));
    mpfi_set(value, o.value);
  }
  return *this;
}
Interval::~Interval() { pool.release(value); }

Interval operator+(const Interval& a, const Interval& b) {
  Interval r;
  mpfi_add(r.value, a.value, b.value);
  return r;
}
Interval operator-(const Interval& a, const Interval& b) {
  Interval r;
  mpfi_sub(r.value, a.value, b.value);
  return r;
}
Interval operator*(const Interval& a, const Interval& b) {
  Interval r;
  mpfi_mul(r.value, a.value, b.value);
  return r;
}
Interval operator/(const Interval& a, const Interval& b) {
  if (mpfi_has_zero(b.value)) {
    if (!last_precision()) throw Undecided{};
    throw std::domain_error("NC-GRID-1: division by a quantity not told from 0");
  }
  Interval r;
  mpfi_div(r.value, a.value, b.value);
  return r;
}
Interval operator-(const Interval& a) {
  Interval r;
  mpfi_neg(r.value, a.value);
  return r;
}
Interval sqrt(const Interval& a) {
  Interval r;
  Interval clipped(a);
  if (mpfr_sgn(&clipped.value->left) < 0) mpfr_set_zero(&clipped.value->left, 1);
  if (mpfr_sgn(&clipped.value->right) < 0) mpfr_set_zero(&clipped.value->right, 1);
  mpfi_sqrt(r.value, clipped.value);
  return r;
}
Interval atan2(const Interval& y, const Interval& x) {
  Interval r;
  if (mpfi_has_zero(y.value) && mpfr_sgn(&x.value->left) <= 0) {  // on the branch cut: callers decide
    if (!last_precision()) throw Undecided{};
    throw std::domain_error("NC-GRID-1: an angle on the branch cut");
  }
  mpfi_atan2(r.value, y.value, x.value);
  return r;
}
Interval Interval::pi() {
  Interval r;
  mpfi_const_pi(r.value);
  return r;
}

Interval Interval::sin_deg(Decimal degrees) {
  // Reduce exactly to [0, 360).
  const Int128 full = Int128(360) * Decimal::kUnitsPerOne;
  Int128 u = degrees.units() % full;
  if (u < 0) u += full;
  const Int128 one = Decimal::kUnitsPerOne;
  if (u == 0 || u == 180 * one) return Interval();
  if (u == 90 * one) return integer(1);
  if (u == 270 * one) return integer(-1);
  Interval half = integer(1) / integer(2);
  if (u == 30 * one || u == 150 * one) return half;
  if (u == 210 * one || u == 330 * one) return -half;
  Interval r = Interval(Decimal::from_units(u)) * pi() / integer(180);
  mpfi_sin(r.value, r.value);
  return r;
}
Interval Interval::cos_deg(Decimal degrees) { return sin_deg(degrees + Decimal::from_int(90)); }

int Interval::sign() const {
  if (mpfr_sgn(&value->left) > 0) return 1;
  if (mpfr_sgn(&value->right) < 0) return -1;
  if (mpfr_zero_p(&value->left) && mpfr_zero_p(&value->right)) return 0;
  if (!last_precision()) throw Undecided{};
  return 0;
}
bool Interval::is_point() const { return mpfr_equal_p(&value->left, &value->right) != 0; }

namespace {
// An MPFR number freed however its scope is left (a value out of range throws from the middle).
struct ScratchNumber {
  mpfr_t v;
  explicit ScratchNumber(mpfr_prec_t precision) { mpfr_init2(v, precision); }
  ~ScratchNumber() { mpfr_clear(v); }
  ScratchNumber(const ScratchNumber&) = delete;
  ScratchNumber& operator=(const ScratchNumber&) = delete;
};
}  // namespace

bool detail::round_all(const Interval* values, std::size_t n, Decimal* out, bool last) {
  ScratchNumber lo_number(current_precision + 64), hi_number(current_precision + 64);
  mpfr_ptr lo = lo_number.v, hi = hi_number.v;
  bool decided = true;
  for (std::size_t k = 0; k < n && decided; ++k) {
    // Units of 10^-9: multiply the end points, rounding outwards.
    mpfr_mul_ui(lo, &values[k].value->left, static_cast<unsigned long>(Decimal::kUnitsPerOne), MPFR_RNDD);
    mpfr_mul_ui(hi, &values[k].value->right, static_cast<unsigned long>(Decimal::kUnitsPerOne), MPFR_RNDU);
    if (!mpfr_number_p(lo) || !mpfr_number_p(hi)) throw std::overflow_error("NC-GRID-1: value out of range");
    mpfr_round(lo, lo);  // nearest integer, halves away from zero
    mpfr_round(hi, hi);
    if (!mpfr_equal_p(lo, hi)) {
      if (!last) {
        decided = false;
        break;
      }
      // A tie at the last precision: away from zero is the end point of larger magnitude.
      if (mpfr_sgn(hi) > 0 && mpfr_sgn(lo) >= 0)
        mpfr_set(lo, hi, MPFR_RNDN);
      else if (mpfr_sgn(hi) > 0)
        mpfr_set_zero(lo, 1);  // straddles 0 by less than a unit: 0
    }
    Int128 units = 0;
    if (!units_of(lo, units) || units > Decimal::kMaxUnits * 1000 || units < -Decimal::kMaxUnits * 1000)
      throw std::overflow_error("NC-GRID-1: value out of range");
    out[k] = Decimal::from_units(units);
  }
  return decided;
}

}  // namespace cutcom::grid
