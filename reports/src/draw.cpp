#include "geomcheck/reports/draw.hpp"

#include "geomcheck/collide_cylinder_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <type_traits>
#include <vector>

#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck::draw {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRim = 48;

// A shape as the views see it: point groups whose projected convex hull is
// the shape's silhouette, and polylines drawn over it.
struct Figure {
  std::vector<std::vector<Vec3>> hulls;
  std::vector<std::pair<std::vector<Vec3>, bool>> lines;  // points, closed
};

std::vector<Vec3> circle(Vec3 c, Vec3 e1, Vec3 e2, double r) {
  std::vector<Vec3> v;
  for (int i = 0; i < kRim; ++i) {
    const double a = 2 * kPi * i / kRim;
    v.push_back(c + (r * std::cos(a)) * e1 + (r * std::sin(a)) * e2);
  }
  return v;
}

// Ball samples whose projection onto any coordinate plane has the disc as hull.
std::vector<Vec3> ball(Vec3 c, double r) {
  std::vector<Vec3> v;
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  for (auto [e1, e2] : {std::pair{x, y}, std::pair{x, z}, std::pair{y, z}}) {
    const auto s = circle(c, e1, e2, r);
    v.insert(v.end(), s.begin(), s.end());
  }
  return v;
}

Figure figure(const Cylinder& c) {
  Figure f;
  const Vec3 d = c.q - c.p;
  const double l = length(d);
  const Vec3 u = l > 0 && std::isfinite(l) ? (1.0 / l) * d : Vec3{0, 0, 1};
  const Vec3 e1 = any_perpendicular(u), e2 = cross(u, e1);
  auto r1 = circle(c.p, e1, e2, c.r), r2 = circle(c.q, e1, e2, c.r);
  std::vector<Vec3> all = r1;
  all.insert(all.end(), r2.begin(), r2.end());
  f.hulls.push_back(all);
  f.lines.push_back({r1, true});
  f.lines.push_back({r2, true});
  f.lines.push_back({{c.p, c.q}, false});  // the axis
  return f;
}
Figure figure(const Sphere& s) {
  Figure f;
  f.hulls.push_back(ball(s.c, s.r));
  return f;
}
Figure figure(const Segment& s) {
  Figure f;
  f.lines.push_back({{s.a, s.b}, false});
  return f;
}
Figure figure(const Capsule& c) {
  Figure f;
  auto v = ball(c.p, c.r), w = ball(c.q, c.r);
  v.insert(v.end(), w.begin(), w.end());
  f.hulls.push_back(v);
  f.lines.push_back({{c.p, c.q}, false});
  return f;
}
Figure figure(const MovingSphere& m) {
  Figure f;
  f.hulls.push_back(ball(m.c, m.r));  // the start
  auto v = ball(m.c, m.r), w = ball(m.c + m.delta, m.r);
  v.insert(v.end(), w.begin(), w.end());
  f.lines.push_back({{m.c, m.c + m.delta}, false});  // the path of the centre
  f.hulls.push_back(v);                               // the swept volume
  return f;
}
Figure figure(const Obb& b) {
  Figure f;
  std::vector<Vec3> k;
  for (int i = 0; i < 8; ++i)
    k.push_back(b.c + ((i & 1 ? 1 : -1) * b.e.x) * b.axes[0] + ((i & 2 ? 1 : -1) * b.e.y) * b.axes[1] +
                ((i & 4 ? 1 : -1) * b.e.z) * b.axes[2]);
  f.hulls.push_back(k);
  for (int i = 0; i < 8; ++i)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(i & bit)) f.lines.push_back({{k[i], k[i | bit]}, false});
  return f;
}
Figure figure(const Triangle& t) {
  Figure f;
  f.hulls.push_back({t.a, t.b, t.c});
  f.lines.push_back({{t.a, t.b, t.c}, true});
  return f;
}

