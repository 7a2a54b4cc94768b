// ref: collision detection CDON (TRC-CD-*): a block's entry against the held-back output and the
// cut there. Geometry in bottleneck.cpp; the held-back output in collision_window.hpp.
#include "compensation.hpp"
#include "piece_box.hpp"

namespace cutcom::ref::detail {

std::optional<Compensation::Entry> Compensation::entry_of(const Block& m, const Block& before) {
  Entry en;
  en.element = element_of(m);
  en.before = &before;
  const ContourElement& next = en.element;
  const FT& sr = comp_->side_radius;
  const int line = m.words.line;
  if (next.is_arc()) {
    en.radius = equidistant_radius<Kernel>(next.radius, next.sense, sr);
    if (CGAL::sign(en.radius) != CGAL::POSITIVE)
      return decide("TRC-CD-2", line, "collapsed", exact_mm(en.radius)), std::nullopt;
  }
  en.normal_start = equidistant_point<Kernel>(next.a, next.start_normal(), sr);
  Point end = equidistant_point<Kernel>(next.b, next.end_normal(), sr);
  auto equidistant_from = [&](const Point& from, bool full) {
    return next.is_arc() ? PathPiece::circle(from, end, next.centre, en.radius, next.sense, full)
                         : PathPiece::segment(from, end, carrier_of(next, en.radius));
  };
  en.before_element = element_of(before);
  const ContourElement& prev = en.before_element;
  FT& prev_radius = en.before_radius;
  if (prev.is_arc()) prev_radius = equidistant_radius<Kernel>(prev.radius, prev.sense, sr);
  en.vertex = prev.b;
  en.own_start = en.normal_start;
  std::optional<CornerClass> rc;
  if (prev.rational && next.rational) rc = classify_corner(prev.end_tangent, next.start_tangent, comp_->s);
  CornerKind kind = rc ? rc->kind : classify_corner(prev.end_dir, next.start_dir, comp_->s);
  if (prev.is_arc() && CGAL::sign(prev_radius) != CGAL::POSITIVE) {
    decide("TRC-CD-2", line, "after-collapse", exact_mm(prev_radius));
    kind = CornerKind::kTangent;
  } else {
    static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
    FT cross = prev.end_dir.x() * next.start_dir.y() - prev.end_dir.y() * next.start_dir.x();
    FT dot = prev.end_dir * next.start_dir;
    decide("TRC-CD-2", line, kKind[static_cast<int>(kind)],
           margins_kept() ? exact_text(FT(comp_->s) * cross / exact_root(dot * dot + cross * cross)) : std::string());
  }
  Point prev_end = equidistant_point<Kernel>(prev.b, prev.end_normal(), sr);
  if (kind == CornerKind::kOuter && !outer_corner_is_circle(m, prev, prev_radius, next, en.radius, rc)) {
    // G451 (TRC-G451-1, TRC-ARC-CORNER-1): both equidistants extended to their intersection.
    en.own_start = *g451_point_;
    en.lead = Entry::Lead::kExtension;
    en.pieces.push_back(prev.is_arc() ? PathPiece::circle(prev_end, en.own_start, prev.centre, prev_radius, prev.sense)
                                      : PathPiece::segment(prev_end, en.own_start, carrier_of(prev, prev_radius)));
    en.pieces.push_back(equidistant_from(en.own_start, false));
    return en;
  }
  if (kind == CornerKind::kOuter || kind == CornerKind::kReversal) {
    en.pieces.push_back(PathPiece::circle(prev_end, en.normal_start, prev.b, leaf(comp_->radius), -comp_->s));
    en.lead = Entry::Lead::kCircle;
  }
  if (kind != CornerKind::kInner) {
    en.pieces.push_back(equidistant_from(en.normal_start, next.full_circle));
    return en;
  }
  Carrier<Kernel> u = carrier_of(prev, prev_radius), v = carrier_of(next, en.radius);
  std::optional<Point> x = nearest_intersection(u, v, prev.b, next.start_dir);
  if (x) facts_.add(*x, u), facts_.add(*x, v);
  if (!x) {
    decide("TRC-CD-2", line, "no-entry", u.circle || v.circle ? exact_mm(carrier_gap<Kernel>(u, v)) : "-inf");
    return std::nullopt;
  }
  Extent reach = extent_of(next, en.radius, *x);
  bool beyond = reach.after_end == CGAL::NEGATIVE;
  // The entry hinges on two thresholds with circles: that the carriers meet at all (their gap)
  // and that the intersection lies before the end; the margin is the nearer one.
  std::string margin = reach.left_text;
  if (!beyond && margins_kept() && (u.circle || v.circle)) {
    FT gap = carrier_gap<Kernel>(u, v);
    if (std::fabs(rough(gap)) * 1e-9 < std::strtod(reach.left_text.c_str(), nullptr))
      margin = exact_mm(-gap);  // units -> mm
  }
  decide("TRC-CD-2", line, beyond ? "no-entry" : "entry", margin);
  if (beyond) return std::nullopt;
  en.own_start = *x;
  en.pieces.push_back(equidistant_from(*x, false));
  return en;
}

bool Compensation::outer_corner_is_circle(const Block& m, const ContourElement& prev, const FT& prev_radius,
                                          const ContourElement& next, const FT& next_radius,
                                          const std::optional<CornerClass>& rc) {
  FT cross = rc ? to_ft(rc->cross) : prev.end_dir.x() * next.start_dir.y() - prev.end_dir.y() * next.start_dir.x();
  FT dot = rc ? to_ft(rc->dot) : prev.end_dir * next.start_dir;
  if (outer_corner_circle(m, rc, cross, dot)) return true;  // traced: the entry may part the runs here
  if (!prev.is_arc() && !next.is_arc()) {
    FT trim = corner_trim<Kernel>(cross, dot, prev.length, next.length, comp_->side_radius);
    g451_point_ = corner_intersection<Kernel>(prev.b, prev.normal, prev.d, prev.length, comp_->side_radius, trim);
    return false;
  }
  Carrier<Kernel> u = carrier_of(prev, prev_radius), v = carrier_of(next, next_radius);
  g451_point_ = nearest_intersection(u, v, prev.b, next.start_dir);
  if (g451_point_) facts_.add(*g451_point_, u), facts_.add(*g451_point_, v);
  // The carriers may just touch: the margin is their gap (a knife edge at 0).
  decide("TRC-CD-2", m.words.line, g451_point_ ? "g451-meets" : "g451-misses",
         margins_kept() ? exact_mm(carrier_gap<Kernel>(u, v)) : std::string());
  return !g451_point_;
}

PathPiece Compensation::piece_of(const HeldRecord& r) {
  const ExactPath::Element& e = r.exact;
  Point a = e.start.plane(e.axes), b = e.end.plane(e.axes);
  if (r.element->type == ElementType::kLine) {
    if (!e.offset_of) return PathPiece::segment(a, b);
    return PathPiece::segment(a, b, ref::carrier_of(*e.offset_of, FT(0), e.side_radius));
  }
  return PathPiece::circle(a, b, e.centre->plane(e.axes), CGAL::abs(e.side_radius), r.element->ccw ? 1 : -1, a == b);
}

PathPiece Compensation::open_piece() const {
  const ContourElement& e = *open_;
  Point end = equidistant_point<Kernel>(e.b, e.end_normal(), comp_->side_radius);
  if (!e.is_arc()) return PathPiece::segment(open_start_, end, carrier_of(e, open_radius_));
  return PathPiece::circle(open_start_, end, e.centre, open_radius_, e.sense, e.full_circle && open_at_normal_start_);
}

bool Compensation::bottleneck(const Block& m, const Block& before) {
  if (comp_->radius.sign() == 0) return false;  // no width: nothing to collide
  int lo = seq_of(m) - md_.cutcom_maxnum_check_blocks, hi = seq_of(m) - 2;
  std::optional<Entry> entry;
  std::optional<FT> near;
  bool overlap = false;  // collinear pieces overlap (a near miss of 0)
  bool compared = false;
  // A G451 lead is the predecessor's equidistant: m-2's held element ends on it, at their common
  // corner, and is not compared with it (in the look-ahead m-1 was passed over: no such corner).
  auto try_piece = [&](const PathPiece& held, int seq) -> std::optional<PieceCrossing> {
    if (!entry && !compared) entry = entry_of(m, before);
    compared = true;
    if (!entry) return std::nullopt;
    bool skip_lead = entry->lead == Entry::Lead::kExtension && seq == hi && !looking_;
    PieceCrossing c = piece_crossing(held, entry->pieces, skip_lead ? 1 : 0, margins_kept(), &facts_);
    // The largest near miss (picked by the filter's value: see bottleneck.hpp).
    keep_largest(near, c.near_miss);
    overlap = overlap || c.overlap;
    if (!c.point) return std::nullopt;
    facts_.add(*c.point, held.carrier());  // the cut point ends the held piece and starts the entry's
    facts_.add(*c.point, entry->pieces[static_cast<std::size_t>(c.entry_piece)].carrier());
    return c;
  };
  // Without margins a held piece plainly apart from the whole entry is passed over: piece_crossing
  // would find no crossing there (PieceBox; with margins its near misses are the trace's).
  std::optional<PieceBox> entry_box;
  auto apart = [&](const PathPiece& held) {
    if (!entry_box) return false;
    std::optional<PieceBox> b = PieceBox::of(held);
    return b && PieceBox::apart(*b, *entry_box);
  };
  const std::deque<HeldRecord>& records = held_.records();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const HeldRecord& r = records[i];
    if (!r.candidate() || r.seq < lo || r.seq > hi) continue;
    if (!compared) {
      entry = entry_of(m, before), compared = true;
      if (!entry) return false;
      if (!margins_kept()) entry_box = PieceBox::around(entry->pieces);
    }
    PathPiece held = piece_of(r);
    if (apart(held)) continue;
    if (std::optional<PieceCrossing> c = try_piece(held, r.seq)) return cut(m, *entry, i, *c, near), true;
  }
  if (looking_ && seq_of(*open_block_) >= lo && seq_of(*open_block_) <= hi) {
    PathPiece held = open_piece();
    if (!apart(held))
      if (std::optional<PieceCrossing> c = try_piece(held, seq_of(*open_block_)))
        return cut(m, *entry, std::nullopt, *c, near), true;
  }
  // A miss of exactly 0 is an overlap of collinear pieces (a point at 0 lies on both: a cut).
  bool at_overlap = overlap && near && CGAL::sign(*near) == CGAL::ZERO;
  if (entry)
    decide("TRC-CD-3", m.words.line, at_overlap ? "overlap" : "none",
           !margins_kept() ? std::string()
           : near          ? exact_mm(*near)
                           : std::string("-inf"));
  return false;
}

