#include "contour_case.hpp"

#include <fmt/format.h>

namespace cutcom::props {

std::string micrometres(std::int64_t um) {
  std::uint64_t a = um < 0 ? static_cast<std::uint64_t>(-(um + 1)) + 1 : static_cast<std::uint64_t>(um);
  return fmt::format("{}{}.{:03}", um < 0 ? "-" : "", a / 1000, a % 1000);
}

std::string to_program(const ContourCase& c) {
  // Plane axes: abscissa / ordinate / applicate letters for G17, G18, G19.
  const char* a = c.plane == 17 ? "X" : c.plane == 18 ? "Z" : "Y";
  const char* b = c.plane == 17 ? "Y" : c.plane == 18 ? "X" : "Z";
  const char* h = c.plane == 17 ? "Z" : c.plane == 18 ? "Y" : "X";
  std::string p = fmt::format("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={}\n", micrometres(c.radius_um));
  int n = 10;
  p += fmt::format("N{} G{} G90 G0 {}{} {}{} {}0 T1 D1\n", n, c.plane, a, micrometres(c.start_x), b,
                   micrometres(c.start_y), h);
  n += 10;
  p += fmt::format("N{} G1 {} {}{} {}{} F500\n", n, c.right ? "G42" : "G41", a, micrometres(c.first_x), b,
                   micrometres(c.first_y));
  std::int64_t x = c.first_x, y = c.first_y;
  int depth = 0;
  for (const Step& s : c.steps) {
    for (int k = 0; k < s.dummies; ++k) {
      n += 10;
      p += k % 2 == 0 ? fmt::format("N{} {}-{}\n", n, h, ++depth) : fmt::format("N{} M8\n", n);
    }
    x += s.dx, y += s.dy;
    n += 10;
    p += fmt::format("N{} {}{} {}{} {}\n", n, a, micrometres(x), b, micrometres(y), s.g451 ? "G451" : "G450");
  }
  n += 10;
  p += fmt::format("N{} G40 {}{} {}{}\n", n, a, micrometres(c.end_x), b, micrometres(c.end_y));
  p += fmt::format("N{} M30\n", n + 10);
  return p;
}

void showValue(const ContourCase& c, std::ostream& os) {
  os << "style " << c.style << ", MD20210=" << c.md20210 << " MD20230=" << c.md20230 << "\n" << to_program(c);
}

}  // namespace cutcom::props
