// Decisions on programmed decimals, exact: signs from integer (GMP) arithmetic on the decimals'
// units of 10^-9 mm, square roots compared by squaring; margins printed from MPFR with that sign.
#include "cutcom/programmed_decisions.hpp"

#include <fmt/format.h>
#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>

#include "cutcom/units_mpz.hpp"

namespace cutcom {
namespace {

int sign(const mpz_class& z) { return sgn(z); }

// A margin in mm from a decimal.
ProgrammedDecision with_margin(std::string_view clause, std::string_view branch, const Decimal& margin) {
  return {clause, branch, true, margin.to_string(), margin.to_double()};
}

// A margin whose value needs square roots: `value` evaluates it (in units) at 256 bits; `exact_sign`
// is its sign decided exactly. The digits are the nearest double's 17, as for every margin.
template <class F>
ProgrammedDecision with_root_margin(std::string_view clause, std::string_view branch, int exact_sign, MarginText text,
                                    F value) {
  if (text == MarginText::kNone) return {clause, branch, false, "", 0.0};
  if (exact_sign == 0) return {clause, branch, true, "0", 0.0};
  mpfr_t v;
  mpfr_init2(v, 256);
  value(v);
  mpfr_div_ui(v, v, 1'000'000'000UL, MPFR_RNDN);
  double magnitude = std::fabs(mpfr_get_d(v, MPFR_RNDN));
  mpfr_clear(v);
  double signed_value = exact_sign < 0 ? -magnitude : magnitude;
  return {clause, branch, true, fmt::format("{}{:.17g}", exact_sign < 0 ? "-" : "", magnitude), signed_value};
}

void set_z(mpfr_t out, const mpz_class& z) { mpfr_set_z(out, z.get_mpz_t(), MPFR_RNDN); }

struct PlaneDelta {
  mpz_class a, b;
};
PlaneDelta delta(const Point3& from, const Point3& to, PlaneAxes ax) {
  return {to_mpz(coord(to, ax.abscissa)) - to_mpz(coord(from, ax.abscissa)),
          to_mpz(coord(to, ax.ordinate)) - to_mpz(coord(from, ax.ordinate))};
}

}  // namespace

CompensationSide compensation_side(const ModalState& state) {
  CompensationSide c;
  c.effective = state.effective_radius();
  int side = state.side == Side::kLeft ? 1 : -1;
  int sg = c.effective.sign();
  c.s = sg < 0 ? -side : side;  // TRC-RADIUS-2: a negative radius swaps G41 and G42
  c.r = sg < 0 ? -c.effective : c.effective;
  c.decision = {"TRC-RADIUS-2", sg < 0 ? "negative" : sg == 0 ? "zero" : "positive", false, "", 0.0};
  return c;
}

SarSize sar_size(const Block& sar, const std::optional<CompensationSide>& trc, int sar_side) {
  SarContour contour = *sar.words.sar_contour;
  bool line = contour == SarContour::kG147 || contour == SarContour::kG148;
  std::string_view clause = line ? "SAR-DISR-1" : "SAR-DISR-2";
  if (!sar.words.disr) return {std::nullopt, {clause, "missing", false, "", 0.0}};
  Decimal disr = *sar.words.disr;
  Decimal size;
  if (line) {
    // SAR-DISR-1: L = DISR + r; only a positive effective radius lengthens the line.
    size = disr + (trc && trc->effective.sign() > 0 ? trc->effective : Decimal{});
  } else {
    // SAR-DISR-2: DISR > 0; the tool centre's radius is DISR + r with the tool on the circle's
    // outside (the SAR side is the compensation side), DISR - r inside.
    if (disr.sign() <= 0) return {std::nullopt, with_margin(clause, "not-positive", disr)};
    size = !trc ? disr : sar_side == trc->s ? disr + trc->r : disr - trc->r;
  }
  // Boundary rule: a size of exactly 0 is not positive.
  bool valid = size.sign() > 0;
  SarSize out{std::nullopt, with_margin(clause, valid ? "valid" : "not-positive", size)};
  if (valid) out.size = size;
  return out;
}

SarLevelCheck check_sar_levels(const Block& sar, SarLevels& h, const MachineData& md) {
  SarLevelCheck out;
  const BlockWords& w = sar.words;
  if (w.disrp.present && w.discl.present) {  // SAR-DISRP-2
    int s1 = (h.h1 - h.h4).sign(), s2 = (h.h2 - h.h4).sign();
    bool opposite = s1 * s2 < 0;
    out.retraction_plane = ProgrammedDecision{"SAR-DISRP-2", opposite ? "opposite-sides" : "same-side", false, "", 0.0};
    if (opposite) {
      out.alarm = 10748;
      return out;
    }
  }
  // SAR-DISCL-3 (decision 9): h(P1), h(P2), h(P4) monotone; P2 at most MD20204 outside is clamped
  // to the nearer bound. Boundary rule: exactly MD20204 outside is clamped (slack 0 is inside).
  Decimal lo = std::min(h.h1, h.h4), hi = std::max(h.h1, h.h4);
  Decimal excess = h.h2 < lo ? lo - h.h2 : h.h2 > hi ? h.h2 - hi : Decimal{};
  Decimal slack = md.wab_clearance_tolerance - excess;
  if (excess.is_zero()) {
    out.reversal = with_margin("SAR-DISCL-3", "between", slack);
  } else if (slack.sign() >= 0) {
    out.reversal = with_margin("SAR-DISCL-3", "clamped", slack);
    h.h2 = h.h2 < lo ? lo : hi;
  } else {
    out.reversal = with_margin("SAR-DISCL-3", "reversal", slack);
    out.alarm = 10741;
  }
  return out;
}

ProgrammedDecision cr_circle_reach(const Block& b, MarginText text) {
  PlaneAxes ax = plane_axes(b.state.plane);
  if (text == MarginText::kDouble) {
    // In double: the differences are exact decimals rounded once, so q = 4 CR^2 - chord^2 errs by
    // well under 16u (4 CR^2 + chord^2); beyond that its sign is q's.
    double da = (coord(b.end, ax.abscissa) - coord(b.start, ax.abscissa)).to_double();
    double db = (coord(b.end, ax.ordinate) - coord(b.start, ax.ordinate)).to_double();
    // (reach: 2|CR| and the allowance of two grid units for the rounding of the end points)
    double reach = 2 * std::fabs(b.words.cr->to_double()) + 2.0 / Decimal::kUnitsPerOne;
    double chord2 = da * da + db * db, q = reach * reach - chord2;
    bool zero_chord = coord(b.end, ax.abscissa) == coord(b.start, ax.abscissa) &&
                      coord(b.end, ax.ordinate) == coord(b.start, ax.ordinate);
    if (std::fabs(q) > 16 * 0x1p-53 * (reach * reach + chord2))
      return {"ARC-CR-1", !zero_chord && q > 0 ? "circle" : "unreachable", true, "", reach - std::sqrt(chord2)};
  }
  PlaneDelta d = delta(b.start, b.end, ax);
  mpz_class chord2 = d.a * d.a + d.b * d.b;
  mpz_class cr = to_mpz(*b.words.cr);
  if (cr < 0) cr = -cr;
  // The reach: 2|CR| and two grid units, the most by which rounding both end points onto the
  // grid (NC-GRID-1: a rotated frame) lengthens a chord of exactly 2|CR|.
  mpz_class reach = 2 * cr + 2;
  // Boundary rule: a chord of exactly the reach is reached (a half circle); a chord of 0 is not
  // (no circle is defined by one point and a radius), whatever the margin.
  bool reachable = sign(chord2) > 0 && chord2 <= reach * reach;
  int margin_sign = sign(reach * reach - chord2);
  return with_root_margin("ARC-CR-1", reachable ? "circle" : "unreachable", margin_sign, text, [&](mpfr_t v) {
    mpfr_t c;
    mpfr_init2(c, 256);
    set_z(c, chord2);
    mpfr_sqrt(c, c, MPFR_RNDN);
    set_z(v, reach);
    mpfr_sub(v, v, c, MPFR_RNDN);
    mpfr_clear(c);
  });
}

std::optional<int> circle_radius_sign(const Block& b, const Decimal& r) {
  if (!b.centre && !b.words.cr) return std::nullopt;
  PlaneAxes ax = plane_axes(b.state.plane);
  auto plane = [&](const Point3& from, const Point3& to) {
    return std::array<Int128, 2>{(coord(to, ax.abscissa) - coord(from, ax.abscissa)).units(),
                                 (coord(to, ax.ordinate) - coord(from, ax.ordinate)).units()};
  };
  ProgrammedCircle c;
  c.chord = plane(b.start, b.end);
  c.by_centre = b.centre.has_value();
  if (b.centre) c.to_centre = plane(b.start, *b.centre);
  if (b.words.cr) c.cr = b.words.cr->units();
  return circle_radius_sign(c, r.units());
}

int circle_radius_sign(const ProgrammedCircle& c, Int128 r_units) {
  mpz_class r = to_mpz(r_units);
  if (!c.by_centre) {  // rho = |CR|, or half the chord where that is a rounding longer (ARC-CR-1)
    mpz_class rho = to_mpz(c.cr < 0 ? -c.cr : c.cr);
    mpz_class ca = to_mpz(c.chord[0]), cb = to_mpz(c.chord[1]);
    mpz_class chord2 = ca * ca + cb * cb;
    if (chord2 > 4 * rho * rho) return sign(chord2 - 4 * r * r);
    return sign(rho - r);
  }
  mpz_class ca = to_mpz(c.chord[0]), cb = to_mpz(c.chord[1]), ta = to_mpz(c.to_centre[0]), tb = to_mpz(c.to_centre[1]);
  if (ca == 0 && cb == 0) return sign(ta * ta + tb * tb - r * r);  // a full circle: its centre as programmed
  // The corrected centre m + k p (m the chord's midpoint, p its perpendicular) is rational; with
  // L2 = |e - s|^2 and q = (2 c0 - s - e) . p:  4 L2 rho^2 = L2^2 + q^2.
  mpz_class L2 = ca * ca + cb * cb;
  mpz_class q = (2 * ta - ca) * (-cb) + (2 * tb - cb) * ca;
  return sign(L2 * L2 + q * q - 4 * L2 * r * r);
}

ProgrammedDecision circle_end_point(const Block& b, const MachineData& md, MarginText text) {
  PlaneAxes ax = plane_axes(b.state.plane);
  if (text == MarginText::kDouble) {
    // In double: each radius errs by a few u of itself, the tolerance by a few u of itself; the
    // excess is decided when it exceeds 32u of their sum (a generous bound of the rounding).
    // sqrt of the sum of squares, not hypot (a library call, every arc): differences of decimals
    // stay below 1e16 mm, whose squares are far from overflow.
    auto radius = [&](const Point3& p) {
      double a = (coord(p, ax.abscissa) - coord(*b.centre, ax.abscissa)).to_double();
      double o = (coord(p, ax.ordinate) - coord(*b.centre, ax.ordinate)).to_double();
      return std::sqrt(a * a + o * o);
    };
    double rs = radius(b.start), re = radius(b.end);
    double c = md.circle_error_const.to_double(), by_factor = md.circle_error_factor.to_double() * rs;
    double tolerance = std::max(c, by_factor), excess = std::fabs(re - rs) - tolerance;
    if (std::fabs(excess) > 32 * 0x1p-53 * (rs + re + c + by_factor))
      return {"ARC-CENTRE-2", excess < 0 ? "within" : "beyond", true, "", excess};
  }
  PlaneDelta s = delta(*b.centre, b.start, ax), e = delta(*b.centre, b.end, ax);
  mpz_class A = s.a * s.a + s.b * s.b, B = e.a * e.a + e.b * e.b;                 // start and end radius squared
  mpz_class c = to_mpz(md.circle_error_const);                                    // MD21000, units
  mpq_class f(to_mpz(md.circle_error_factor), mpz_class(Decimal::kUnitsPerOne));  // MD21010, a plain factor
  // d = |sqrt(B) - sqrt(A)|, t = max(c, f sqrt(A)); excess = d - t = min(d - c, d - f sqrt(A)).
  // sign(d - c) = sign(d^2 - c^2) = sign(X - sqrt(4AB)) with X = A + B - c^2.
  auto sign_d_minus_c = [&]() {
    mpz_class X = A + B - c * c;
    if (X < 0) return -1;
    return sign(X * X - 4 * A * B);
  };
  // sign(d - f sqrt(A)): end outside, sqrt(B) - (1+f) sqrt(A); inside, (1-f) sqrt(A) - sqrt(B).
  auto sign_d_minus_fa = [&]() {
    if (B >= A) {
      mpq_class k = (1 + f) * (1 + f) * A;
      return sgn(mpq_class(B) - k);
    }
    mpq_class one_minus = 1 - f;
    if (sgn(one_minus) <= 0) return sgn(B) == 0 && sgn(one_minus) == 0 ? 0 : -1;
    return sgn(one_minus * one_minus * A - mpq_class(B));
  };
  int sc = sign_d_minus_c(), sf = sign_d_minus_fa();
  int excess_sign = (sc < 0 || sf < 0) ? -1 : (sc == 0 || sf == 0) ? 0 : 1;
  // Boundary rule: a difference of exactly the tolerance is within.
  bool within = excess_sign <= 0;
  return with_root_margin("ARC-CENTRE-2", within ? "within" : "beyond", excess_sign, text, [&](mpfr_t v) {
    mpfr_t ra, rb, t, k;
    for (auto* x : {&ra, &rb, &t, &k}) mpfr_init2(*x, 256);
    set_z(ra, A), mpfr_sqrt(ra, ra, MPFR_RNDN);
    set_z(rb, B), mpfr_sqrt(rb, rb, MPFR_RNDN);
    mpfr_sub(v, rb, ra, MPFR_RNDN);
    mpfr_abs(v, v, MPFR_RNDN);
    mpfr_set_q(k, f.get_mpq_t(), MPFR_RNDN);
    mpfr_mul(t, k, ra, MPFR_RNDN);
    set_z(k, c);
    mpfr_max(t, t, k, MPFR_RNDN);
    mpfr_sub(v, v, t, MPFR_RNDN);
    for (auto* x : {&ra, &rb, &t, &k}) mpfr_clear(*x);
  });
}

}  // namespace cutcom