void Compensation::cut(const Block& m, const Entry& en, std::optional<std::size_t> record, const PieceCrossing& c,
                       const std::optional<FT>& near) {
  const Point x = *c.point;
  decide("TRC-CD-3", m.words.line, "cut", margins_kept() ? exact_mm(lowered(c.slack, near)) : std::string());
  if (!cut_at(m, record, x)) return;
  continue_entry(m, en, c.entry_piece, x);
}

bool Compensation::cut_at(const Block& reporting, std::optional<std::size_t> record, const Point& x) {
  std::vector<const Block*> passed;
  auto pass = [&](const Block* b) {
    for (const Block* p : passed)
      if (p == b) return;
    passed.push_back(b);
  };
  if (record) {
    const HeldRecord& r = held_.records()[*record];
    const Block* crossed = r.owner;
    ExactPoint end = r.exact.end;
    FT* coords[3] = {&end.x, &end.y, &end.z};
    *coords[comp_->axes.abscissa] = x.x(), *coords[comp_->axes.ordinate] = x.y();
    bool rest = false;  // the crossed block had more after the cut element
    for (const HeldRecord& k : held_.cut(*record, end)) {
      const Block* owner = k.owner;
      if (!k.element) actions_done_[slot(*owner)] = 0;  // run again at x
      if (owner == crossed)
        rest = true;
      else
        pass(owner);
    }
    if (open_block_ == crossed)
      rest = true;  // its equidistant was still open
    else
      pass(open_block_);
    if (rest) {  // the crossed block's applicate motion still to come
      ExactPoint to = end;
      FT* t[3] = {&to.x, &to.y, &to.z};
      *t[comp_->axes.applicate] = leaf(coord(crossed->end, comp_->axes.applicate));
      emit_line(*crossed, end, to, OriginKind::kInfeed);
    }
  } else {
    looking_ = false;
    if (!close_open(x, reporting, Placed::kOnPiece)) return false;
  }
  for (const Block* d : skipped_) pass(d);
  for (const Block* d : dummies_) pass(d);
  std::sort(passed.begin(), passed.end(), [](const Block* a, const Block* b) { return a->index < b->index; });
  skipped_ = std::move(passed);
  dummies_.clear();
  looking_ = false;
  kont_first_ = false;
  run_skipped(x);
  return true;
}

