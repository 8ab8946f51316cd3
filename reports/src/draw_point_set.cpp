// geomcheck — a point set and a subject's triangles drawn (draw.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "geomcheck/reports/draw.hpp"

namespace geomcheck::draw {

std::string point_set_view(const std::vector<Vec2>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                           const std::string& title) {
  constexpr double W = 520, pad = 14;
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Vec2& p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  std::ostringstream o;
  o << "<figure><figcaption>" << title << "</figcaption>";
  if (!(x0 <= x1)) return o.str() + "<p>no finite point to draw</p></figure>";
  // Scaled in long double, so that sets of huge or tiny coordinates fit too.
  const long double span = std::max<long double>({(long double)x1 - x0, (long double)y1 - y0, 1e-300L});
  const long double s = (W - 2 * pad) / span;
  auto X = [&](double x) { return static_cast<double>(pad + ((long double)x - x0) * s); };
  auto Y = [&](double y) { return static_cast<double>(W - pad - ((long double)y - y0) * s); };
  char buf[160];
  o << "<svg width='" << W << "' height='" << W << "' role='img' viewBox='0 0 " << W << ' ' << W
    << "'><rect x='0' y='0' width='" << W << "' height='" << W << "' fill='#f8fbff' stroke='#ccc'/>";
  for (const auto& t : triangles) {
    if (t[0] >= points.size() || t[1] >= points.size() || t[2] >= points.size()) continue;
    o << "<polygon points='";
    for (std::uint32_t v : t) {
      std::snprintf(buf, sizeof buf, "%.2f,%.2f ", X(points[v].x), Y(points[v].y));
      o << buf;
    }
    o << "' fill='#ffd8a8' fill-opacity='0.45' stroke='#c05000' stroke-width='0.8'/>";
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    std::snprintf(buf, sizeof buf, "<circle cx='%.2f' cy='%.2f' r='2.5' fill='#1f4e9a'><title>%zu: (%.17g, %.17g)</title></circle>",
                  X(p.x), Y(p.y), i, p.x, p.y);
    o << buf;
  }
  o << "</svg><p>" << points.size() << " points (blue; hover for index and coordinates), " << triangles.size()
    << " triangles (orange)</p></figure>";
  return o.str();
}

}  // namespace geomcheck::draw
