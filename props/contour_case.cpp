#include "contour_case.hpp"

#include <fmt/format.h>

namespace cutcom::props {

std::string fixed(std::int64_t units, int decimals) {
  std::uint64_t a = units < 0 ? static_cast<std::uint64_t>(-(units + 1)) + 1 : static_cast<std::uint64_t>(units);
  std::uint64_t one = 1;
  for (int i = 0; i < decimals; ++i) one *= 10;
  return fmt::format("{}{}.{:0{}}", units < 0 ? "-" : "", a / one, a % one, decimals);
}

namespace {
// The corner mode of a contour block, and the new side where it changes.
std::string side_word(const Step& s, bool right) {
  std::string w = s.g451 ? "G451" : "G450";
  if (s.flip) w += right ? " G42" : " G41";
  return w;
}
}  // namespace

std::string to_program(const ContourCase& c) {
  // Plane axes: abscissa / ordinate / applicate letters for G17, G18, G19.
  const char* a = c.plane == 17 ? "X" : c.plane == 18 ? "Z" : "Y";
  const char* b = c.plane == 17 ? "Y" : c.plane == 18 ? "X" : "Z";
  const char* h = c.plane == 17 ? "Z" : c.plane == 18 ? "Y" : "X";
  std::string p = fmt::format("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={}\n", fixed(c.radius_um, c.decimals));
  int n = 10;
  p += fmt::format("N{} G{} G90 G0 {}{} {}{} {}0 T1 D1\n", n, c.plane, a, fixed(c.start_x, c.decimals), b,
                   fixed(c.start_y, c.decimals), h);
  n += 10;
  p += fmt::format("N{} G1 {} {} {} G{} {} {}{} {}{} F500\n", n, c.right ? "G42" : "G41",
                   c.kont_select ? "KONT" : "NORM", c.g451_select ? "G451" : "G450", c.edge_select,
                   c.cdon ? "CDON" : "CDOF", a, fixed(c.first_x, c.decimals), b, fixed(c.first_y, c.decimals));
  std::int64_t x = c.first_x, y = c.first_y;
  bool right = c.right;
  int depth = 0;
  for (const Step& s : c.steps) {
    for (int k = 0; k < s.dummies; ++k) {
      n += 10;
      p += k % 2 == 0 ? fmt::format("N{} G1 {}-{}\n", n, h, ++depth) : fmt::format("N{} M8\n", n);
    }
    x += s.dx, y += s.dy;
    if (s.flip) right = !right;
    n += 10;
    if (s.arc && s.cr != 0) {
      p += fmt::format("N{} {} {}{} {}{} CR={} {}\n", n, s.ccw ? "G3" : "G2", a, fixed(x, c.decimals), b,
                       fixed(y, c.decimals), fixed(s.cr, c.decimals), side_word(s, right));
    } else if (s.arc) {
      // Centre words of the plane: I/J (G17), K/I (G18), J/K (G19).
      const char* ci = c.plane == 17 ? "I" : c.plane == 18 ? "K" : "J";
      const char* cj = c.plane == 17 ? "J" : c.plane == 18 ? "I" : "K";
      p += fmt::format("N{} {} {}{} {}{} {}{} {}{} {}\n", n, s.ccw ? "G3" : "G2", a, fixed(x, c.decimals), b,
                       fixed(y, c.decimals), ci, fixed(s.ci, c.decimals), cj, fixed(s.cj, c.decimals),
                       side_word(s, right));
    } else {
      p += fmt::format("N{} G1 {}{} {}{} {}\n", n, a, fixed(x, c.decimals), b, fixed(y, c.decimals),
                       side_word(s, right));
    }
  }
  n += 10;
  p += fmt::format("N{} G1 G40 {} {} G{} {}{} {}{}\n", n, c.kont_deselect ? "KONT" : "NORM",
                   c.g451_deselect ? "G451" : "G450", c.edge_deselect, a, fixed(c.end_x, c.decimals), b,
                   fixed(c.end_y, c.decimals));
  p += fmt::format("N{} M30\n", n + 10);
  return p;
}

void showValue(const ContourCase& c, std::ostream& os) {
  os << "style " << c.style << ", MD20210=" << c.md20210 << " MD20230=" << c.md20230 << " MD20240=" << c.md20240 << "\n"
     << to_program(c);
}

}  // namespace cutcom::props