void Compensation::continue_entry(const Block& m, const Entry& en, int entry_piece, const Point& x) {
  const Entry::Lead lead = en.lead;
  bool on_lead = lead != Entry::Lead::kNone && entry_piece == 0 && x != en.own_start;
  if (!on_lead) return open(m, en.element, x, en.radius, Placed::kOnPiece, en.own_start);
  Decimal h = coord(m.start, comp_->axes.applicate);
  if (lead == Entry::Lead::kCircle) {
    Origin corner = origin(*en.before, OriginKind::kTransitionCircle);
    corner.next_line = m.words.line, corner.next_block = m.words.number, corner.next_insert = m.insert;
    emit_corner_circle(m, x, en.normal_start, en.vertex, h, corner);
    return open(m, en.element, en.normal_start, en.radius, Placed::kNormal);
  }
  // The rest of the predecessor's extended equidistant, at m's applicate, named after it.
  const ContourElement& p = en.before_element;
  if (p.is_arc())
    emit_arc(m, at({x, h}), at({en.own_start, h}), at({p.centre, h}), en.before_radius, p.sense > 0,
             origin(*en.before, OriginKind::kOffset), comp_->axes);
  else
    emit_line(m, at({x, h}), at({en.own_start, h}), OriginKind::kOffset, &p, en.before);
  open(m, en.element, en.own_start, en.radius);
}

