// NC-CONTOUR-1/2/3/6: the reader's stage that holds a block back until the element after it is
// known: roundings and chamfers at its end corner (RND RNDM CHF CHR), the corner of a two-block
// angle definition (ANG), and the full turns of a helix (TURN). Programs without them pass by.
#include <fmt/format.h>

#include <stdexcept>

#include "contour_geometry.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

using contour::IPoint;
using grid::Interval;

namespace {

bool has_corner_word(const BlockWords& w) { return w.cw().rnd || w.cw().chf || w.cw().chr; }

void set_plane(Point3& p, PlaneAxes ax, Decimal a, Decimal o) { coord(p, ax.abscissa) = a, coord(p, ax.ordinate) = o; }

bool moves_applicate(const Block& b) {
  int h = plane_axes(b.state.plane).applicate;
  return coord(b.start, h) != coord(b.end, h);
}

// A block by its N number, else its line; in a subprogram its file and line there (`where`: the
// interpreter's text of its place, "NAME.SPF line 9, called from ...").
std::string name_of(const Block& b, const std::string& where = {}) {
  if (b.words.number) return fmt::format("N{}", *b.words.number);
  if (b.words.source != 0 && !where.empty()) return where.substr(0, where.find(", called from"));
  return fmt::format("line {}", b.words.line);
}

}  // namespace

bool ProgramReader::needs_contour_stage(const Block& b) const {
  const BlockWords& w = b.words;
  return ang_open_ || has_corner_word(w) || (w.cw().turn && *w.cw().turn > 0) ||
         (rounding_modal_.sign() > 0 && b.moves_in_plane() && !b.is_sar_block());
}

void ProgramReader::set_position(const Point3& p) {
  position_ = p;
  refresh_programmed();
}

void ProgramReader::pop_ready(Block& out) {
  out = std::move(ready_.front());
  ready_.pop_front();
  out.index = index_++;
}

void ProgramReader::contour_stage(Block& b) {
  if (pending_) {
    bool element = b.moves_in_plane() || b.is_sar_block() || !b.words.not_simulated.empty() || ang_open_;
    if (!element && !b.words.program_end && between_.size() < 3) {
      between_.push_back(std::move(b));
      return;
    }
    finish_pending(element ? &b : nullptr);
  }
  const BlockWords& w = b.words;
  bool corner = has_corner_word(w) || (rounding_modal_.sign() > 0 && b.moves_in_plane() && !b.is_sar_block());
  if (has_corner_word(w) && !b.moves_in_plane() && !ang_open_)
    throw InputError(w.line, 1, "RND/CHF/CHR in a block without motion in the plane: nothing to round or chamfer");
  if (has_corner_word(w) && b.is_sar_block())
    throw InputError(w.line, 1, "RND/CHF/CHR in a SAR block is SINUMERIK NC that cutcom does not simulate");
  if (corner || ang_open_) {
    pending_radius_ = w.cw().rnd ? length(*w.cw().rnd) : rounding_modal_;  // modal values as of this block
    pending_feed_ = corner_feed_modal_;
    pending_ = std::move(b);
    pending_ang_ = ang_open_;
    ang_open_ = false;
    return;
  }
  push_ready(std::move(b));
}

