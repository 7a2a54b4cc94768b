// ref: the ends of compensation - the approach onto the contour and the retraction off it: NORM,
// KONT travelling around the start or end point (TRC-KONT-*), G460/G461/G462 for a too-short
// first or last block (TRC-EDGE-*), and the end of the program (TRC-END-1).
#include "compensation.hpp"

namespace cutcom::ref::detail {

void Compensation::approach(const Block& first_block) {
  prev_block_ = &first_block;
  ContourElement first = element_of(first_block);
  FT radius;
  if (!equidistant_exists(first, radius)) return raise(10751, first_block);  // nothing before it to meet
  ExactPoint from = selection_start();
  Decimal h = coord(selection_->end, comp_->axes.applicate);
  if (selection_->state.approach == ApproachMode::kKont) {
    KontCorner k;
    k.vertex = first.a, k.point = from.plane(comp_->axes);
    k.d1 = k.vertex - k.point, k.d2 = first.start_dir;
    if (!selection_from_ && first.rational && !overrides_.count(selection_->index))
      k.r1 = RationalVector{mpq_class(to_mpz(coord(selection_->end, comp_->axes.abscissa)) -
                                      to_mpz(coord(selection_->start, comp_->axes.abscissa))),
                            mpq_class(to_mpz(coord(selection_->end, comp_->axes.ordinate)) -
                                      to_mpz(coord(selection_->start, comp_->axes.ordinate)))},
      k.r2 = first.start_tangent;
    if (kont_behind(*selection_, k, k.d2, 10755)) return approach_around(first_block, first, radius, from, h, k);
    if (trace_.stopped()) return;
  }
  Point onto = equidistant_point<Kernel>(first.a, first.start_normal(), comp_->side_radius);
  ExactPoint to = at({onto, h});
  FT length = path.distance(from, to);
  decide("TRC-APPR-NORM-1", selection_->words.line, CGAL::sign(length) == CGAL::ZERO ? "zero-length" : "line",
         exact_mm(length));
  // Output waits until the first element's end is known: if it turns out too short,
  // TRC-EDGE-* replace this line.
  approach_ = PendingApproach{from, to, std::move(dummies_)};
  dummies_.clear();
  open(first_block, first, onto, radius, Placed::kNormal);
  phase_ = Phase::kActive;
}

bool Compensation::kont_side(const Block& at_block, const Point& vertex, const Point& point, const Vector& tangent) {
  Vector off = point - vertex;
  FT cross = tangent.x() * off.y() - tangent.y() * off.x();
  bool behind = comp_->s * static_cast<int>(CGAL::sign(cross)) < 0;
  decide("TRC-KONT-1", at_block.words.line, behind ? "behind" : "in-front",
         exact_mm(FT(comp_->s) * cross / exact_root(tangent.squared_length())));
  return behind;
}

bool Compensation::kont_behind(const Block& at_block, const KontCorner& k, const Vector& tangent, int alarm) {
  if (!kont_side(at_block, k.vertex, k.point, tangent)) return false;
  Vector off = k.point - k.vertex;
  FT distance2 = off.squared_length();
  bool inside = CGAL::compare(distance2, comp_->side_radius * comp_->side_radius) == CGAL::SMALLER;
  decide("TRC-KONT-2", at_block.words.line, inside ? "inside" : "room",
         exact_mm(exact_root(distance2) - leaf(comp_->radius)));
  if (inside) raise(alarm, at_block, "TRC-KONT-2");
  return !inside;
}

bool Compensation::kont_circle(const Block& at_block, const KontCorner& k) {
  if (k.r1 && k.r2) return outer_corner_circle(at_block, classify_corner(*k.r1, *k.r2, comp_->s), {}, {});
  FT cross = k.d1.x() * k.d2.y() - k.d1.y() * k.d2.x(), dot = k.d1 * k.d2;
  return outer_corner_circle(at_block, std::nullopt, cross, dot);
}

std::optional<Point> Compensation::kont_intersection(const Block& at_block, const KontCorner& k,
                                                     const ContourElement& e, const FT& e_radius, const Point& on_line,
                                                     const Vector& d) {
  if (!e.is_arc()) {
    FT cross = k.d1.x() * k.d2.y() - k.d1.y() * k.d2.x(), dot = k.d1 * k.d2;
    FT l1 = exact_root(k.d1.squared_length()), l2 = exact_root(k.d2.squared_length());
    FT trim = corner_trim<Kernel>(cross, dot, l1, l2, comp_->side_radius);
    Vector n1(-k.d1.y() / l1, k.d1.x() / l1);
    return corner_intersection<Kernel>(k.vertex, n1, k.d1, l1, comp_->side_radius, trim);
  }
  Carrier<Kernel> line;
  line.point = on_line, line.direction = d;
  Carrier<Kernel> u = carrier_of(e, e_radius);
  std::optional<Point> x = nearest_intersection(u, line, k.vertex, k.d2);
  decide("TRC-ARC-CORNER-1", at_block.words.line, x ? "intersection" : "none", exact_mm(carrier_gap<Kernel>(u, line)));
  return x;
}

void Compensation::approach_around(const Block& first_block, const ContourElement& first, const FT& radius,
                                   const ExactPoint& from, const Decimal& h, const KontCorner& k) {
  kont_first_ = true;
  Point a = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d1), comp_->side_radius);
  bool circle = kont_circle(*selection_, k);
  std::optional<Point> x;
  if (!circle) x = kont_intersection(*selection_, k, first, radius, a, k.d1);
  if (!x) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2: no intersection at an outer corner)
    decide("TRC-KONT-3", selection_->words.line, "circle");
    emit_line(*selection_, from, at({a, h}), OriginKind::kApproach);
    run_held_back(a);
    Point q = equidistant_point<Kernel>(k.vertex, first.start_normal(), comp_->side_radius);
    Origin corner = origin(*selection_, OriginKind::kTransitionCircle);
    corner.next_line = first_block.words.line, corner.next_block = first_block.words.number;
    corner.next_insert = first_block.insert;
    Decimal h1 = coord(first_block.start, comp_->axes.applicate);  // after the held-back blocks
    if (comp_->radius.sign() != 0)                                 // TRC-G450-2
      emit_corner_circle(first_block, a, q, k.vertex, h1, corner);
    open(first_block, first, q, radius, Placed::kNormal);
  } else {  // TRC-KONT-4
    decide("TRC-KONT-4", selection_->words.line, "intersection");
    emit_line(*selection_, from, at({*x, h}), OriginKind::kApproach);
    run_held_back(*x);
    open(first_block, first, *x, radius);
  }
  phase_ = Phase::kActive;
}

