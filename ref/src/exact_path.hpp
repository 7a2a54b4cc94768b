// ref's exact record of the path it outputs, and the exact self-checks run on it
// (PROP-EXACT-1..3): the properties are decided before anything is rounded.
#pragma once

#include <optional>
#include <vector>

#include "contour_element.hpp"
#include "cutcom/ref/engine.hpp"
#include "kernel.hpp"

namespace cutcom::ref {

// A point of the path in workpiece coordinates, exact, in units of 10^-9 mm.
struct ExactPoint {
  FT x, y, z;
  static ExactPoint programmed(const Point3& p) { return {leaf(p.x), leaf(p.y), leaf(p.z)}; }
  static ExactPoint in_plane(const Point& p, const Decimal& applicate, PlaneAxes axes);
  Point plane(PlaneAxes axes) const;
};

class ExactPath {
 public:
  PathPoint output(const ExactPoint& p) const;  // rounded once, for the shared output model
  bool same(const ExactPoint& a, const ExactPoint& b) const;
  FT distance(const ExactPoint& a, const ExactPoint& b) const;

  void check(ExactCheckReport& report) const;

  struct Element {
    int line = 0;  // source line of the block the element belongs to
    ExactPoint start, end;
    PlaneAxes axes{0, 1, 2};
    std::optional<ContourElement> offset_of;  // equidistant of this programmed line
    std::optional<ExactPoint> centre;         // transition circle
    FT side_radius;
  };
  const std::vector<Element>& elements() const { return elements_; }

  // An output line; `offset_of` names the programmed block for an equidistant.
  static Element line_element(int line, const ExactPoint& from, const ExactPoint& to, const ContourElement* offset_of,
                              const FT& side_radius, PlaneAxes axes);
  static Element circle_element(int line, const ExactPoint& from, const ExactPoint& to, const ExactPoint& centre,
                                const FT& side_radius, PlaneAxes axes);
  // In output order; kept only for the checks (keep_elements), else memory would grow with the
  // program (each exact point holds its whole construction).
  void add(const Element& e) {
    if (keep_) elements_.push_back(e);
  }
  void keep_elements(bool keep) { keep_ = keep; }

 private:
  std::vector<Element> elements_;
  bool keep_ = true;
};

}  // namespace cutcom::ref

namespace cutcom::ref {
// Runs a program and hands over ref's exact path (metamorphic checks).
bool run_exact(BlockSource& blocks, const MachineData& md, PathSink& sink, ExactPath& path);
}  // namespace cutcom::ref
