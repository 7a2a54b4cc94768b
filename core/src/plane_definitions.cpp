// Positions a block gives by other means than plane coordinates in a plain frame: polar
// coordinates (NC-POLAR-1/2), a line by its angle (NC-CONTOUR-3), circles by an intermediate point
// or tangentially (NC-CONTOUR-4) or by their opening angle (NC-CONTOUR-5), and any position under
// a rotated frame (NC-FRAME-4). Computed in the frame's system on enclosures, mapped to the output
// system and put onto the grid once (NC-GRID-1).
#include <fmt/format.h>

#include "contour_geometry.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

using contour::IPoint;
using grid::Interval;

namespace {
Interval half() { return Interval::integer(1) / Interval::integer(2); }
IPoint unit(Decimal degrees) { return {Interval::cos_deg(degrees), Interval::sin_deg(degrees)}; }
}  // namespace

// A programmed value of `axis` in the frame's system, in mm (NC-UNIT-1). NC-DIAM-1: in G18
// turning, X is a diameter (DIAMON; DIAM90 only for absolute values); a distance such as an
// incremental centre word is a radius value.
Decimal ProgramReader::frame_value(int axis, const AxisWord& aw, const Decimal& current, bool absolute,
                                   bool distance) const {
  Decimal v = length(aw.value);
  if (axis == 0 && !distance &&
      (diameter_ == DiameterMode::kDiamon || (diameter_ == DiameterMode::kDiam90 && absolute)))
    v = v.scaled(1, 2);
  return absolute ? v : current + v;
}

bool ProgramReader::values_as_written() const {
  const Decimal one = Decimal::from_int(1);
  return (units_ == Units::kG71 || units_ == Units::kG710) && diameter_ == DiameterMode::kDiamof &&
         frame_.factor[0] == one && frame_.factor[1] == one && frame_.factor[2] == one && frame_.shift[0].is_zero() &&
         frame_.shift[1].is_zero() && frame_.shift[2].is_zero() && offset_difference_.x.is_zero() &&
         offset_difference_.y.is_zero() && offset_difference_.z.is_zero();
}

void ProgramReader::update_programmed(const BlockWords& w, bool absolute_mode) {
  for (int a = 0; a < 3; ++a) {
    const AxisWord& aw = w.axis[static_cast<std::size_t>(a)];
    if (!aw.present) continue;
    bool abs = aw.mode == ValueMode::kAbsolute || (aw.mode == ValueMode::kModal && absolute_mode);
    Decimal& p = coord(programmed_, a);
    p = frame_value(a, aw, p, abs);
  }
}

// NC-POLAR-1: G110 from the last programmed position, G111 from the workpiece zero, G112 from the
// last pole; by plane coordinates or by AP=/RP= (a polar offset from that point).
void ProgramReader::set_pole(const BlockWords& w, Plane plane) {
  PlaneAxes pa = plane_axes(plane);
  std::array<Decimal, 2> from{};
  if (!programmed_known_) refresh_programmed();
  if (*w.cw().pole == PoleWord::kG110) from = {coord(programmed_, pa.abscissa), coord(programmed_, pa.ordinate)};
  if (*w.cw().pole == PoleWord::kG112) from = pole_;
  if (w.cw().ap.present || w.cw().rp) {
    if (w.cw().ap.mode == ValueMode::kIncremental) throw InputError(w.line, 1, "a pole takes AP= without IC()");
    Decimal ap = w.cw().ap.present ? w.cw().ap.value : Decimal{};
    Decimal rp = w.cw().rp ? length(*w.cw().rp) : Decimal{};
    pole_ = grid::to_grid<2>([&] {
      IPoint p = IPoint{Interval(from[0]), Interval(from[1])} + Interval(rp) * unit(ap);
      return std::array<Interval, 2>{p.a, p.o};
    });
    return;
  }
  int axes[2] = {pa.abscissa, pa.ordinate};
  for (std::size_t k = 0; k < 2; ++k) {
    const AxisWord& aw = w.axis[static_cast<std::size_t>(axes[k])];
    if (aw.present)
      pole_[k] = from[k] + frame_value(axes[k], aw, Decimal{}, true);
    else if (*w.cw().pole == PoleWord::kG111)
      pole_[k] = Decimal{};
    else
      pole_[k] = from[k];
  }
}