void Compensation::flush_approach() {
  if (!approach_) return;
  PendingApproach a = std::move(*approach_);
  approach_.reset();
  emit_line(*selection_, a.from, a.to, OriginKind::kApproach);
  dummies_.swap(a.held_back);
  run_held_back(a.to.plane(comp_->axes));
  dummies_.swap(a.held_back);
}

void Compensation::retract_edge(const Block& b) {
  reject_kontc_kontt(b, true);  // TRC-UNSUP-1
  const Block* last_block = nullptr;
  for (const Block* d : skipped_)
    if (d->moves_in_plane()) last_block = d;
  ContourElement last = element_of(*last_block);
  decide("TRC-DESEL-1", b.words.line, "deselected");
  if (b.state.approach == ApproachMode::kKont) {  // TRC-KONT-1/2, then TRC-EDGE-6
    KontCorner k = retraction_corner(b, last);
    if (kont_behind(b, k, k.d1, 10756)) return retract_edge_around(b, *last_block, k);
    if (trace_.stopped()) return;
  }
  decide("TRC-EDGE-1", b.words.line, g_code(b.state.edge_strategy));
  Point normal_end = equidistant_point<Kernel>(last.b, last.end_normal(), comp_->side_radius);
  EdgeCurve curve = edge_curve(b.state.edge_strategy, last.b, normal_end, last.end_dir, plane_end(b), false);
  EdgeHit edge = edge_hit(curve, *open_, open_radius_, PieceStart{open_start_, open_from_}, false);
  std::optional<Point> hit = edge.point;
  decide("TRC-EDGE-5", b.words.line, hit ? "hit" : "none", edge.margin);
  if (b.state.collision == CollisionMode::kCdon && search_further_back(b, curve)) return;
  if (!hit) return raise(10751, b);
  looking_ = false;
  if (!close_open(*hit, b, Placed::kOnPiece)) return;
  run_skipped(*hit);
  retraction_line(b, *hit);
}