struct P2 { double x, y; };
double cross2(P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

std::vector<P2> hull2(std::vector<P2> p) {  // Andrew's monotone chain
  std::sort(p.begin(), p.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  std::vector<P2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

struct View {
  const char* name;
  int i, j;  // coordinates shown: 0 x, 1 y, 2 z
  const char* axes;
};
constexpr View kViews[] = {{"top", 0, 1, "x \u2192, y \u2191"}, {"front", 0, 2, "x \u2192, z \u2191"}, {"side", 1, 2, "y \u2192, z \u2191"}};

double coord(Vec3 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", x);
  return b;
}

std::string fmt3(double x) { return report::readable(x, 3); }

bool finite3(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A fourth panel where the marks (the subject's answer, the truth's
// witness, a peer's answer) lie closer together than the views can show
// (under 1/50 of the scene): a window four times their spread around their
// centre, in the view that separates them most, with a scale bar. Only the
// marks are drawn there: the shapes' outlines are sampled polygons, not
// exact at that zoom.
std::string zoom(const std::vector<Mark>& marks, double span_all, double W) {
  std::vector<Vec3> pts;
  for (const Mark& m : marks) {
    if (finite3(m.p)) pts.push_back(m.p);
    if ((m.kind == Mark::Kind::Segment || m.kind == Mark::Kind::Arrow) && finite3(m.q)) pts.push_back(m.q);
  }
  double spread = 0;
  int best = 0;
  double best_sep = -1;
  for (int k = 0; k < 3; ++k) {
    double sep = 0;
    for (const Vec3& a : pts)
      for (const Vec3& b : pts) {
        spread = std::max(spread, length(a - b));
        sep = std::max(sep, std::hypot(coord(a, kViews[k].i) - coord(b, kViews[k].i),
                                       coord(a, kViews[k].j) - coord(b, kViews[k].j)));
      }
    if (sep > best_sep) best_sep = sep, best = k;
  }
  if (pts.size() < 2 || !(spread > 0) || !std::isfinite(spread) || !(spread < span_all / 50)) return "";
  const View& v = kViews[best];
  double cx = 0, cy = 0;
  for (const Vec3& p : pts) cx += coord(p, v.i) / pts.size(), cy += coord(p, v.j) / pts.size();
  const double window = 4 * spread, s = W / window;
  auto X = [&](double a) { return W / 2 + (a - cx) * s; };
  auto Y = [&](double b) { return W / 2 - (b - cy) * s; };
  std::ostringstream o;
  o << "<svg width='" << W << "' height='" << W + 16 << "' role='img' viewBox='0 0 " << W << ' ' << W + 16
    << "'><title>zoom at the contact</title><rect x='0' y='0' width='" << W << "' height='" << W
    << "' fill='#fff8e8' stroke='#ccc'/>";
  for (const Mark& m : marks) {
    if (!finite3(m.p)) continue;
    const double ax = X(coord(m.p, v.i)), ay = Y(coord(m.p, v.j));
    o << "<circle cx='" << num(ax) << "' cy='" << num(ay) << "' r='3' fill='" << m.color << "'/>";
    if ((m.kind == Mark::Kind::Segment || m.kind == Mark::Kind::Arrow) && finite3(m.q))
      o << "<line x1='" << num(ax) << "' y1='" << num(ay) << "' x2='" << num(X(coord(m.q, v.i))) << "' y2='"
        << num(Y(coord(m.q, v.j))) << "' stroke='" << m.color << "' stroke-width='1.5'/>";
    if (m.kind == Mark::Kind::PointNormal) {
      const double nx = coord(m.q, v.i), ny = coord(m.q, v.j);
      if (std::isfinite(nx) && std::isfinite(ny) && (nx != 0 || ny != 0))
        o << "<line x1='" << num(ax) << "' y1='" << num(ay) << "' x2='" << num(ax + 40 * nx) << "' y2='"
          << num(ay - 40 * ny) << "' stroke='" << m.color << "' stroke-width='1.5'/>";
    }
  }
  o << "<line x1='10' y1='" << W - 10 << "' x2='" << 10 + W / 4 << "' y2='" << W - 10
    << "' stroke='#333' stroke-width='2'/><text x='10' y='" << W - 14 << "' font-size='10'>" << fmt3(window / 4)
    << "</text><text x='4' y='" << W + 12 << "' font-size='10'>zoom, " << v.name << " (" << v.axes
    << "): the marks " << fmt3(spread) << " apart</text></svg>";
  return o.str();
}

std::string render(const Figure (&shapes)[2], const std::vector<Mark>& marks, const std::string& title) {
  static const char* kFill[2] = {"rgba(60,110,200,0.25)", "rgba(230,140,30,0.25)"};
  static const char* kStroke[2] = {"#2c5aa0", "#c06a00"};
  constexpr double W = 220, M = 12;
  std::ostringstream o;
  o << "<figure class='cx'><figcaption>" << report::readable_numbers(title) << "</figcaption>";
  // Fit: each view centred on the bounds of its finite projected points, one
  // scale for all three (the largest span of any view fits), so that the
  // views can be compared.
  double lo_of[3][2], hi_of[3][2], span_all = -INFINITY;
  for (int k = 0; k < 3; ++k) {
    const View& v = kViews[k];
    double* lo = lo_of[k];
    double* hi = hi_of[k];
    lo[0] = lo[1] = INFINITY, hi[0] = hi[1] = -INFINITY;
    auto grow = [&](Vec3 p) {
      const double a = coord(p, v.i), b = coord(p, v.j);
      if (!std::isfinite(a) || !std::isfinite(b)) return;
      lo[0] = std::min(lo[0], a), hi[0] = std::max(hi[0], a), lo[1] = std::min(lo[1], b), hi[1] = std::max(hi[1], b);
    };
    for (const Figure& f : shapes) {
      for (const auto& h : f.hulls)
        for (Vec3 p : h) grow(p);
      for (const auto& l : f.lines)
        for (Vec3 p : l.first) grow(p);
    }
    for (const Mark& m : marks) {
      if (!finite3(m.p)) continue;
      grow(m.p);
      if (m.kind == Mark::Kind::Arrow || m.kind == Mark::Kind::Segment) grow(m.q);
    }
    const double span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (span >= 0 && std::isfinite(span)) span_all = std::max(span_all, span);
  }
  for (int k = 0; k < 3; ++k) {
    const View& v = kViews[k];
    const double* lo = lo_of[k];
    const double* hi = hi_of[k];
    o << "<svg width='" << W << "' height='" << W + 16 << "' role='img' viewBox='0 0 " << W << ' ' << W + 16
      << "'><title>" << v.name << " view</title><rect x='0' y='0' width='" << W << "' height='" << W
      << "' fill='#fafafa' stroke='#ccc'/>";
    const double span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(span >= 0) || !std::isfinite(span)) {
      o << "<text x='10' y='110' font-size='11'>nothing finite to draw</text></svg>";
      continue;
    }
    const double s = span_all > 0 ? (W - 2 * M) / span_all : 1;
    const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    auto X = [&](double a) { return W / 2 + (a - cx) * s; };
    auto Y = [&](double b) { return W / 2 - (b - cy) * s; };
    auto pt = [&](Vec3 p) { return P2{X(coord(p, v.i)), Y(coord(p, v.j))}; };
    auto finite = [](P2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    for (int k = 0; k < 2; ++k) {
      for (const auto& h : shapes[k].hulls) {
        std::vector<P2> q;
        for (Vec3 p : h)
          if (finite(pt(p))) q.push_back(pt(p));
        const auto hh = hull2(q);
        o << "<polygon fill='" << kFill[k] << "' stroke='" << kStroke[k] << "' stroke-width='1' points='";
        for (P2 p : hh) o << num(p.x) << ',' << num(p.y) << ' ';
        o << "'/>";
      }
      for (const auto& [pts, closed] : shapes[k].lines) {
        o << "<" << (closed ? "polygon" : "polyline") << " fill='none' stroke='" << kStroke[k]
          << "' stroke-width='0.8' stroke-dasharray='3,2' points='";
        for (Vec3 p : pts)
          if (finite(pt(p))) o << num(pt(p).x) << ',' << num(pt(p).y) << ' ';
        o << "'/>";
      }
    }
    for (const Mark& m : marks) {
      if (!finite3(m.p) || !finite(pt(m.p))) continue;  // a legend entry only
      const P2 a = pt(m.p);
      auto line = [&](P2 b) {
        if (finite(b))
          o << "<line x1='" << num(a.x) << "' y1='" << num(a.y) << "' x2='" << num(b.x) << "' y2='" << num(b.y)
            << "' stroke='" << m.color << "' stroke-width='1.5'/>";
      };
      o << "<circle cx='" << num(a.x) << "' cy='" << num(a.y) << "' r='3' fill='" << m.color << "'/>";
      switch (m.kind) {
        case Mark::Kind::PointNormal: {
          const double nx = coord(m.q, v.i), ny = coord(m.q, v.j);
          if (std::isfinite(nx) && std::isfinite(ny) && (nx != 0 || ny != 0)) line({a.x + 40 * nx, a.y - 40 * ny});
          break;
        }
        case Mark::Kind::Arrow:
          line(pt(m.q));
          break;
        case Mark::Kind::Segment:
          line(pt(m.q));
          if (finite(pt(m.q)))
            o << "<circle cx='" << num(pt(m.q).x) << "' cy='" << num(pt(m.q).y) << "' r='2.5' fill='" << m.color << "'/>";
          break;
        case Mark::Kind::Ball:
          if (std::isfinite(m.r * s))
            o << "<circle cx='" << num(a.x) << "' cy='" << num(a.y) << "' r='" << num(m.r * s) << "' fill='none' stroke='"
              << m.color << "' stroke-width='1.2' stroke-dasharray='4,2'/>";
          break;
      }
    }
    o << "<text x='4' y='" << W + 12 << "' font-size='10'>" << v.name << " (" << v.axes << "), 1 unit = " << fmt3(s)
      << " px</text></svg>";
  }
  o << zoom(marks, span_all, W);
  o << "<p class='legend'><span style='color:#2c5aa0'>&#9632; A</span> <span style='color:#c06a00'>&#9632; B</span>";
  for (const Mark& m : marks)
    if (!m.label.empty()) o << "<br><span style='color:" << m.color << "'>&#9679; " << report::readable_numbers(m.label) << "</span>";
  o << "</p></figure>";
  return o.str();
}

std::string fmt(double x) { return report::readable(x, 6); }
}  // namespace

Answer answer_of(const Contact& k, const std::string& who) {
  return {k.hit, k.point, k.normal,
          k.hit ? who + ": contact, depth " + fmt(k.depth) + " (point and normal)" : who + ": no contact"};
}
Answer answer_of(const CastHit& h, const std::string& who) {
  return {h.hit, h.point, h.normal, h.hit ? who + ": hit at t = " + fmt(h.t) + " (point and normal)" : who + ": miss"};
}

namespace {

constexpr const char* kOracleColour = "#080";
const Vec3 kNowhere{NAN, NAN, NAN};  // a mark with a legend entry only

Vec3 dbl(const oracle::QVec& v) { return {oracle::to_double(v.x), oracle::to_double(v.y), oracle::to_double(v.z)}; }

// The cylinder's farthest point along unit u, in doubles (for drawing only).
Vec3 cylinder_support(const Cylinder& c, Vec3 u) {
  const Vec3 d = c.q - c.p;
  const Vec3 end = dot(d, u) >= 0 ? c.q : c.p;
  const double l2 = dot(d, d);
  const Vec3 radial = l2 > 0 ? u - (dot(u, d) / l2) * d : u;
  const double rl = length(radial);
  return rl > 0 ? end + (c.r / rl) * radial : end;
}

std::vector<Mark> engine_witness(const oracle::ConvexShape& a, const oracle::ConvexShape& b, const Cylinder* cyl,
                                 const Vec3* hint) {
  oracle::EngineOptions opt;
  opt.rel_width = 1e-12;
  oracle::DistanceResult d = oracle::classify(a, b, opt);
  if (d.verdict == oracle::Verdict::Separated && !(d.witness_a && d.witness_b)) {
    opt.filter = false;  // the interval filter decides without points: GJK in rationals gives them
    d = oracle::classify(a, b, opt);
  }
  switch (d.verdict) {
    case oracle::Verdict::Separated:
      if (d.witness_a && d.witness_b)
        return {{Mark::Kind::Segment, dbl(*d.witness_a), dbl(*d.witness_b), 0, kOracleColour,
                 "oracle: nearest points, distance " + fmt(oracle::to_double(d.distance.mid()))}};
      return {{Mark::Kind::Segment, kNowhere, kNowhere, 0, kOracleColour, "oracle: separated"}};
    case oracle::Verdict::Touching:
      return {{Mark::Kind::PointNormal, d.common_point ? dbl(*d.common_point) : kNowhere, Vec3{}, 0, kOracleColour,
               "oracle: touching (a common point)"}};
    case oracle::Verdict::Overlapping: {
      const oracle::PenetrationResult pd = oracle::penetration(a, b, 1e-20);
      const Vec3 dir = dbl(pd.direction);
      const double len = length(dir), depth = oracle::to_double(pd.depth.mid());
      const bool have_dir = pd.overlapping && len > 0 && std::isfinite(depth);
      // A point certified in both: the engine's, else the first candidate
      // that passes the exact test (production's point, the middle of the
      // translation from A's extreme point along the direction).
      std::vector<Vec3> candidates;
      if (d.common_point) candidates.push_back(dbl(*d.common_point));
      if (hint) candidates.push_back(*hint);
      Vec3 extreme = kNowhere;
      if (have_dir && cyl) {
        extreme = cylinder_support(*cyl, (1 / len) * dir);
        candidates.push_back(extreme - (0.5 * depth / len) * dir);
      }
      Vec3 common = kNowhere;
      for (Vec3 x : candidates)
        if (finite3(x) && oracle::check_common_point(a, b, oracle::to_q(x))) {
          common = x;
          break;
        }
      if (!have_dir)
        return {{Mark::Kind::PointNormal, common, Vec3{}, 0, kOracleColour, "oracle: overlapping (a certified common point)"}};
      const Vec3 from = finite3(common) ? common : extreme;
      return {{Mark::Kind::Arrow, from, from + (depth / len) * dir, 0, kOracleColour,
               std::string("oracle: overlapping, depth ") + fmt(depth) + "; B's minimal translation out, drawn from " +
                   (finite3(common) ? "a certified common point" : "A's extreme point along it")}};
    }
    default:
      return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: undecided"}};
  }
}

template <class A, class B>
std::vector<Mark> collide_witness(const A& a, const B& b, const Vec3* hint) {
  if (!is_valid(a) || !is_valid(b)) return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: invalid input"}};
  const Cylinder* cyl = nullptr;
  if constexpr (std::is_same_v<A, Cylinder>) cyl = &a;
  return engine_witness(oracle::make_shape(a), oracle::make_shape(b), cyl, hint);
}

}  // namespace

namespace {

std::vector<Mark> cast_witness(const Segment& s, const Cylinder& c) {
  if (!is_valid(s) || !is_valid(c)) return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: invalid input"}};
  const oracle::CastTruth t = oracle::solve_cast(s, c);
  if (!t.hit) return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: miss"}};
  const double tm = oracle::to_double(t.t.mid());
  return {{Mark::Kind::PointNormal, s.a + tm * (s.b - s.a), Vec3{}, 0, kOracleColour,
           std::string("oracle: first touch S(t), t = ") + fmt(tm) + " (" + oracle::to_string(t.feature) + ")"}};
}

std::vector<Mark> sweep_witness(const MovingSphere& m, const Cylinder& c) {
  if (!is_valid(m) || !is_valid(c)) return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: invalid input"}};
  const oracle::ImpactResult r =
      oracle::time_of_impact(oracle::make_shape(Sphere{m.c, m.r}), oracle::to_q(m.delta), oracle::make_shape(c));
  switch (r.kind) {
    case oracle::ImpactResult::Kind::Hit: {
      const double t = oracle::to_double(r.t.mid());
      return {{Mark::Kind::Ball, m.c + t * m.delta, Vec3{}, m.r, kOracleColour, "oracle: the ball at its first touch, t = " + fmt(t)}};
    }
    case oracle::ImpactResult::Kind::StartsInside:
      return {{Mark::Kind::Ball, m.c, Vec3{}, m.r, kOracleColour, "oracle: the ball starts in contact (t = 0)"}};
    case oracle::ImpactResult::Kind::NoHit:
      return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: miss"}};
    default:
      return {{Mark::Kind::PointNormal, kNowhere, Vec3{}, 0, kOracleColour, "oracle: undecided"}};
  }
}

}  // namespace

template <QueryId Q>
Answer production_answer(const typename QueryTraits<Q>::Case& c) {
  const auto& impl = production_of<Q>();
  if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) return answer_of(impl.collide(c.a, c.b), "production");
  else if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) return answer_of(impl.cast(c.a, c.b), "production");
  else return answer_of(impl.sweep(c.a, c.b), "production");
}

template <QueryId Q>
std::vector<Mark> oracle_witness(const typename QueryTraits<Q>::Case& c, const Vec3* hint) {
  if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) return collide_witness(c.a, c.b, hint);
  else if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) return cast_witness(c.a, c.b);
  else return sweep_witness(c.a, c.b);
}