bool Compensation::search_further_back(const Block& b, const EdgeCurve& curve) {
  std::vector<PathPiece> aux{curve_piece(curve)};
  int lo = seq_of(b) - md_.cutcom_maxnum_check_blocks, hi = seq_of(b) - 2;
  std::optional<FT> near;
  bool overlap = false;  // collinear pieces overlap (a near miss of 0)
  bool compared = false;
  const std::deque<HeldRecord>& records = held_.records();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const HeldRecord& r = records[i];
    if (!r.candidate() || r.seq < lo || r.seq > hi) continue;
    compared = true;
    PathPiece held = piece_of(r);
    PieceCrossing c = piece_crossing(held, aux, 0, margins_kept(), &facts_);
    keep_largest(near, c.near_miss);
    overlap = overlap || c.overlap;
    if (!c.point) continue;
    facts_.add(*c.point, held.carrier());
    facts_.add(*c.point, aux[0].carrier());
    decide("TRC-CD-5", b.words.line, "earlier-block",
           margins_kept() ? exact_mm(lowered(c.slack, near)) : std::string());
    const Point x = *c.point;
    if (!cut_at(b, i, x)) return true;
    retraction_line(b, x);
    return true;
  }
  if (compared)
    decide("TRC-CD-5", b.words.line, "open-element",
           !margins_kept() ? std::string()
           : near          ? exact_mm(*near)
                           : std::string("-inf"));
  return false;
}

PathPiece Compensation::curve_piece(const EdgeCurve& curve) const {
  const Carrier<Kernel>& k = curve.carrier;
  if (k.circle)
    return PathPiece::circle(k.point + Vector(k.radius, 0), k.point + Vector(k.radius, 0), k.point, k.radius, 1, true);
  if (curve.bound == EdgeCurve::Bound::kSegment) return PathPiece::segment(k.point, k.point + k.direction, k);
  FT far = FT(10'000'000'000'000L) * FT(1'000'000'000L) / exact_root(k.direction.squared_length());
  return PathPiece::segment(k.point, k.point + k.direction * far, k);
}

}  // namespace cutcom::ref::detail