void Compensation::approach_edge(const Candidate& c) {
  const Block& sel = *selection_;
  decide("TRC-EDGE-1", sel.words.line, g_code(sel.state.edge_strategy));
  const ContourElement& first = *open_;
  EdgeCurve curve = edge_curve(sel.state.edge_strategy, first.a, open_start_, -first.start_dir,
                               approach_->from.plane(comp_->axes), true);
  EdgeHit edge = edge_hit(curve, *c.element, c.radius, std::nullopt, true);
  std::optional<Point> hit = edge.point;
  decide("TRC-EDGE-5", sel.words.line, hit ? "hit" : "none", edge.margin);
  if (!hit) return raise(10751, *c.block);
  PendingApproach a = std::move(*approach_);
  approach_.reset();
  emit_line(sel, a.from, at({*hit, coord(sel.end, comp_->axes.applicate)}), OriginKind::kApproach);
  // Blocks passed over, in programmed order: held back before the first block, the first block,
  // held back after it, passed over by the look-ahead.
  std::vector<const Block*> passed = std::move(a.held_back);
  passed.push_back(open_block_);
  for (const Block* d : dummies_) passed.push_back(d);
  for (const Block* d : skipped_) passed.push_back(d);
  dummies_.clear();
  skipped_ = std::move(passed);
  looking_ = false;
  run_skipped(*hit);
  open(*c.block, *c.element, *hit, c.radius, Placed::kOnPiece);
  // TRC-CD-6: with CDON the later blocks of the window are searched too.
  if (sel.state.collision == CollisionMode::kCdon)
    approach_search_ = ApproachSearch{curve, seq_of(sel) + md_.cutcom_maxnum_check_blocks};
}

bool Compensation::approach_further_ahead(const Block& m) {
  if (seq_of(m) > approach_search_->until || m.state.collision != CollisionMode::kCdon) {
    approach_search_.reset();
    return false;
  }
  ContourElement e = element_of(m);
  FT radius;
  if (e.is_arc()) {
    radius = equidistant_radius<Kernel>(e.radius, e.sense, comp_->side_radius);
    if (CGAL::sign(radius) != CGAL::POSITIVE) return false;
  }
  EdgeHit hit = edge_hit(approach_search_->curve, e, radius, std::nullopt, true);
  decide("TRC-CD-6", m.words.line, hit.point ? "later-block" : "none", hit.margin);
  if (!hit.point) return false;
  const std::deque<HeldRecord>& records = held_.records();
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!records[i].element || records[i].element->origin.kind != OriginKind::kApproach) continue;
    if (!cut_at(m, i, *hit.point)) return true;
    open(m, e, *hit.point, radius, Placed::kOnPiece);
    return true;
  }
  return false;
}

void Compensation::deselect(const Block& b) {
  reject_kontc_kontt(b, true);  // TRC-UNSUP-1
  decide("TRC-DESEL-1", b.words.line, "deselected");
  if (b.state.approach == ApproachMode::kKont) {
    KontCorner k = retraction_corner(b, *open_);
    if (kont_behind(b, k, k.d1, 10756)) return retract_around(b, k);
    if (trace_.stopped()) return;
  }
  Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
  if (!close_open(end, b, Placed::kNormal)) return;
  run_held_back(end);
  retraction_line(b, end);
}

// TRC-DESEL-3: G40 without a plane axis ends the last contour block at its normal end point now;
// the block (and those after it without a plane axis) run there.
void Compensation::deselect_in_place(const Block& b) {
  decide("TRC-DESEL-3", b.words.line, "in-place");
  Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
  if (!close_open(end, b, Placed::kNormal)) return;
  run_held_back(end);
  open_.reset();
  retract_from_ = end;
  phase_ = Phase::kRetracting;
  retraction_pending(b);
}

void Compensation::retraction_pending(const Block& b) {
  Decimal from_h = coord(b.start, comp_->axes.applicate);
  if (b.state.plane != comp_->plane) return raise(10757, b);  // TRC-PLANE-1: the tool is off its plane position
  if (!b.programs_plane_axis()) {
    emit_line(b, at({*retract_from_, from_h}), at({*retract_from_, coord(b.end, comp_->axes.applicate)}),
              OriginKind::kRetraction);
    return;
  }
  if (b.state.side == Side::kOff) {
    if (b.is_arc()) return raise(10754, b);  // TRC-DESEL-2: the retraction is a linear block
    decide("TRC-DESEL-3", b.words.line, "retraction");
    Point from = *retract_from_;
    retract_from_.reset();
    return retraction_line(b, from);
  }
  // Selected again: the approach starts where the tool is (as after a side change, TRC-SIDE-1).
  ExactPoint tool = at({*retract_from_, from_h});
  retract_from_.reset();
  phase_ = Phase::kOff;
  comp_.reset();
  compensation_off(b);
  if (phase_ == Phase::kApproach) selection_from_ = tool;
}

Compensation::KontCorner Compensation::retraction_corner(const Block& b, const ContourElement& last) const {
  KontCorner k;
  k.vertex = last.b, k.point = plane_end(b);
  k.d1 = last.end_dir, k.d2 = k.point - k.vertex;
  if (last.rational && !overrides_.count(b.index))
    k.r1 = last.end_tangent,
    k.r2 = RationalVector{
        mpq_class(to_mpz(coord(b.end, comp_->axes.abscissa)) - to_mpz(coord(last.end3, comp_->axes.abscissa))),
        mpq_class(to_mpz(coord(b.end, comp_->axes.ordinate)) - to_mpz(coord(last.end3, comp_->axes.ordinate)))};
  return k;
}