// The pending block meets `next` (nullptr: the program ends, or too many blocks without plane
// motion came between): resolve the angle corner, insert the rounding or chamfer, release.
void ProgramReader::finish_pending(Block* next) {
  Block p = std::move(*pending_);
  pending_.reset();
  bool ang = pending_ang_;
  pending_ang_ = false;
  PlaneAxes ax = plane_axes(p.state.plane);
  // NC-PARAM-SUB-3: a block of a subprogram names where it stands there (its line is the call's).
  auto fail = [&](int line, const std::string& what) {
    for (const Block* b : {&p, next})
      if (b && b->words.line == line && b->words.source != 0)
        throw InputError(line, 1, fmt::format("in subprogram {}: {}", interpreter_.source_text(b->words.source), what));
    throw InputError(line, 1, what);
  };
  auto named = [&](const Block& b) { return name_of(b, interpreter_.source_text(b.words.source)); };

  if (ang) {  // NC-CONTOUR-3: the corner of two lines given by their angles
    if (!next || !next->words.cw().ang || !next->words.axis[static_cast<std::size_t>(ax.abscissa)].present ||
        !next->words.axis[static_cast<std::size_t>(ax.ordinate)].present || next->is_arc())
      fail(p.words.line,
           "ANG= without an end point opens a two-block definition: the next block with motion in "
           "the plane must give the end point in both plane axes and its own ANG=");
    for (int a : {ax.abscissa, ax.ordinate})
      if (next->words.axis[static_cast<std::size_t>(a)].mode == ValueMode::kIncremental ||
          (next->words.axis[static_cast<std::size_t>(a)].mode == ValueMode::kModal && !next->state.absolute))
        fail(next->words.line, "the end point of a two-block ANG definition is programmed absolutely");
    const ProgrammableFrame f = frame_;
    Decimal fa = f.factor[static_cast<std::size_t>(ax.abscissa)], fo = f.factor[static_cast<std::size_t>(ax.ordinate)];
    Decimal a1 = *p.words.cw().ang, a2 = *next->words.cw().ang;
    Point3 s = p.start, e = next->end;
    std::array<Decimal, 2> corner;
    try {
      corner = grid::to_grid<2>([&] {
        auto direction = [&](Decimal deg) {  // the line's direction in the output system
          return contour::turned({Interval(fa) * Interval::cos_deg(deg), Interval(fo) * Interval::sin_deg(deg)},
                                 f.rotation);
        };
        IPoint d1 = direction(a1), d2 = direction(a2);
        IPoint q1 = contour::in_plane(s, ax), q2 = contour::in_plane(e, ax);
        Interval den = contour::cross(d1, d2);
        if (den.sign() == 0) throw contour::ContourError{"the two lines of the ANG definition are parallel"};
        IPoint c = q1 + (contour::cross(q2 - q1, d2) / den) * d1;
        return std::array<Interval, 2>{c.a, c.o};
      });
    } catch (const contour::ContourError& err) {
      fail(next->words.line, err.what);
    } catch (const std::overflow_error&) {  // nearly parallel lines: the corner lies beyond any axis
      fail(next->words.line, "the corner of the ANG definition lies out of range: the two lines are nearly parallel");
    }
    set_plane(p.end, ax, corner[0], corner[1]);
    p.words.axis[static_cast<std::size_t>(ax.abscissa)].present = true;
    p.words.axis[static_cast<std::size_t>(ax.ordinate)].present = true;
    set_plane(next->start, ax, corner[0], corner[1]);
    for (Block& m : between_) set_plane(m.start, ax, corner[0], corner[1]), set_plane(m.end, ax, corner[0], corner[1]);
  }

  // NC-CONTOUR-1/2: the rounding or chamfer at the end of p.
  const ContourWords& cw = p.words.cw();
  std::optional<Block> insert;
  // The rounding (RND or RNDM) wins over a chamfer in the same block; a value of 0 inserts nothing.
  const contour::CornerKind kind = (cw.rnd || !(cw.chf || cw.chr)) ? contour::CornerKind::kRounding
                                   : cw.chf                        ? contour::CornerKind::kChamferLength
                                                                   : contour::CornerKind::kChamferLeg;
  const bool rounding = kind == contour::CornerKind::kRounding;
  Decimal value = rounding ? pending_radius_ : length(cw.chf ? *cw.chf : *cw.chr);
  bool corner = value.sign() > 0 && p.moves_in_plane();
  std::string why_not;
  if (corner && !next)
    why_not = between_.size() >= 3 ? "more than three blocks without motion in the plane follow"
                                   : "no element follows in the plane";
  else if (corner && (next->is_sar_block() || !next->words.not_simulated.empty()))
    why_not = "the next block is not a contour element";
  else if (corner && next->state.plane != p.state.plane)
    why_not = "the plane changes";
  if (corner && !why_not.empty()) {
    note(p, "NC-CONTOUR-1",
         fmt::format("{} of {} not inserted: {}", rounding ? "rounding" : "chamfer", named(p), why_not));
    corner = false;
  }
  if (corner) {
    if (moves_applicate(p) || moves_applicate(*next))
      fail(p.words.line,
           "a rounding or chamfer next to a move of the infeed axis is SINUMERIK NC that cutcom does "
           "not simulate");
    Decimal fa = frame_.factor[static_cast<std::size_t>(ax.abscissa)];
    Decimal fo = frame_.factor[static_cast<std::size_t>(ax.ordinate)];
    if (fa != fo && fa != -fo)
      fail(p.words.line,
           "a rounding or chamfer under a frame that scales the plane axes "
           "differently is not simulated");
    value = value.times(fa.sign() < 0 ? -fa : fa);  // a uniform scale scales the rounding too
    std::optional<std::array<Decimal, 13>> cut;
    bool tangent = false;  // the elements meet tangentially: no corner to cut
    try {
      // [0..1] new end of p, [2..3] new start of next, [4..5] the rounding's centre, [6..9] the
      // circles' centres, [10] 1 if there is a corner to cut (0: tangent), [11] its turn (±1),
      // [12] the value inserted where the programmed one was reduced, else 0.
      std::array<Decimal, 13> v = grid::to_grid<13>([&] {
        contour::Element e1 = contour::element_of(p), e2 = contour::element_of(*next);
        std::optional<contour::CornerCut> c = contour::cut_corner(e1, e2, kind, Interval(value));
        if (!c) return std::array<Interval, 13>{};
        return std::array<Interval, 13>{c->t1.a,
                                        c->t1.o,
                                        c->t2.a,
                                        c->t2.o,
                                        c->centre.a,
                                        c->centre.o,
                                        e1.centre.a,
                                        e1.centre.o,
                                        e2.centre.a,
                                        e2.centre.o,
                                        Interval::integer(1),
                                        Interval::integer(c->sense),
                                        c->reduced ? c->value : Interval()};
      });
      if (v[10] == Decimal::from_int(1))
        cut = v;
      else
        tangent = true;
    } catch (const contour::ContourError& err) {
      fail(p.words.line,
           fmt::format("{} of {}/{}: {}", rounding ? "the rounding" : "the chamfer", named(p), named(*next), err.what));
    } catch (const std::domain_error&) {
      fail(p.words.line, "the rounding or chamfer has no solution at this corner");
    } catch (const std::overflow_error&) {
      fail(p.words.line, "the rounding or chamfer lies out of range");
    }
    // The block's own RND, CHF or CHR at a tangent transition: said, so that the programmer does
    // not look for it in the path (a modal RNDM passes over such corners silently, as intended).
    if (tangent && (!rounding || cw.rnd))
      note(p, "NC-CONTOUR-1",
           fmt::format("{} of {}/{} not inserted: the elements meet tangentially, there is no corner",
                       rounding ? "rounding" : "chamfer", named(p), named(*next)));
    // A cut whose two points fall on one grid point is shorter than the grid: inserted, a rounding
    // would read as a full circle (ARC rules: start = end), so nothing is.
    if (cut && (*cut)[0] == (*cut)[2] && (*cut)[1] == (*cut)[3]) {
      note(p, "NC-CONTOUR-1",
           fmt::format("{} of {}/{} not inserted: it is shorter than 10^-9 mm", rounding ? "rounding" : "chamfer",
                       named(p), named(*next)));
      cut.reset();
    }
    if (cut && (*cut)[12].sign() > 0)
      note(p, "NC-CONTOUR-1",
           fmt::format("{} of {}/{} reduced to {} mm: the programmed one does not fit on the elements",
                       rounding ? "rounding" : "chamfer", named(p), named(*next), (*cut)[12].to_string()));
    if (cut) {
      const auto& v = *cut;
      auto centre_of = [&](const Block& b, Decimal a, Decimal o) {
        Point3 c = b.start;
        set_plane(c, ax, a, o);
        return c;
      };
      auto closed = [&](const Block& b) {
        return coord(b.start, ax.abscissa) == coord(b.end, ax.abscissa) &&
               coord(b.start, ax.ordinate) == coord(b.end, ax.ordinate);
      };
      // A reduced cut may take a whole element: what is left is a block without motion in the
      // plane, not a full circle.
      auto emptied = [&](Block& b) {
        if (!b.is_arc() || !closed(b)) return;
        b.circle = false, b.centre.reset(), b.words.cr.reset();
        b.state.motion = Motion::kLinear;
      };
      if (p.is_arc()) p.centre = centre_of(p, v[6], v[7]), p.words.cr.reset();
      set_plane(p.end, ax, v[0], v[1]);
      emptied(p);
      bool next_arc = next->is_arc() && !closed(*next);  // a full circle keeps its centre
      if (next_arc) next->centre = centre_of(*next, v[8], v[9]), next->words.cr.reset();
      set_plane(next->start, ax, v[2], v[3]);
      if (next_arc) emptied(*next);
      for (Block& m : between_) set_plane(m.start, ax, v[2], v[3]), set_plane(m.end, ax, v[2], v[3]);
      Block ins;
      ins.words.line = p.words.line;
      ins.words.source = p.words.source;
      ins.words.number = p.words.number;
      ins.words.word_count = 1;
      for (int a : {ax.abscissa, ax.ordinate}) {
        AxisWord& aw = ins.words.axis[static_cast<std::size_t>(a)];
        aw.present = true, aw.mode = ValueMode::kAbsolute;
      }
      ins.previous = p.state;
      ins.state = p.state;
      bool rapid = p.state.motion == Motion::kRapid;
      if (cw.frc)
        ins.state.feed = *cw.frc;  // FRC / FRCM: the feed of the inserted element
      else if (pending_feed_.sign() > 0)
        ins.state.feed = pending_feed_;
      ins.start = p.end;
      ins.end = p.end;
      set_plane(ins.end, ax, v[2], v[3]);
      if (rounding) {
        Point3 c = ins.start;
        set_plane(c, ax, v[4], v[5]);
        ins.centre = c;
        ins.circle = true;
        ins.state.motion = v[11].sign() > 0 ? Motion::kArcCcw : Motion::kArcCw;  // turns like the corner
      } else {
        ins.state.motion = rapid ? Motion::kRapid : Motion::kLinear;
      }
      for (int a : {ax.abscissa, ax.ordinate}) ins.words.axis[static_cast<std::size_t>(a)].value = coord(ins.end, a);
      ins.insert.kind = rounding ? InsertKind::kRounding : InsertKind::kChamfer;
      ins.insert.next_line = next->words.line;
      ins.insert.next_block = next->words.number;
      insert = std::move(ins);
    }
  }
  push_ready(std::move(p));
  if (insert) push_ready(std::move(*insert));
  for (Block& m : between_) push_ready(std::move(m));
  between_.clear();
}

