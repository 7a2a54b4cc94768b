// NC-FRAME-1/2/4: programmable frames (TRANS ATRANS ROT AROT SCALE ASCALE MIRROR AMIRROR) and the
// position in the frame's own system that partial and polar programming start from.
#include <fmt/format.h>

#include "contour_geometry.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

using grid::Interval;

bool ProgrammableFrame::identity() const {
  for (std::size_t a = 0; a < 3; ++a)
    if (factor[a] != Decimal::from_int(1) || !shift[a].is_zero()) return false;
  return !rotated();
}

namespace {
// The plane that a rotation about `axis` turns: the one whose applicate it is (NC-PLANE-1).
std::pair<std::size_t, std::size_t> rotation_plane(int axis) {
  PlaneAxes pa = plane_axes(axis == 2 ? Plane::kG17 : axis == 1 ? Plane::kG18 : Plane::kG19);
  return {static_cast<std::size_t>(pa.abscissa), static_cast<std::size_t>(pa.ordinate)};
}
// Angle reduced to (-180, 180].
Decimal reduced(Decimal deg) {
  const Int128 full = Int128(360) * Decimal::kUnitsPerOne, half = full / 2;
  Int128 u = deg.units() % full;
  if (u > half) u -= full;
  if (u <= -half) u += full;
  return Decimal::from_units(u);
}
}  // namespace

// NC-FRAME-1/2/4: the block's axis words (or RPL=) are the frame's values.
void ProgramReader::apply_frame(const BlockWords& w, Plane plane) {
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  FrameWord f = *w.frame;
  bool replaces = f == FrameWord::kTrans || f == FrameWord::kScale || f == FrameWord::kMirror || f == FrameWord::kRot;
  if (replaces) frame_ = ProgrammableFrame{};
  if (f == FrameWord::kRot || f == FrameWord::kArot) {
    // NC-FRAME-4: one rotation about the applicate of the working plane (RPL= or that axis); a
    // half turn about another axis mirrors the two axes it turns; anything else tilts the plane.
    int applicate = plane_axes(plane).applicate;
    for (int a = 0; a < 3; ++a) {
      const AxisWord& aw = w.axis[static_cast<std::size_t>(a)];
      if (!aw.present) continue;
      if (aw.mode != ValueMode::kModal) fail("a rotation takes no AC() or IC()");
      Decimal angle = reduced(aw.value);
      if (angle.is_zero()) continue;
      if (a == applicate) continue;
      if (angle != Decimal::from_int(180))
        fail(
            fmt::format("ROT/AROT {}{}: a rotation that tilts the working plane is SINUMERIK NC that cutcom does "
                        "not simulate",
                        "XYZ"[a], aw.value.to_string()));
      auto [p, q] = rotation_plane(a);
      frame_.factor[p] = -frame_.factor[p];
      frame_.factor[q] = -frame_.factor[q];
    }
    Decimal turn = w.cw().rpl ? *w.cw().rpl
                   : w.axis[static_cast<std::size_t>(applicate)].present
                       ? w.axis[static_cast<std::size_t>(applicate)].value
                       : Decimal{};
    if (w.cw().rpl && w.axis[static_cast<std::size_t>(applicate)].present)
      fail("RPL= and a rotation about the applicate in one block");
    turn = reduced(turn);
    if (turn.is_zero()) return;
    if (frame_.rotated() && frame_.rotation_axis != applicate)
      fail("rotations in two different planes are SINUMERIK NC that cutcom does not simulate");
    auto [p, q] = rotation_plane(applicate);
    Decimal fa = frame_.factor[p], fo = frame_.factor[q];
    // R·F·R(v) = R·R(±v)·F when F scales both plane axes alike (mirrored: the turn reverses).
    if (fa != fo && fa != -fo) fail("a rotation after scaling the plane axes differently is a shear: not simulated");
    frame_.rotation = reduced(frame_.rotation + ((fa.sign() < 0) != (fo.sign() < 0) ? -turn : turn));
    frame_.rotation_axis = applicate;
    return;
  }
  for (int a = 0; a < 3; ++a) {
    std::size_t i = static_cast<std::size_t>(a);
    const AxisWord& aw = w.axis[i];
    if (!aw.present) continue;
    if (aw.mode != ValueMode::kModal) fail("a frame value takes no AC() or IC()");
    switch (f) {
      case FrameWord::kTrans:
        frame_.shift[i] = length(aw.value);
        break;
      case FrameWord::kAtrans:  // in the current frame: the shift turns with mirror and scale
        if (frame_.rotated() && a != frame_.rotation_axis) break;  // and with the rotation: below
        frame_.shift[i] = frame_.shift[i] + length(aw.value).times(frame_.factor[i]);
        break;
      case FrameWord::kScale:
      case FrameWord::kAscale:
        if (aw.value.sign() == 0) fail(fmt::format("{}: a scale factor of 0", "XYZ"[a]));
        if (aw.value > Decimal::from_int(1000) || aw.value < Decimal::from_int(-1000))
          fail(fmt::format("{}: scale factors up to 1000 are supported", "XYZ"[a]));
        frame_.factor[i] = frame_.factor[i].times(aw.value);
        // ASCALE repeated (a loop, a subprogram calling itself) shrinks the product below the
        // grid's 1e-9: a factor of 0, which no position can be divided by (reader_fuzz).
        if (frame_.factor[i].sign() == 0)
          fail(fmt::format("{}: the scale factors together come to less than 1e-9", "XYZ"[a]));
        break;
      case FrameWord::kMirror:
      case FrameWord::kAmirror:  // the value is not evaluated: the axis is mirrored
        frame_.factor[i] = -frame_.factor[i];
        break;
      case FrameWord::kRot:
      case FrameWord::kArot:
        break;
    }
  }
  if (f == FrameWord::kAtrans && frame_.rotated()) {
    // NC-FRAME-4: the translation is in the rotated system: turn its plane part (NC-GRID-1).
    // Plain variables, not a structured binding: the lambda below captures them (clang 14).
    const std::size_t p = rotation_plane(frame_.rotation_axis).first, q = rotation_plane(frame_.rotation_axis).second;
    Decimal tp = w.axis[p].present ? length(w.axis[p].value).times(frame_.factor[p]) : Decimal{};
    Decimal tq = w.axis[q].present ? length(w.axis[q].value).times(frame_.factor[q]) : Decimal{};
    auto v = grid::to_grid<2>([&] {
      contour::IPoint t = contour::turned({Interval(tp), Interval(tq)}, frame_.rotation);
      return std::array<Interval, 2>{Interval(frame_.shift[p]) + t.a, Interval(frame_.shift[q]) + t.o};
    });
    frame_.shift[p] = v[0];
    frame_.shift[q] = v[1];
  }
}