void Compensation::retract_edge_around(const Block& b, const Block& last_block, const KontCorner& k) {
  if (!kont_circle(b, k))
    throw UnsupportedError(  // TRC-EDGE-7 (planned)
        b.words.line, "KONT retraction from behind by intersection (G451) after a too-short last block");
  Point r_point = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d2), comp_->side_radius);
  EdgeCurve circle;
  circle.carrier.circle = true, circle.carrier.point = k.vertex, circle.carrier.radius = leaf(comp_->radius);
  EdgeHit hit = edge_hit(circle, *open_, open_radius_, PieceStart{open_start_, open_from_}, false);
  decide("TRC-EDGE-6", b.words.line, hit.point ? "circle" : "line", hit.margin);
  bool on_circle = hit.point.has_value();
  if (!on_circle) {
    EdgeCurve line;
    line.bound = EdgeCurve::Bound::kSegment, line.carrier.point = r_point, line.carrier.direction = k.point - r_point;
    hit = edge_hit(line, *open_, open_radius_, PieceStart{open_start_, open_from_}, false);
    decide("TRC-EDGE-5", b.words.line, hit.point ? "hit" : "none", hit.margin);
    if (!hit.point) return raise(10751, b);
  }
  const Point x = *hit.point;
  looking_ = false;
  if (!close_open(x, b, Placed::kOnPiece)) return;
  run_skipped(x);
  if (!on_circle) return retraction_line(b, x);
  Origin corner = origin(last_block, OriginKind::kTransitionCircle);
  corner.next_line = b.words.line, corner.next_block = b.words.number, corner.next_insert = b.insert;
  Decimal h = coord(b.start, comp_->axes.applicate);
  emit_corner_circle(b, x, r_point, k.vertex, h, corner);
  retraction_line(b, r_point);
}

void Compensation::retraction_line(const Block& b, const Point& from_point) {
  ExactPoint from = at({from_point, coord(b.start, comp_->axes.applicate)});
  ExactPoint to = end_of(b);
  FT length = path.distance(from, to);
  decide("TRC-RETR-NORM-1", b.words.line, CGAL::sign(length) == CGAL::ZERO ? "zero-length" : "line", exact_mm(length));
  emit_line(b, from, to, OriginKind::kRetraction);
  phase_ = Phase::kOff;
  comp_.reset();
  open_.reset();
}

void Compensation::retract_around(const Block& b, const KontCorner& k) {
  Point r = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d2), comp_->side_radius);
  bool circle = kont_circle(b, k);
  std::optional<Point> x;
  if (!circle) x = kont_intersection(b, k, *open_, open_radius_, r, k.d2);
  if (!x) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
    decide("TRC-KONT-3", b.words.line, "circle");
    Point from = equidistant_point<Kernel>(k.vertex, open_->end_normal(), comp_->side_radius);
    Origin corner = origin(*open_block_, OriginKind::kTransitionCircle);
    corner.next_line = b.words.line, corner.next_block = b.words.number, corner.next_insert = b.insert;
    if (!close_open(from, b, Placed::kNormal)) return;
    run_held_back(from);
    Decimal h = coord(b.start, comp_->axes.applicate);
    if (comp_->radius.sign() != 0)  // TRC-G450-2
      emit_corner_circle(b, from, r, k.vertex, h, corner);
    return retraction_line(b, r);
  }
  decide("TRC-KONT-4", b.words.line, "intersection");
  if (!close_open(*x, b)) return;
  run_held_back(*x);
  retraction_line(b, *x);
}

void Compensation::end_of_program() {
  if (looking_) {  // the program ends before an intersection was found
    decide("TRC-LOOK-2", skipped_.back()->words.line, "none");
    return raise(10751, *skipped_.back());
  }
  if (phase_ == Phase::kApproach) {
    decide("TRC-END-1", selection_->words.line, "no-contour");
    sink_.notice({selection_->words.line, "TRC-END-1",
                  "compensation selected but no block with motion in the plane follows", selection_->words.source});
    emit_line(*selection_, selection_start(), end_of(*selection_), OriginKind::kProgrammed);
    run_held_back_uncompensated();
  } else if (phase_ == Phase::kActive) {
    decide("TRC-END-1", open_->line, "active-at-end");
    sink_.notice({open_->line, "TRC-END-1",
                  "program ends with compensation active: last block ends at its normal point",
                  open_block_->words.source});
    Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
    if (!close_open(end, *open_block_, Placed::kNormal)) return;
    run_held_back(end);
  }
}

}  // namespace cutcom::ref::detail