// NC-CONTOUR-6: a helix with TURN=n runs n full circles before its arc; the infeed is shared in
// proportion to the angle turned (NC-GRID-1).
void ProgramReader::push_ready(Block&& b) {
  if (!b.words.cw().turn || *b.words.cw().turn == 0) {
    ready_.push_back(std::move(b));
    return;
  }
  PlaneAxes ax = plane_axes(b.state.plane);
  int n = static_cast<int>(*b.words.cw().turn);
  Decimal h0 = coord(b.start, ax.applicate), h1 = coord(b.end, ax.applicate);
  std::vector<Decimal> levels(static_cast<std::size_t>(n));
  Point3 centre = *b.centre;
  if (!(coord(b.start, ax.abscissa) == coord(b.end, ax.abscissa) &&
        coord(b.start, ax.ordinate) == coord(b.end, ax.ordinate))) {
    auto c = grid::to_grid<2>([&] {
      contour::Element e = contour::element_of(b);
      return std::array<Interval, 2>{e.centre.a, e.centre.o};
    });
    set_plane(centre, ax, c[0], c[1]);
  }
  for (int k = 1; k <= n; ++k) {
    if (h0 == h1) {
      levels[static_cast<std::size_t>(k - 1)] = h0;
      continue;
    }
    auto level = grid::to_grid<1>([&] {
      contour::Element e = contour::element_of(b);
      Interval two_pi = Interval::integer(2) * Interval::pi();
      Interval last = e.full ? two_pi : contour::sweep(e.centre, e.start, e.end, e.sense);
      Interval total = Interval::integer(n) * two_pi + last;
      return std::array<Interval, 1>{Interval(h0) + Interval(h1 - h0) * Interval::integer(k) * two_pi / total};
    });
    levels[static_cast<std::size_t>(k - 1)] = level[0];
  }
  Point3 at = b.start;
  for (int k = 1; k <= n; ++k) {
    Block turn = b;
    if (k > 1) turn.words.aux_count = 0, turn.notice.clear(), turn.words.tool_data_count = 0;
    turn.start = at;
    turn.end = at;
    coord(turn.end, ax.applicate) = levels[static_cast<std::size_t>(k - 1)];
    turn.centre = centre;
    coord(*turn.centre, ax.applicate) = coord(turn.start, ax.applicate);
    turn.insert.kind = InsertKind::kTurn;
    turn.insert.turn = k;
    turn.words.cw_set().turn.reset();
    at = turn.end;
    ready_.push_back(std::move(turn));
  }
  b.start = at;
  b.words.aux_count = 0, b.notice.clear(), b.words.tool_data_count = 0;
  b.words.cw_set().turn.reset();
  if (b.centre) coord(*b.centre, ax.applicate) = coord(at, ax.applicate);
  ready_.push_back(std::move(b));
}

}  // namespace cutcom