// NC-FRAME-3: exactly one of the plane's axes is mirrored.
bool ProgramReader::mirrors_plane(Plane plane) const {
  PlaneAxes pa = plane_axes(plane);
  return (frame_.factor[static_cast<std::size_t>(pa.abscissa)].sign() < 0) !=
         (frame_.factor[static_cast<std::size_t>(pa.ordinate)].sign() < 0);
}

// The selected settable offset relative to the first one (NC-OFFSET-1).
void ProgramReader::select_offset(int index) {
  offset_index_ = index;
  if (index != kWrittenFrame) offset_gcode_ = index;  // NC-PARAM-SYS-5
  offsets_changed_ = false;
  Point3 d = offsets_.translation(offset_index_);
  if (first_offset_ > 0) {
    const Point3& f = first_translation_;
    d = Point3{d.x - f.x, d.y - f.y, d.z - f.z};
  }
  offset_difference_ = d;
  as_written_due_ = true;
}

// NC-FRAME-4: after a frame or offset change the tool stays; its position in the new frame's
// system is the inverse image of where it is, on the grid (NC-GRID-1).
void ProgramReader::refresh_programmed() {
  Point3 off = offset_difference();
  ProgrammableFrame f = frame_;
  std::array<Decimal, 3> base{position_.x - off.x - f.shift[0], position_.y - off.y - f.shift[1],
                              position_.z - off.z - f.shift[2]};
  const std::size_t p = rotation_plane(f.rotation_axis).first, q = rotation_plane(f.rotation_axis).second;
  auto v = grid::to_grid<3>([&] {
    std::array<Interval, 3> b{Interval(base[0]), Interval(base[1]), Interval(base[2])};
    if (f.rotated()) {  // turn back by the rotation
      contour::IPoint t = contour::turned({b[p], b[q]}, -f.rotation);
      b[p] = t.a, b[q] = t.o;
    }
    for (std::size_t a = 0; a < 3; ++a) b[a] = b[a] / Interval(f.factor[a]);
    return b;
  });
  programmed_ = Point3{v[0], v[1], v[2]};
  programmed_known_ = true;
}

}  // namespace cutcom