bool ProgramReader::define_in_plane(Block& b, ModalState& eff) {
  BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  const ModalState& s = state_;
  PlaneAxes pa = plane_axes(s.plane);
  const std::size_t ia = static_cast<std::size_t>(pa.abscissa), io = static_cast<std::size_t>(pa.ordinate);
  bool polar = (w.cw().ap.present || w.cw().rp) && !w.cw().pole;
  bool has_a = w.axis[ia].present, has_o = w.axis[io].present;
  bool has_centre = w.centre[ia].present || w.centre[io].present;
  bool cip = b.is_arc() && circle_definition_ == CircleDefinition::kCip;
  bool ct = b.is_arc() && circle_definition_ == CircleDefinition::kCt;
  bool ar = w.cw().ar.has_value();
  bool ang = w.cw().ang.has_value();
  bool rotated = frame_.rotated();
  if (rotated && frame_.rotation_axis != pa.applicate && (w.programs_any_axis() || has_centre || polar))
    fail("the frame's rotation tilts the working plane of this block: SINUMERIK NC that cutcom does not simulate");
  if (!polar && !ang && !ar && !cip && !ct && !(rotated && (has_a || has_o || has_centre))) return false;

  bool arc = b.is_arc();
  int sense = s.motion == Motion::kArcCcw ? 1 : -1;  // as programmed, in the frame's system
  if (polar && (has_a || has_o)) fail("AP=/RP= and plane coordinates in one block: either polar or Cartesian");
  if (ang && arc) fail("ANG= defines a straight line: not with G2/G3, CIP or CT");
  if (ar && !arc) fail("AR= (opening angle) needs G2 or G3");
  if (ar && (w.cr || (has_centre && (has_a || has_o)) || polar)) fail("AR= with the centre or the end point, not both");
  if (ar && !has_centre && !has_a && !has_o) fail("AR= needs the centre (I, J) or the end point");
  if (cip && !(w.cw().intermediate[ia].present && w.cw().intermediate[io].present))
    fail(fmt::format("CIP needs the intermediate point in both plane axes ({}1=, {}1=)", "IJK"[ia], "IJK"[io]));
  if (!cip && (w.cw().intermediate[0].present || w.cw().intermediate[1].present || w.cw().intermediate[2].present))
    fail("I1=/J1=/K1= (intermediate point) belong to CIP");
  if ((cip || ct) && (has_centre || w.cr || ar)) fail("CIP and CT take no centre, CR= or AR=");
  if (polar && arc && has_centre) fail("a polar circle turns about the pole: no I, J, K");

  // The start point in the frame's system, and the end point's plane words.
  if (!programmed_known_) refresh_programmed();
  const Decimal sa = coord(programmed_, pa.abscissa), so = coord(programmed_, pa.ordinate);
  auto abs_of = [&](const AxisWord& aw) {
    return aw.mode == ValueMode::kAbsolute || (aw.mode == ValueMode::kModal && s.absolute);
  };
  Decimal ea = has_a ? frame_value(pa.abscissa, w.axis[ia], sa, abs_of(w.axis[ia])) : sa;
  Decimal eo = has_o ? frame_value(pa.ordinate, w.axis[io], so, abs_of(w.axis[io])) : so;

  if (polar) {  // NC-POLAR-2: AP and RP are modal; AP=IC() turns from the last AP
    if (w.cw().ap.present)
      polar_angle_ = w.cw().ap.mode == ValueMode::kIncremental ? polar_angle_ + w.cw().ap.value : w.cw().ap.value;
    if (w.cw().rp) polar_radius_ = length(*w.cw().rp);
  }
  if (ang) {  // NC-CONTOUR-3
    if (has_a && has_o) {
      if (!pending_ang_ || !pending_)
        fail(
            "ANG= with both plane coordinates: the end point is given twice (ANG "
            "with one coordinate, or in the second block of a two-block definition)");
    } else if (!has_a && !has_o) {
      ang_open_ = true;  // the first block of a two-block definition: its end is the corner
    }
  }
  Decimal angle = ang ? *w.cw().ang : Decimal{};
  const Point3 off = offset_difference();
  const ProgrammableFrame f = frame_;
  const Decimal fa = f.factor[ia], fo = f.factor[io];
  Decimal intermediate[2];
  for (std::size_t k = 0; k < 2 && cip; ++k) {
    const AxisWord& aw = w.cw().intermediate[k == 0 ? ia : io];
    int axis = k == 0 ? pa.abscissa : pa.ordinate;
    intermediate[k] = frame_value(axis, aw, k == 0 ? sa : so, abs_of(aw));
  }
  Decimal centre_words[2] = {sa, so};
  for (std::size_t k = 0; k < 2 && has_centre; ++k) {
    const AxisWord& aw = w.centre[k == 0 ? ia : io];
    int axis = k == 0 ? pa.abscissa : pa.ordinate;
    if (!aw.present) continue;
    bool abs = aw.mode == ValueMode::kAbsolute;  // NC-ARC-1: I=AC() a position, else a distance
    centre_words[k] = frame_value(axis, aw, centre_words[k], abs, !abs);
  }
  // CT: the end tangent of the element before, turned back into the frame's system.
  if (ct) {
    if (!last_element_valid_ || last_element_.state.plane != s.plane)
      fail("CT needs an element in the plane before it (a line or circle to continue tangentially)");
  }
  const Decimal ar_value = ar ? *w.cw().ar : Decimal{};
  if (ar && (ar_value.sign() <= 0 || ar_value >= Decimal::from_int(360)))
    fail("AR= (opening angle) must lie between 0 and 360 degrees");
  const bool ar_by_centre = ar && has_centre;
  const Decimal turn_polar = polar_angle_, radius_polar = polar_radius_;
  const std::array<Decimal, 2> pole = pole_;
  int geometric_sense = sense;

  auto to_base = [&](const IPoint& p) {
    // base = offset + shift + R·(F ⊙ p); a rotation of 0 is the exact identity
    IPoint r = contour::turned({Interval(fa) * p.a, Interval(fo) * p.o}, f.rotation);
    return IPoint{Interval(coord(off, pa.abscissa) + f.shift[ia]) + r.a,
                  Interval(coord(off, pa.ordinate) + f.shift[io]) + r.o};
  };
  auto v = grid::to_grid<6>([&] {
    IPoint start{Interval(sa), Interval(so)};
    IPoint end{Interval(ea), Interval(eo)};
    IPoint centre{Interval(centre_words[0]), Interval(centre_words[1])};
    if (polar) {
      IPoint p{Interval(pole[0]), Interval(pole[1])};
      end = p + Interval(radius_polar) * unit(turn_polar);
      if (arc) centre = p;
    }
    if (ang && has_a != has_o) {
      IPoint u = unit(angle);
      if (has_a) {  // the ordinate from the angle: tan
        if (u.a.sign() == 0) throw contour::ContourError{"ANG= is vertical to the given abscissa: no end point"};
        end.o = start.o + (end.a - start.a) * u.o / u.a;
      } else {
        if (u.o.sign() == 0) throw contour::ContourError{"ANG= is parallel to the abscissa: no end point"};
        end.a = start.a + (end.o - start.o) * u.a / u.o;
      }
    }
    if (ar && !ar_by_centre) {  // centre on the bisector: m + σ cot(α/2)/2 · perp(chord)
      IPoint d = end - start;
      Interval sin_a = Interval::sin_deg(ar_value), cos_a = Interval::cos_deg(ar_value);
      Interval cot_half = ar_value == Decimal::from_int(180) ? Interval() : (Interval::integer(1) + cos_a) / sin_a;
      centre = half() * (start + end) + (Interval::integer(sense) * half() * cot_half) * contour::perp(d);
    }
    if (ar_by_centre) {  // the end turns from the start about the centre by σ·AR
      end = centre + contour::turned(start - centre, sense > 0 ? ar_value : -ar_value);
    }
    if (cip) {  // the circle through start, intermediate point and end
      IPoint q{Interval(intermediate[0]), Interval(intermediate[1])};
      IPoint u = q - start, t = end - start;
      Interval den = Interval::integer(2) * contour::cross(u, t);
      if (den.sign() == 0) throw contour::ContourError{"CIP: start, intermediate and end point lie on one line"};
      Interval uu = contour::dot(u, u), tt = contour::dot(t, t);
      centre = start + IPoint{(t.o * uu - u.o * tt) / den, (u.a * tt - t.a * uu) / den};
      geometric_sense = contour::cross(u, end - q).sign() > 0 ? 1 : -1;
    }
    if (ct) {  // NC-CONTOUR-4: the centre on the normal at the start, equidistant from the end
      contour::Element e = contour::element_of(last_element_);
      IPoint tb = contour::turned(e.tangent_at_end(), -f.rotation);  // into the frame's system
      IPoint t{tb.a / Interval(fa), tb.o / Interval(fo)};
      IPoint n = contour::perp(t), d = end - start;
      Interval nd = contour::dot(n, d);
      if (nd.sign() == 0) throw contour::ContourError{"CT: the end point lies on the tangent: no circle"};
      Interval k = contour::dot(d, d) / (Interval::integer(2) * nd);
      centre = start + k * n;
      geometric_sense = k.sign() > 0 ? 1 : -1;
    }
    IPoint eb = to_base(end), cb = to_base(centre);
    return std::array<Interval, 6>{eb.a, eb.o, cb.a, cb.o, end.a, end.o};
  });
  if (!ang_open_) {  // (an open ANG block stays at its start in the plane: its corner comes later)
    coord(b.end, pa.abscissa) = v[0], coord(b.end, pa.ordinate) = v[1];
    coord(programmed_, pa.abscissa) = v[4], coord(programmed_, pa.ordinate) = v[5];
    w.axis[ia].present = w.axis[io].present = true;  // the block moves in both plane axes
    w.axis[ia].value = v[0], w.axis[io].value = v[1];
    w.axis[ia].mode = w.axis[io].mode = ValueMode::kAbsolute;
  }
  if (arc && !w.cr) {
    Point3 c = b.start;
    coord(c, pa.abscissa) = v[2], coord(c, pa.ordinate) = v[3];
    if (coord(c, pa.abscissa) == coord(b.start, pa.abscissa) && coord(c, pa.ordinate) == coord(b.start, pa.ordinate))
      fail("the circle centre lies on the start point (radius 0)");
    b.centre = c;
  }
  if (cip || ct) {  // the sense follows from the geometry; a mirroring frame reverses it (NC-FRAME-3)
    bool ccw = (geometric_sense > 0) != mirrors_plane(s.plane);
    eff.motion = ccw ? Motion::kArcCcw : Motion::kArcCw;
    b.state.motion = eff.motion;
    effective_.motion = eff.motion;
  }
  // The applicate as usual.
  const AxisWord& ah = w.axis[static_cast<std::size_t>(pa.applicate)];
  if (ah.present) {
    Decimal& p = coord(programmed_, pa.applicate);
    p = frame_value(pa.applicate, ah, p, abs_of(ah));
  }
  return true;
}

}  // namespace cutcom