template <class Case>
std::string views(const Case& c, const std::string& title, const std::vector<Mark>& extra, const Answer* answer) {
  constexpr QueryId Q = query_of_case<Case>;
  const Figure shapes[2] = {figure(c.a), figure(c.b)};
  const Answer ans = answer ? *answer : production_answer<Q>(c);
  std::vector<Mark> marks{{Mark::Kind::PointNormal, ans.hit ? ans.point : kNowhere, ans.normal, 0, "#d00", ans.label}};
  for (const Mark& m : oracle_witness<Q>(c, ans.hit ? &ans.point : nullptr)) marks.push_back(m);
  marks.insert(marks.end(), extra.begin(), extra.end());
  return render(shapes, marks, title);
}

#define GEOMCHECK_X(id, kind, A, B, summary)                                                                       \
  template Answer production_answer<QueryId::id>(const PairCase<A, B, QueryId::id>&);                                        \
  template std::vector<Mark> oracle_witness<QueryId::id>(const PairCase<A, B, QueryId::id>&, const Vec3*);                   \
  template std::string views(const PairCase<A, B, QueryId::id>&, const std::string&, const std::vector<Mark>&,  \
                             const Answer*);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

std::string mesh_views(const Cylinder& cyl, const TriangleMesh& mesh, const Contact& k, std::uint32_t face,
                       const std::string& who, const std::string& title) {
  Figure faces;
  const double size = std::max(max_abs(cyl.q - cyl.p), cyl.r);
  const double grow = std::isfinite(size) ? 2 * size : 0;
  const bool has_face = k.hit && mesh.valid() && face < mesh.size();
  std::size_t drawn = 0;
  auto add = [&](const Triangle& t) {
    faces.hulls.push_back({t.a, t.b, t.c});
    faces.lines.push_back({{t.a, t.b, t.c}, true});
    ++drawn;
  };
  if (has_face) add(mesh.triangle(face));  // the answer's face, whatever the count
  for (std::size_t i = 0; mesh.valid() && i < mesh.size() && drawn < 400; ++i) {
    if (has_face && i == face) continue;
    const Triangle t = mesh.triangle(i);
    bool near = true;
    for (int c = 0; c < 3 && near; ++c) {
      auto at = [c](Vec3 v) { return c == 0 ? v.x : c == 1 ? v.y : v.z; };
      const double lo = std::min(at(cyl.p), at(cyl.q)) - cyl.r - grow, hi = std::max(at(cyl.p), at(cyl.q)) + cyl.r + grow;
      near = !(std::max({at(t.a), at(t.b), at(t.c)}) < lo || std::min({at(t.a), at(t.b), at(t.c)}) > hi);
    }
    if (near) add(t);
  }
  const Figure shapes[2] = {figure(cyl), faces};
  const Answer ans = answer_of(k, who);
  std::vector<Mark> marks{{Mark::Kind::PointNormal, ans.hit ? ans.point : kNowhere, ans.normal, 0, "#d00",
                           ans.label + (has_face ? ", face " + std::to_string(face) : std::string())}};
  if (has_face) {
    const Triangle t = mesh.triangle(face);
    const Vec3 v[3] = {t.a, t.b, t.c};
    for (int e = 0; e < 3; ++e)
      marks.push_back({Mark::Kind::Segment, v[e], v[(e + 1) % 3], 0, "#d00", e == 0 ? "face " + std::to_string(face) + " (red edges)" : ""});
    for (const Mark& m : collide_witness(cyl, t, &ans.point)) marks.push_back(m);
  }
  return render(shapes, marks,
                title + " (" + std::to_string(drawn) + " of " + std::to_string(mesh.size()) + " faces drawn)");
}

}  // namespace geomcheck::draw
