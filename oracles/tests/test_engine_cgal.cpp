// Cross-check of the certified convex engine against CGAL's exact kernel on
// the polyhedral pairs (point, segment, triangle, box = parallelepiped).
//
// For every pair the exact truth is computed with CGAL (Epeck, exact
// constructions):
//   * intersect   do_intersect (a box is split into six Kuhn tetrahedra,
//                 Tetrahedron_3 is a solid in CGAL's do_intersect);
//   * distance    for disjoint pairs, the exact squared distance: CGAL's own
//                 squared_distance where 5.5 has it (point-point/segment/
//                 triangle/tetrahedron, segment-segment, triangle-triangle),
//                 and everywhere the vertex-shape / edge-edge decomposition
//                 (closest pairs of disjoint polytopes are vertex-face,
//                 face-vertex or edge-edge), the two compared;
//   * depth       for intersecting pairs, the convex hull of the Minkowski
//                 difference A - B (CGAL convex_hull_3): the origin strictly
//                 inside it <=> Overlapping, and the penetration depth is the
//                 distance from the origin to the nearest hull facet plane;
//                 otherwise the signed distance is exactly 0 (Touching).
// The engine (with and without its double filter) must give the verdict of
// the truth (Undecided only where |distance| < 2^-200 * scale and its
// interval holds the true value), a distance interval holding the exact
// signed distance (checked squared, in rationals), and certificates that the
// engine's own check functions accept AND that hold independently (CGAL
// containment, CGAL orientation, an independent exact support function).
// Forged certificates (tilted/cutting directions, points pushed outside by
// one ulp or 2^-60) must be rejected exactly when the independent exact
// computation says they are invalid. For overlapping pairs penetration()'s
// depth enclosure must hold the exact depth; time_of_impact() is checked
// against an exact ray cast into the hull of A - B.
//
// Inputs: random doubles in [-2, 2] (fixed seeds), exact touching
// constructions on a dyadic grid, and the same moved by one ulp / 2^-50 /
// 2^-40 (~1e-12). Every failure prints the inputs as hex floats (%a).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <array>
#include <optional>
#include <stdexcept>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/oracles/engine.hpp"

using namespace geomcheck;
using namespace geomcheck::oracle;

namespace {

/// The engine without its interval filter: the rational rounds decide.
EngineOptions without_filter() {
  EngineOptions o;
  o.filter = false;
  return o;
}

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using P3 = K::Point_3;
using V3 = K::Vector_3;
using Seg3 = K::Segment_3;
using Tri3 = K::Triangle_3;
using Tet3 = K::Tetrahedron_3;

// ---- exact conversions between CGAL and Q -------------------------------------------

template <boost::multiprecision::expression_template_option E>
Q q_of_exact(const boost::multiprecision::number<boost::multiprecision::gmp_rational, E>& x) {
  return Q(x.backend().data());
}
#ifdef CGAL_USE_GMPXX
[[maybe_unused]] Q q_of_exact(const mpq_class& x) { return Q(x.get_mpq_t()); }
#endif
#ifdef CGAL_USE_GMP
[[maybe_unused]] Q q_of_exact(const CGAL::Gmpq& x) { return Q(x.mpq()); }
#endif

Q qft(const FT& x) { return q_of_exact(CGAL::exact(x)); }
FT ftq(const Q& q) {
  using EX = std::decay_t<decltype(CGAL::exact(std::declval<const FT&>()))>;
  return FT(EX(q.backend().data()));
}
P3 p3(const QVec& v) { return P3(ftq(v.x), ftq(v.y), ftq(v.z)); }
P3 p3(Vec3 v) { return P3(v.x, v.y, v.z); }

// ---- printing -------------------------------------------------------------------------

std::string hex(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}
std::string hex(Vec3 v) { return "{" + hex(v.x) + ", " + hex(v.y) + ", " + hex(v.z) + "}"; }
std::string qs(const Q& q) {
  std::ostringstream o;
  o << q << " (~" << to_double(q) << ")";
  return o.str();
}
std::string qs(const QVec& v) { return "(" + qs(v.x) + ", " + qs(v.y) + ", " + qs(v.z) + ")"; }

// ---- the test's shapes -----------------------------------------------------------------

struct Shape {
  enum class T { Point, Segment, Triangle, Box } t = T::Point;
  Vec3 v[3];  // point: v[0]; segment: v[0], v[1]; triangle: v[0..2]
  Obb box;
};

Shape point_shape(Vec3 a) {
  Shape s;
  s.t = Shape::T::Point;
  s.v[0] = a;
  return s;
}
Shape segment_shape(Vec3 a, Vec3 b) {
  Shape s;
  s.t = Shape::T::Segment;
  s.v[0] = a;
  s.v[1] = b;
  return s;
}
Shape triangle_shape(Vec3 a, Vec3 b, Vec3 c) {
  Shape s;
  s.t = Shape::T::Triangle;
  s.v[0] = a;
  s.v[1] = b;
  s.v[2] = c;
  return s;
}
Shape box_shape(const Obb& b) {
  Shape s;
  s.t = Shape::T::Box;
  s.box = b;
  return s;
}

std::string show(const Shape& s) {
  switch (s.t) {
    case Shape::T::Point: return "make_point(" + hex(s.v[0]) + ")";
    case Shape::T::Segment: return "Segment{" + hex(s.v[0]) + ", " + hex(s.v[1]) + "}";
    case Shape::T::Triangle: return "Triangle{" + hex(s.v[0]) + ", " + hex(s.v[1]) + ", " + hex(s.v[2]) + "}";
    case Shape::T::Box: {
      const Obb& b = s.box;
      return "Obb{" + hex(b.c) + ", {" + hex(b.axes[0]) + ", " + hex(b.axes[1]) + ", " + hex(b.axes[2]) + "}, " +
             hex(b.e) + "}";
    }
  }
  return "?";
}

ConvexShape engine_shape(const Shape& s) {
  switch (s.t) {
    case Shape::T::Point: return make_point(s.v[0]);
    case Shape::T::Segment: return make_shape(Segment{s.v[0], s.v[1]});
    case Shape::T::Triangle: return make_shape(Triangle{s.v[0], s.v[1], s.v[2]});
    case Shape::T::Box: return make_shape(s.box);
  }
  return make_point(s.v[0]);
}

Shape translated(const Shape& s, Vec3 t) {
  Shape o = s;
  for (Vec3& v : o.v) v = v + t;
  o.box.c = o.box.c + t;
  return o;
}

/// Exact vertices (box: bit k of the index = +e_k axes_k). Computed here in
/// rationals, independently of the engine.
std::vector<QVec> qverts(const Shape& s) {
  switch (s.t) {
    case Shape::T::Point: return {to_q(s.v[0])};
    case Shape::T::Segment: return {to_q(s.v[0]), to_q(s.v[1])};
    case Shape::T::Triangle: return {to_q(s.v[0]), to_q(s.v[1]), to_q(s.v[2])};
    case Shape::T::Box: {
      const double e[3] = {s.box.e.x, s.box.e.y, s.box.e.z};
      std::vector<QVec> out;
      for (int i = 0; i < 8; ++i) {
        QVec v = to_q(s.box.c);
        for (int k = 0; k < 3; ++k) {
          const QVec span = to_q(e[k]) * to_q(s.box.axes[k]);
          v = (i >> k & 1) ? v + span : v - span;
        }
        out.push_back(v);
      }
      return out;
    }
  }
  return {};
}

/// The shape as CGAL sees it: degenerate segments/triangles become points or
/// segments (the header's meaning of a degenerate triangle).
struct CShape {
  enum class T { Point, Segment, Triangle, Box } t = T::Point;
  std::vector<P3> v;                 // vertices (box: 8)
  std::vector<std::pair<int, int>> e;  // edges
  std::vector<Tet3> tets;            // box: the six Kuhn tetrahedra
};

/// c's first two vertices as CGAL's segment, or its point when they
/// coincide.
void set_segment_or_point(CShape& c) {
  if (c.v[0] == c.v[1]) {
    c.t = CShape::T::Point;
    c.v.resize(1);
  } else {
    c.t = CShape::T::Segment;
    c.e = {{0, 1}};
  }
}

CShape cgal_shape(const Shape& s) {
  CShape c;
  const std::vector<QVec> qv = qverts(s);
  for (const QVec& q : qv) c.v.push_back(p3(q));
  switch (s.t) {
    case Shape::T::Point: c.t = CShape::T::Point; break;
    case Shape::T::Segment: set_segment_or_point(c); break;
    case Shape::T::Triangle:
      if (!CGAL::collinear(c.v[0], c.v[1], c.v[2])) {
        c.t = CShape::T::Triangle;
        c.e = {{0, 1}, {1, 2}, {2, 0}};
      } else {
        // The longest of the three segments (or a point).
        const FT d01 = CGAL::squared_distance(c.v[0], c.v[1]), d12 = CGAL::squared_distance(c.v[1], c.v[2]),
                 d20 = CGAL::squared_distance(c.v[2], c.v[0]);
        std::vector<P3> w;
        if (d01 >= d12 && d01 >= d20) w = {c.v[0], c.v[1]};
        else if (d12 >= d20) w = {c.v[1], c.v[2]};
        else w = {c.v[2], c.v[0]};
        c.v = w;
        set_segment_or_point(c);
      }
      break;
    case Shape::T::Box: {
      c.t = CShape::T::Box;
      for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
          if (!(i >> k & 1)) c.e.push_back({i, i | 1 << k});
      const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
      for (const auto& p : perm) {
        const int a = 1 << p[0], b = a | 1 << p[1];
        // Positively oriented: CGAL 5.5's squared_distance(Point_3,
        // Tetrahedron_3) silently assumes it.
        const CGAL::Orientation o = CGAL::orientation(c.v[0], c.v[a], c.v[b], c.v[7]);
        if (o == CGAL::COPLANAR) throw std::invalid_argument("degenerate box given to the CGAL reference");
        if (o == CGAL::POSITIVE) c.tets.emplace_back(c.v[0], c.v[a], c.v[b], c.v[7]);
        else c.tets.emplace_back(c.v[a], c.v[0], c.v[b], c.v[7]);
      }
      break;
    }
  }
  return c;
}

Seg3 seg(const CShape& s) { return Seg3(s.v[0], s.v[1]); }
Tri3 tri(const CShape& s) { return Tri3(s.v[0], s.v[1], s.v[2]); }

bool contains(const CShape& s, const P3& x) {
  switch (s.t) {
    case CShape::T::Point: return s.v[0] == x;
    case CShape::T::Segment: return seg(s).has_on(x);
    case CShape::T::Triangle: return CGAL::do_intersect(tri(s), x);
    case CShape::T::Box:
      for (const Tet3& t : s.tets)
        if (!t.has_on_unbounded_side(x)) return true;
      return false;
  }
  return false;
}

template <class G>
bool box_meets(const CShape& box, const G& g) {
  for (const Tet3& t : box.tets)
    if (CGAL::do_intersect(t, g)) return true;
  return false;
}

bool cgal_intersect(const CShape& a, const CShape& b) {
  using T = CShape::T;
  if (a.t > b.t) return cgal_intersect(b, a);
  if (a.t == T::Point) return contains(b, a.v[0]);
  if (a.t == T::Segment) {
    if (b.t == T::Segment) return CGAL::do_intersect(seg(a), seg(b));
    if (b.t == T::Triangle) return CGAL::do_intersect(seg(a), tri(b));
    return box_meets(b, seg(a));
  }
  if (a.t == T::Triangle) {
    if (b.t == T::Triangle) return CGAL::do_intersect(tri(a), tri(b));
    return box_meets(b, tri(a));
  }
  for (const Tet3& t : a.tets)
    if (box_meets(b, t)) return true;
  return false;
}

/// Exact squared distance from a point to the (solid) shape.
FT point_d2(const P3& p, const CShape& s) {
  switch (s.t) {
    case CShape::T::Point: return CGAL::squared_distance(p, s.v[0]);
    case CShape::T::Segment: return CGAL::squared_distance(p, seg(s));
    case CShape::T::Triangle: return CGAL::squared_distance(p, tri(s));
    case CShape::T::Box: {
      FT m = CGAL::squared_distance(p, s.tets[0]);
      for (std::size_t i = 1; i < s.tets.size(); ++i) {
        FT d = CGAL::squared_distance(p, s.tets[i]);
        if (d < m) m = d;
      }
      return m;
    }
  }
  return 0;
}

/// Squared distance of disjoint polytopes by decomposition: vertex-shape,
/// shape-vertex and edge-edge.
Q decomposed_d2(const CShape& a, const CShape& b) {
  // (Plain comparisons, not CGAL::min: the lazy kernel then evaluates
  // exactly only the winner and the comparisons its filter cannot decide.)
  FT m = point_d2(a.v[0], b);
  auto take = [&m](const FT& d) {
    if (d < m) m = d;
  };
  for (const P3& p : a.v) take(point_d2(p, b));
  for (const P3& p : b.v) take(point_d2(p, a));
  for (const auto& ea : a.e)
    for (const auto& eb : b.e)
      take(CGAL::squared_distance(Seg3(a.v[ea.first], a.v[ea.second]), Seg3(b.v[eb.first], b.v[eb.second])));
  return qft(m);
}

/// CGAL's own squared_distance where 5.5 offers one for the pair.
std::optional<Q> direct_d2(const CShape& a, const CShape& b) {
  using T = CShape::T;
  if (a.t > b.t) return direct_d2(b, a);
  if (a.t == T::Point) return qft(point_d2(a.v[0], b));
  if (a.t == T::Segment && b.t == T::Segment) return qft(CGAL::squared_distance(seg(a), seg(b)));
  if (a.t == T::Triangle && b.t == T::Triangle) return qft(CGAL::squared_distance(tri(a), tri(b)));
  return std::nullopt;
}

/// The exact truth of a pair.
struct Truth {
  bool intersect = false;
  bool interior = false;  // origin strictly inside A - B: Overlapping
  Q d2;                   // squared distance (disjoint)
  Q depth2;               // squared penetration depth (interior)
  std::optional<Q> direct;  // CGAL's direct squared distance, if any
};

/// Facet planes of the Minkowski difference A - B = hull of the vertex
/// differences, as outward normals n and offsets h (x in A - B <=> n.x <= h
/// for every facet), exact. `full` is false when A - B is flat (dimension
/// < 3): then it has no interior.
struct MinkowskiPlanes {
  bool full = false;
  std::vector<std::pair<QVec, Q>> f;
};

MinkowskiPlanes minkowski_planes(const CShape& a, const CShape& b) {
  MinkowskiPlanes out;
  std::vector<P3> w;
  for (const P3& p : a.v)
    for (const P3& q : b.v) w.push_back(CGAL::ORIGIN + (p - q));
  // Dimension: four affinely independent points?
  std::size_t i1 = 0, i2 = 0, i3 = 0;
  for (i1 = 1; i1 < w.size() && w[i1] == w[0]; ++i1) {}
  if (i1 < w.size())
    for (i2 = i1 + 1; i2 < w.size() && CGAL::collinear(w[0], w[i1], w[i2]); ++i2) {}
  if (i1 < w.size() && i2 < w.size())
    for (i3 = i2 + 1; i3 < w.size() && CGAL::coplanar(w[0], w[i1], w[i2], w[i3]); ++i3) {}
  if (i1 >= w.size() || i2 >= w.size() || i3 >= w.size()) return out;
  out.full = true;
  CGAL::Surface_mesh<P3> hull;
  CGAL::convex_hull_3(w.begin(), w.end(), hull);
  // An interior reference point: the centroid of a full-dimensional tetrahedron.
  const QVec ref = {qft(CGAL::centroid(w[0], w[i1], w[i2], w[i3]).x()), qft(CGAL::centroid(w[0], w[i1], w[i2], w[i3]).y()),
                    qft(CGAL::centroid(w[0], w[i1], w[i2], w[i3]).z())};
  for (auto f : hull.faces()) {
    std::vector<QVec> fp;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      const P3& p = hull.point(v);
      fp.push_back({qft(p.x()), qft(p.y()), qft(p.z())});
    }
    QVec n = cross(fp[1] - fp[0], fp[2] - fp[0]);
    Q h = dot(n, fp[0]);
    if (dot(n, ref) > h) {  // the reference point must be on the inner side
      n = Q(-1) * n;
      h = -h;
    }
    out.f.emplace_back(n, h);
  }
  return out;
}

Truth exact_truth(const CShape& a, const CShape& b) {
  Truth t;
  t.intersect = cgal_intersect(a, b);
  if (!t.intersect) {
    t.d2 = decomposed_d2(a, b);
    t.direct = direct_d2(a, b);
    return t;
  }
  const MinkowskiPlanes m = minkowski_planes(a, b);
  if (!m.full) return t;  // flat: distance exactly 0
  // Origin strictly inside <=> h > 0 for every facet; the depth is the
  // distance to the nearest facet plane.
  bool first = true;
  Q best = 0;
  for (const auto& [n, h] : m.f) {
    if (h <= 0) return t;
    const Q d2 = h * h / dot(n, n);
    if (first || d2 < best) best = d2;
    first = false;
  }
  t.interior = true;
  t.depth2 = best;
  return t;
}

const char* truth_name(const Truth& t) {
  return !t.intersect ? "Separated" : (t.interior ? "Overlapping" : "Touching");
}

// ---- independent checks of the certificates ----------------------------------------

Q support(const std::vector<QVec>& v, const QVec& n) {
  Q m = dot(n, v[0]);
  for (const QVec& p : v) m = std::max(m, Q(dot(n, p)));
  return m;
}
/// Exact sign of h_A(n) + h_B(-n) for the polytopes.
int indep_sep_sign(const std::vector<QVec>& va, const std::vector<QVec>& vb, const QVec& n) {
  const Q s = support(va, n) + support(vb, Q(-1) * n);
  return s > 0 ? 1 : (s < 0 ? -1 : 0);
}
bool indep_overlap_ok(const CShape& a, const CShape& b, const OverlapCertificate& c) {
  for (int i = 0; i < 4; ++i)
    if (!contains(a, p3(c.a[i])) || !contains(b, p3(c.b[i]))) return false;
  std::array<P3, 4> w;
  for (int i = 0; i < 4; ++i) w[i] = CGAL::ORIGIN + (p3(c.a[i]) - p3(c.b[i]));
  const CGAL::Orientation s = CGAL::orientation(w[0], w[1], w[2], w[3]);
  if (s == CGAL::COPLANAR) return false;
  for (int i = 0; i < 4; ++i) {
    std::array<P3, 4> t = w;
    t[i] = CGAL::ORIGIN;
    if (CGAL::orientation(t[0], t[1], t[2], t[3]) != s) return false;
  }
  return true;
}

// ---- statistics ---------------------------------------------------------------------

struct Stats {
  int pairs = 0;
  int truth_sep = 0, truth_touch = 0, truth_over = 0;
  int undecided_at_contact = 0;
  int undecided_narrow_checked = 0;  // Undecided results held to the 2^-200 * scale width
  int by_filter = 0;
  int forged_dirs = 0, forged_dirs_rejected = 0;
  int forged_overlap = 0, forged_overlap_rejected = 0;
  int forged_points = 0, forged_points_rejected = 0;
  int genuine_certs = 0;
  int d2_direct_checked = 0;
  int penetrations = 0, penetration_wide = 0;
  double engine_ms = 0, truth_ms = 0, cert_ms = 0;
  void print(const char* name) const {
    std::printf(
        "[%s] pairs %d (truth: %d separated, %d touching, %d overlapping), %d decided by the filter, %d undecided at "
        "exact contact (%d undecided held to 2^-200 * scale wide); genuine certificates %d; forged directions %d (%d rejected), forged overlap certificates %d "
        "(%d rejected), forged common points %d (%d rejected); CGAL direct distances %d; penetration depths %d (%d "
        "wider than 1e-6 relative); engine %.0f ms, CGAL truth %.0f ms, certificate checks %.0f ms\n",
        name, pairs, truth_sep, truth_touch, truth_over, by_filter, undecided_at_contact, undecided_narrow_checked, genuine_certs, forged_dirs,
        forged_dirs_rejected, forged_overlap, forged_overlap_rejected, forged_points, forged_points_rejected,
        d2_direct_checked, penetrations, penetration_wide, engine_ms, truth_ms, cert_ms);
  }
};

std::string describe(const DistanceResult& r) {
  std::ostringstream o;
  o << "engine " << to_string(r.verdict) << " [" << qs(r.distance.lo) << ", " << qs(r.distance.hi) << "] bits " << r.bits
    << (r.by_filter ? " (filter)" : "") << " note:" << r.note;
  return o.str();
}

/// The pair being checked (for verbose reports).
std::string g_current;

/// Verdict and signed distance of one engine result against the truth.
void check_result(const DistanceResult& r, const Truth& t, const Q& scale, Stats& st) {
  SCOPED_TRACE(describe(r));
  const Q tiny = scale / Q(boost::multiprecision::mpz_int(1) << 200);
  const Q& lo = r.distance.lo;
  const Q& hi = r.distance.hi;
  EXPECT_LE(lo, hi) << "empty distance interval";
  // Undecided is narrow: its enclosure no wider than 2^-200 * scale.
  if (r.verdict == Verdict::Undecided) {
    ++st.undecided_narrow_checked;
    EXPECT_LE(hi - lo, tiny) << "Undecided with an enclosure wider than 2^-200 * scale";
  }
  if (!t.intersect) {
    // Signed distance d = sqrt(d2) > 0: lo <= d <= hi.
    const bool contains = (lo <= 0 || lo * lo <= t.d2) && hi >= 0 && t.d2 <= hi * hi;
    if (r.verdict == Verdict::Undecided) {
      EXPECT_TRUE(t.d2 < tiny * tiny && contains)
          << "Undecided for a separated pair with distance^2 " << qs(t.d2) << " (not below 2^-200 * scale)";
      return;
    }
    EXPECT_EQ(r.verdict, Verdict::Separated) << "CGAL: disjoint, distance^2 " << qs(t.d2);
    EXPECT_GE(lo, 0);
    EXPECT_TRUE(contains) << "distance interval does not hold sqrt(" << qs(t.d2) << ")";
    return;
  }
  if (!t.interior) {
    if (r.verdict == Verdict::Undecided) {
      ++st.undecided_at_contact;
      if (std::getenv("ENGINE_CGAL_VERBOSE")) std::printf("undecided at exact contact: %s | %s\n", g_current.c_str(), describe(r).c_str());
      EXPECT_TRUE(lo <= 0 && hi >= 0) << "Undecided interval misses the exact distance 0";
      return;
    }
    EXPECT_EQ(r.verdict, Verdict::Touching) << "exact signed distance is 0 (CGAL: intersecting, origin on the "
                                               "boundary of A - B or A - B flat)";
    EXPECT_TRUE(lo <= 0 && hi >= 0) << "distance interval misses 0";
    return;
  }
  // Overlapping: signed distance -depth, depth = sqrt(depth2) > 0.
  const bool contains = lo <= 0 && lo * lo >= t.depth2 && (hi >= 0 || hi * hi <= t.depth2);
  if (r.verdict == Verdict::Undecided) {
    EXPECT_TRUE(t.depth2 < tiny * tiny && contains)
        << "Undecided for an overlapping pair with depth^2 " << qs(t.depth2) << " (not below 2^-200 * scale)";
    return;
  }
  EXPECT_EQ(r.verdict, Verdict::Overlapping) << "CGAL: origin strictly inside A - B, depth^2 " << qs(t.depth2);
  EXPECT_TRUE(contains) << "distance interval does not hold -sqrt(" << qs(t.depth2) << ")";
}

/// Points near x: +-2^-60 along each axis, and +-1 ulp per coordinate of
/// its nearest double.
std::vector<QVec> nudges(const QVec& x) {
  std::vector<QVec> out;
  const Q eps = Q(1) / Q(boost::multiprecision::mpz_int(1) << 60);
  for (int k = 0; k < 3; ++k)
    for (int s : {-1, 1}) {
      QVec y = x;
      (k == 0 ? y.x : k == 1 ? y.y : y.z) += s * eps;
      out.push_back(y);
    }
  const Vec3 d{to_double(x.x), to_double(x.y), to_double(x.z)};
  for (int k = 0; k < 3; ++k)
    for (double dir : {-INFINITY, INFINITY}) {
      Vec3 y = d;
      y[k] = std::nextafter(y[k], dir);
      out.push_back(to_q(y));
    }
  return out;
}

/// Vertex v pushed away from the centroid c by 2^-60 (v - c) (outside the
/// polytope: v is extreme), and (when v is a double) by one ulp in each
/// coordinate away from c (usually, not always, outside).
std::vector<QVec> pushed_out(const QVec& v, const QVec& c) {
  const Q eps = Q(1) / Q(boost::multiprecision::mpz_int(1) << 60);
  std::vector<QVec> out{v + eps * (v - c)};
  const Vec3 d{to_double(v.x), to_double(v.y), to_double(v.z)};
  if (to_q(d).x == v.x && to_q(d).y == v.y && to_q(d).z == v.z) {
    const QVec dc = v - c;
    Vec3 y = d;
    for (int k = 0; k < 3; ++k) {
      const Q& comp = k == 0 ? dc.x : k == 1 ? dc.y : dc.z;
      if (comp != 0) y[k] = std::nextafter(y[k], comp > 0 ? INFINITY : -INFINITY);
    }
    out.push_back(to_q(y));
  }
  return out;
}

QVec centroid(const std::vector<QVec>& v) {
  QVec c{0, 0, 0};
  for (const QVec& p : v) c = c + p;
  return Q(1, static_cast<long>(v.size())) * c;
}

/// Certificates of one result: accepted by the engine's checks and valid
/// independently; forged variants rejected exactly when invalid.
void check_certificates(const Shape& sa, const Shape& sb, const ConvexShape& A, const ConvexShape& B, const CShape& ca,
                        const CShape& cb, const Truth& truth, const DistanceResult& r, std::mt19937_64& rng,
                        Stats& st) {
  SCOPED_TRACE(describe(r));
  const std::vector<QVec> va = qverts(sa), vb = qverts(sb);
  if (r.witness_a && r.witness_b) {
    // Witness points: in A, in B, at least the true distance apart.
    EXPECT_TRUE(contains(ca, p3(*r.witness_a))) << "witness_a not in A (CGAL) " << qs(*r.witness_a);
    EXPECT_TRUE(contains(cb, p3(*r.witness_b))) << "witness_b not in B (CGAL) " << qs(*r.witness_b);
    const QVec d = *r.witness_a - *r.witness_b;
    if (!truth.intersect) {
      EXPECT_GE(dot(d, d), truth.d2) << "witnesses closer than the distance";
    }
  }
  const bool full = !r.by_filter;  // the filter returns no certificates
  if (r.verdict == Verdict::Separated || r.verdict == Verdict::Touching) {
    const bool strict = r.verdict == Verdict::Separated;
    if (full) {
      EXPECT_TRUE(r.separation.has_value()) << "no separation certificate";
    }
    if (r.separation) {
      ++st.genuine_certs;
      EXPECT_TRUE(check_separation(A, B, *r.separation, strict)) << "genuine direction rejected: " << qs(r.separation->n);
      const int s = indep_sep_sign(va, vb, r.separation->n);
      EXPECT_TRUE(strict ? s < 0 : s <= 0) << "certificate direction does not separate (independent support): "
                                           << qs(r.separation->n);
    }
  }
  if (r.verdict == Verdict::Touching && full) {
    EXPECT_TRUE(r.common_point.has_value()) << "Touching without a point";
  }
  if (r.verdict == Verdict::Overlapping && full) {
    EXPECT_TRUE(r.overlap.has_value()) << "Overlapping without tetrahedron";
  }
  if (r.common_point) {
    ++st.genuine_certs;
    EXPECT_TRUE(check_common_point(A, B, *r.common_point)) << "genuine common point rejected " << qs(*r.common_point);
    EXPECT_TRUE(contains(ca, p3(*r.common_point)) && contains(cb, p3(*r.common_point)))
        << "common point not in both shapes (CGAL) " << qs(*r.common_point);
    for (const QVec& y : nudges(*r.common_point)) {
      const bool truth = contains(ca, p3(y)) && contains(cb, p3(y));
      ++st.forged_points;
      if (!truth) ++st.forged_points_rejected;
      EXPECT_EQ(check_common_point(A, B, y), truth) << "nudged common point " << qs(y);
    }
  }
  if (r.overlap) {
    ++st.genuine_certs;
    EXPECT_TRUE(check_overlap(A, B, *r.overlap)) << "genuine overlap certificate rejected";
    EXPECT_TRUE(indep_overlap_ok(ca, cb, *r.overlap)) << "overlap certificate invalid (CGAL)";
    // Forged: one a_i (or b_i) replaced by a vertex pushed outside.
    const QVec cA = centroid(va), cB = centroid(vb);
    for (int i = 0; i < 4; ++i) {
      for (int side = 0; side < 2; ++side) {
        const std::vector<QVec>& vv = side == 0 ? va : vb;
        const CShape& cs = side == 0 ? ca : cb;
        // Every stored vertex is extreme unless the shape is a point or degenerate.
        const bool extreme = cs.t != CShape::T::Point && cs.v.size() == vv.size();
        const QVec& v = vv[static_cast<std::size_t>(i) % vv.size()];
        const std::vector<QVec> pushed = pushed_out(v, side == 0 ? cA : cB);
        for (std::size_t j = 0; j < pushed.size(); ++j) {
          const QVec& y = pushed[j];
          OverlapCertificate f = *r.overlap;
          (side == 0 ? f.a : f.b)[i] = y;
          const bool truth = indep_overlap_ok(ca, cb, f);
          // The radial push (j == 0) leaves the polytope; the per-coordinate
          // ulp push need not (skewed vertex cones).
          if (extreme && j == 0) {
            EXPECT_FALSE(truth) << "test bug: pushed vertex still inside";
          }
          if (truth) continue;
          ++st.forged_overlap;
          if (!check_overlap(A, B, f)) ++st.forged_overlap_rejected;
          EXPECT_EQ(check_overlap(A, B, f), truth) << "forged overlap certificate: " << (side ? "b" : "a") << "[" << i
                                                   << "] = " << qs(y);
        }
        // The vertex itself (inside): accepted iff the tetrahedron still holds the origin.
        OverlapCertificate g = *r.overlap;
        (side == 0 ? g.a : g.b)[i] = v;
        EXPECT_EQ(check_overlap(A, B, g), indep_overlap_ok(ca, cb, g)) << "modified overlap certificate";
      }
    }
  }
  // Directions: the certificate's tilted, the inner-point difference, random.
  std::vector<QVec> dirs;
  std::uniform_real_distribution<double> u(-1, 1);
  auto rvec = [&] { return to_q(Vec3{u(rng), u(rng), u(rng)}); };
  if (r.separation) {
    dirs.push_back(r.separation->n);
    for (int k : {8, 30, 60}) dirs.push_back(r.separation->n + (Q(1) / Q(boost::multiprecision::mpz_int(1) << k)) * rvec());
  }
  dirs.push_back(centroid(vb) - centroid(va));
  dirs.push_back(rvec());
  for (const QVec& n : dirs) {
    if (n.x == 0 && n.y == 0 && n.z == 0) continue;
    const int s = indep_sep_sign(va, vb, n);
    ++st.forged_dirs;
    if (s >= 0) ++st.forged_dirs_rejected;
    EXPECT_EQ(check_separation(A, B, SeparationCertificate{n}, true), s < 0) << "strict, n = " << qs(n);
    EXPECT_EQ(check_separation(A, B, SeparationCertificate{n}, false), s <= 0) << "non-strict, n = " << qs(n);
  }
}

/// Runs f() (an engine call) and adds its wall time to `ms`; an exception is
/// a test failure ("<what> threw: ...") and gives no answer.
template <class F>
auto engine_call(const char* what, double& ms, F&& f) -> std::optional<decltype(f())> {
  try {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = f();
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return r;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << " threw: " << e.what();
    return std::nullopt;
  }
}

/// The whole cross-check of one pair. Returns the truth.
Truth check_pair(const Shape& sa, const Shape& sb, const std::string& label, std::mt19937_64& rng, Stats& st,
                 bool with_penetration = true) {
  g_current = label + ": A = " + show(sa) + ", B = " + show(sb);
  SCOPED_TRACE(g_current);
  const auto t_start = std::chrono::steady_clock::now();
  const CShape ca = cgal_shape(sa), cb = cgal_shape(sb);
  const Truth t = exact_truth(ca, cb);
  st.truth_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();
  SCOPED_TRACE(std::string("truth ") + truth_name(t) + (t.intersect ? "" : " d2 " + qs(t.d2)) +
               (t.interior ? " depth2 " + qs(t.depth2) : ""));
  ++st.pairs;
  if (!t.intersect) ++st.truth_sep;
  else if (t.interior) ++st.truth_over;
  else ++st.truth_touch;
  if (t.direct) {
    ++st.d2_direct_checked;
    EXPECT_EQ(*t.direct, t.d2) << "CGAL reference inconsistent: direct squared_distance " << qs(*t.direct)
                               << " vs decomposition " << qs(t.d2);
  }
  const ConvexShape A = engine_shape(sa), B = engine_shape(sb);
  const Q scale = pair_scale(A, B);
  if (t.interior && with_penetration) {
    // Penetration depth: the certified enclosure holds the exact depth, and
    // the EPA direction is not a separating one.
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const PenetrationResult p = penetration(A, B, 1e-12);
      st.engine_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      SCOPED_TRACE("penetration: depth [" + qs(p.depth.lo) + ", " + qs(p.depth.hi) + "] note " + p.note);
      ++st.penetrations;
      EXPECT_TRUE(p.overlapping) << "penetration() did not certify an overlapping pair";
      if (p.overlapping) {
        EXPECT_GE(p.depth.lo, 0);
        EXPECT_TRUE((p.depth.lo <= 0 || p.depth.lo * p.depth.lo <= t.depth2) && t.depth2 <= p.depth.hi * p.depth.hi)
            << "depth enclosure does not hold sqrt(" << qs(t.depth2) << ")";
        if (!(p.depth.lo * 1000000 >= p.depth.hi * 999999)) ++st.penetration_wide;
        if (!(p.direction.x == 0 && p.direction.y == 0 && p.direction.z == 0)) {
          EXPECT_FALSE(check_separation(A, B, {p.direction}, false)) << "EPA direction accepted as separating";
        }
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << "penetration threw: " << e.what();
    }
  }
  for (bool filter : {true, false}) {
    SCOPED_TRACE(filter ? "classify(default)" : "classify(filter = false)");
    EngineOptions opt;
    opt.filter = filter;
    const std::optional<DistanceResult> answer =
        engine_call("classify", st.engine_ms, [&] { return classify(A, B, opt); });
    if (!answer) continue;
    const DistanceResult& r = *answer;
    if (r.by_filter) ++st.by_filter;
    check_result(r, t, scale, st);
    const auto c_start = std::chrono::steady_clock::now();
    check_certificates(sa, sb, A, B, ca, cb, t, r, rng, st);
    st.cert_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c_start).count();
    // Swapped order: same verdict.
    if (!filter) {
      try {
        const DistanceResult s = classify(B, A, opt);
        EXPECT_EQ(s.verdict, r.verdict) << "swapped order gives " << describe(s);
      } catch (const std::exception& e) {
        ADD_FAILURE() << "classify(B, A) threw: " << e.what();
      }
    }
  }
  return t;
}

// ---- generators ----------------------------------------------------------------------

double uni(std::mt19937_64& g, double lo = -2, double hi = 2) { return std::uniform_real_distribution<double>(lo, hi)(g); }
Vec3 uvec(std::mt19937_64& g, double lo = -2, double hi = 2) { return {uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)}; }
/// Dyadic grid: k * 2^-20, |k| <= lim * 2^20.
double grid(std::mt19937_64& g, double lim = 2) {
  const long m = static_cast<long>(lim * (1 << 20));
  return std::ldexp(static_cast<double>(std::uniform_int_distribution<long>(-m, m)(g)), -20);
}
Vec3 gvec(std::mt19937_64& g, double lim = 2) { return {grid(g, lim), grid(g, lim), grid(g, lim)}; }
int irand(std::mt19937_64& g, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); }

bool nondegenerate_triangle(Vec3 a, Vec3 b, Vec3 c) { return !CGAL::collinear(p3(a), p3(b), p3(c)); }

Triangle random_triangle(std::mt19937_64& g) {
  for (;;) {
    const Vec3 a = uvec(g), b = uvec(g), c = uvec(g);
    if (nondegenerate_triangle(a, b, c)) return {a, b, c};
  }
}
Triangle grid_triangle(std::mt19937_64& g, double lim = 1.5) {
  for (;;) {
    const Vec3 a = gvec(g, lim), b = gvec(g, lim), c = gvec(g, lim);
    if (nondegenerate_triangle(a, b, c)) return {a, b, c};
  }
}

bool nondegenerate_box(const Obb& b) {
  const Shape s = box_shape(b);
  const std::vector<QVec> v = qverts(s);
  // Spans independent: v1-v0, v2-v0, v4-v0.
  return CGAL::orientation(p3(v[0]), p3(v[1]), p3(v[2]), p3(v[4])) != CGAL::COPLANAR;
}

Vec3 normalized(Vec3 v) { return (1.0 / length(v)) * v; }

Obb random_box(std::mt19937_64& g) {
  for (;;) {
    Obb b;
    b.c = uvec(g);
    b.e = {std::fabs(uni(g)) * 0.5, std::fabs(uni(g)) * 0.5, std::fabs(uni(g)) * 0.5};
    if (irand(g, 0, 1) == 0) {
      // Nearly orthonormal axes (Gram-Schmidt in doubles; the parallelepiped
      // of the stored doubles is what counts).
      const Vec3 x = normalized(uvec(g, -1, 1));
      Vec3 y = uvec(g, -1, 1);
      y = normalized(y - dot(y, x) * x);
      b.axes = {x, y, cross(x, y)};
    } else {
      b.axes = {uvec(g, -1, 1), uvec(g, -1, 1), uvec(g, -1, 1)};
    }
    if (nondegenerate_box(b)) return b;
  }
}

/// A box on the grid: centre, axes and extents dyadic, so that face points
/// c + s0 e0 a0 + t1 e1 a1 + t2 e2 a2 (t dyadic) are exact doubles.
Obb grid_box(std::mt19937_64& g) {
  for (;;) {
    Obb b;
    b.c = gvec(g, 1);
    b.e = {std::ldexp(irand(g, 1, 8), -3), std::ldexp(irand(g, 1, 8), -3), std::ldexp(irand(g, 1, 8), -3)};
    if (irand(g, 0, 2) == 0) {
      b.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    } else {
      b.axes = {gvec(g, 1), gvec(g, 1), gvec(g, 1)};
    }
    if (nondegenerate_box(b)) return b;
  }
}

/// Dyadic t in [-1, 1] (multiples of 1/8), with the ends often.
double dyadic_t(std::mt19937_64& g) {
  const int k = irand(g, -10, 10);
  return k <= -8 ? -1.0 : (k >= 8 ? 1.0 : k / 8.0);
}

/// Exact barycentric point of a grid triangle: weights w_i >= 0 summing to
/// 16 (some zero: edges and vertices).
Vec3 bary_point(const Triangle& t, std::mt19937_64& g) {
  int w0 = irand(g, 0, 16), w1 = irand(g, 0, 16 - w0);
  int w2 = 16 - w0 - w1;
  const int mode = irand(g, 0, 5);
  if (mode == 0) { w0 = 16; w1 = w2 = 0; }
  if (mode == 1) { w2 = 0; w1 = 16 - w0; }
  auto c = [&](double a, double b, double cc) { return (w0 * a + w1 * b + w2 * cc) / 16; };
  return {c(t.a.x, t.b.x, t.c.x), c(t.a.y, t.b.y, t.c.y), c(t.a.z, t.b.z, t.c.z)};
}

/// Exact point on the boundary of a grid box (face, edge or vertex).
Vec3 box_face_point(const Obb& b, std::mt19937_64& g, int* face_axis = nullptr, int* face_sign = nullptr) {
  const int k = irand(g, 0, 2);
  const int s = irand(g, 0, 1) ? 1 : -1;
  double t[3] = {dyadic_t(g), dyadic_t(g), dyadic_t(g)};
  t[k] = s;
  const double e[3] = {b.e.x, b.e.y, b.e.z};
  Vec3 p = b.c;
  for (int i = 0; i < 3; ++i) p = p + (t[i] * e[i]) * b.axes[i];
  if (face_axis) *face_axis = k;
  if (face_sign) *face_sign = s;
  return p;
}

/// A point moved by one ulp in coordinate k.
Vec3 ulp_move(Vec3 p, int k, int dir) {
  p[k] = std::nextafter(p[k], dir > 0 ? INFINITY : -INFINITY);
  return p;
}
Vec3 axis_vec(int k, double d) {
  Vec3 v{0, 0, 0};
  v[k] = d;
  return v;
}

}  // namespace

// =====================================================================================
// (a) random doubles in [-2, 2]
// =====================================================================================

namespace {

/// Random shapes of the (a) tests: vertices uvec(g), in the order drawn.
Shape u_point(std::mt19937_64& g) { return point_shape(uvec(g)); }
Shape u_segment(std::mt19937_64& g) {
  const Segment s{uvec(g), uvec(g)};
  return segment_shape(s.a, s.b);
}
Shape u_triangle(std::mt19937_64& g) {
  const Triangle t = random_triangle(g);
  return triangle_shape(t.a, t.b, t.c);
}
Shape u_box(std::mt19937_64& g) { return box_shape(random_box(g)); }

/// A random pair: A drawn first, then B.
template <Shape (*DrawA)(std::mt19937_64&), Shape (*DrawB)(std::mt19937_64&)>
std::pair<Shape, Shape> random_pair(std::mt19937_64& g) {
  Shape a = DrawA(g);
  Shape b = DrawB(g);
  return {std::move(a), std::move(b)};
}

}  // namespace

class EngineCgalRandom : public ::testing::Test {
 protected:
  void run(const char* name, std::uint64_t seed, int n, const std::function<std::pair<Shape, Shape>(std::mt19937_64&)>& gen) {
    std::printf("[%s] seed %llu, %d pairs\n", name, static_cast<unsigned long long>(seed), n);
    std::mt19937_64 g(seed), aux(seed ^ 0x9e3779b97f4a7c15ULL);
    Stats st;
    for (int i = 0; i < n; ++i) {
      const auto [a, b] = gen(g);
      check_pair(a, b, std::string(name) + " seed " + std::to_string(seed) + " #" + std::to_string(i), aux, st);
      if (::testing::Test::HasFatalFailure()) break;
    }
    st.print(name);
  }
};

TEST_F(EngineCgalRandom, SegmentTriangle) { run("segment-triangle", 1001, 300, random_pair<u_segment, u_triangle>); }
TEST_F(EngineCgalRandom, TriangleTriangle) { run("triangle-triangle", 1002, 300, random_pair<u_triangle, u_triangle>); }
TEST_F(EngineCgalRandom, SegmentSegment) { run("segment-segment", 1003, 300, random_pair<u_segment, u_segment>); }
TEST_F(EngineCgalRandom, PointTriangle) { run("point-triangle", 1004, 300, random_pair<u_point, u_triangle>); }
TEST_F(EngineCgalRandom, BoxSegment) { run("box-segment", 1005, 300, random_pair<u_box, u_segment>); }
TEST_F(EngineCgalRandom, BoxTriangle) { run("box-triangle", 1006, 300, random_pair<u_box, u_triangle>); }
TEST_F(EngineCgalRandom, BoxBox) { run("box-box", 1007, 300, random_pair<u_box, u_box>); }

TEST_F(EngineCgalRandom, PointBox) {
  // The box is drawn first.
  run("point-box", 1008, 200, [](std::mt19937_64& g) {
    const Shape b = u_box(g);
    return std::make_pair(u_point(g), b);
  });
}

TEST_F(EngineCgalRandom, DegenerateTriangles) {
  // Collinear / coincident triangle vertices: the triangle is its segment or
  // point (CGAL side: Segment_3 / Point_3).
  run("degenerate-triangle", 1009, 200, [](std::mt19937_64& g) {
    const Vec3 a = gvec(g), b = gvec(g);
    const int k = irand(g, -8, 24);
    Vec3 c = a + (k / 16.0) * (b - a);
    if (irand(g, 0, 4) == 0) c = a;
    Triangle t{a, b, c};
    if (irand(g, 0, 1)) t = {c, a, b};
    Shape other;
    switch (irand(g, 0, 3)) {
      case 0: other = segment_shape(gvec(g), gvec(g)); break;
      case 1: { const Triangle u = grid_triangle(g); other = triangle_shape(u.a, u.b, u.c); break; }
      case 2: other = box_shape(grid_box(g)); break;
      default: other = point_shape(a + (irand(g, 0, 16) / 16.0) * (b - a)); break;
    }
    return std::make_pair(triangle_shape(t.a, t.b, t.c), other);
  });
}

// =====================================================================================
// (b) exact touching constructions and their 1-ulp / 2^-50 / 2^-40 neighbours
// =====================================================================================

namespace {

struct NearCase {
  Shape a, b;
  std::string what;
};

/// The neighbours of a touching pair: the contact vertex of B (if any) moved
/// by one ulp in each direction of one coordinate, B translated by +-2^-50
/// and +-2^-40 along one axis.
std::vector<NearCase> neighbours(const Shape& a, const Shape& b, int contact_vertex, int k, std::mt19937_64& g) {
  std::vector<NearCase> out;
  out.push_back({a, b, "touch"});
  if (contact_vertex >= 0) {
    for (int dir : {-1, 1}) {
      Shape m = b;
      m.v[contact_vertex] = ulp_move(m.v[contact_vertex], k, dir);
      out.push_back({a, m, "contact vertex " + std::to_string(dir) + " ulp in coordinate " + std::to_string(k)});
    }
  }
  const int kk = irand(g, 0, 2);
  for (int e : {-50, -40})
    for (int dir : {-1, 1})
      out.push_back({a, translated(b, axis_vec(kk, dir * std::ldexp(1, e))),
                     "B translated by " + std::to_string(dir) + "*2^" + std::to_string(e) + " along axis " +
                         std::to_string(kk)});
  return out;
}

/// Coordinate of the largest component of a (double) normal.
int main_axis(Vec3 n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

/// A grid box and an exact point p of its boundary, on the face of axis k
/// and outward sign s (box_face_point's draw).
struct BoxFacePoint {
  Obb box;
  Vec3 p;
  int k = 0, s = 0;
};
BoxFacePoint grid_box_face_point(std::mt19937_64& g) {
  BoxFacePoint f;
  f.box = grid_box(g);
  f.p = box_face_point(f.box, g, &f.k, &f.s);
  return f;
}

/// The point `al` beyond f's face (along s * axes_k) from f.p, moved along
/// the face by dyadic multiples of the other two axes.
Vec3 beyond(const BoxFacePoint& f, double al, std::mt19937_64& g) {
  return f.p + (f.s * al) * f.box.axes[f.k] + dyadic_t(g) * f.box.axes[(f.k + 1) % 3] +
         dyadic_t(g) * f.box.axes[(f.k + 2) % 3];
}

/// A non-degenerate triangle with its vertex a at f.p and the other two
/// drawn by `outward()`.
template <class Outward>
Triangle triangle_on_face_point(const BoxFacePoint& f, Outward outward) {
  Vec3 q, r;
  do {
    q = outward();
    r = outward();
  } while (!nondegenerate_triangle(f.p, q, r));
  return {f.p, q, r};
}

/// The neighbours of the touching pair (f's box, b), b touching the face at
/// its vertex 0.
std::vector<NearCase> face_neighbours(const BoxFacePoint& f, const Shape& b, std::mt19937_64& g) {
  const Vec3 nrm = cross(f.box.axes[(f.k + 1) % 3], f.box.axes[(f.k + 2) % 3]);
  return neighbours(box_shape(f.box), b, 0, main_axis(nrm), g);
}

}  // namespace

class EngineCgalNear : public ::testing::Test {
 protected:
  /// `make` returns the touching pair; the touch itself must be exact (CGAL
  /// intersecting), the neighbours are judged by CGAL.
  void run(const char* name, std::uint64_t seed, int n,
           const std::function<std::vector<NearCase>(std::mt19937_64&)>& make) {
    std::printf("[%s] seed %llu, %d constructions\n", name, static_cast<unsigned long long>(seed), n);
    std::mt19937_64 g(seed), aux(seed ^ 0x9e3779b97f4a7c15ULL);
    Stats st;
    for (int i = 0; i < n; ++i) {
      const std::vector<NearCase> cases = make(g);
      for (const NearCase& c : cases) {
        const std::string label = std::string(name) + " seed " + std::to_string(seed) + " #" + std::to_string(i) + " " + c.what;
        const Truth t = check_pair(c.a, c.b, label, aux, st);
        if (c.what == "touch") {
          EXPECT_TRUE(t.intersect) << "test bug: construction not exact: " << label << " A = " << show(c.a)
                                   << " B = " << show(c.b);
        }
      }
      if (::testing::Test::HasFatalFailure()) break;
    }
    st.print(name);
  }
};

TEST_F(EngineCgalNear, SegmentEndOnTriangle) {
  run("segment end on triangle", 2001, 24, [](std::mt19937_64& g) {
    const Triangle t = grid_triangle(g);
    const Vec3 p = bary_point(t, g);
    const Vec3 n = cross(t.b - t.a, t.c - t.a);
    Vec3 q;
    do q = gvec(g); while (CGAL::orientation(p3(t.a), p3(t.b), p3(t.c), p3(q)) == CGAL::COPLANAR);
    Shape b = segment_shape(p, q);
    return neighbours(triangle_shape(t.a, t.b, t.c), b, 0, main_axis(n), g);
  });
}

TEST_F(EngineCgalNear, SegmentCrossingTriangleEdge) {
  // A segment through a point of a triangle's edge, transversal to the plane.
  run("segment through triangle edge", 2002, 16, [](std::mt19937_64& g) {
    const Triangle t = grid_triangle(g, 1);
    const int w = irand(g, 0, 16);
    const Vec3 p = (1.0 / 16) * (w * t.a + (16 - w) * t.b);
    const Vec3 d = gvec(g, 0.5);
    Shape b = segment_shape(p - d, p + d);
    return neighbours(triangle_shape(t.a, t.b, t.c), b, -1, 0, g);
  });
}

TEST_F(EngineCgalNear, TrianglesSharingEdge) {
  run("triangles sharing an edge", 2003, 20, [](std::mt19937_64& g) {
    const Triangle t = grid_triangle(g, 1);
    Vec3 d;
    const int mode = irand(g, 0, 3);
    if (mode == 0) d = t.a + t.b - t.c;  // coplanar, other side of the edge
    else if (mode == 1) d = t.c + (1.0 / 8) * (t.b - t.a);  // coplanar, overlapping
    else
      do d = gvec(g, 1); while (!nondegenerate_triangle(t.a, t.b, d));
    Shape b = triangle_shape(t.a, t.b, d);
    return neighbours(triangle_shape(t.a, t.b, t.c), b, 2, main_axis(cross(t.b - t.a, t.c - t.a)), g);
  });
}

TEST_F(EngineCgalNear, TrianglesSharingVertex) {
  run("triangles sharing a vertex", 2004, 16, [](std::mt19937_64& g) {
    const Triangle t = grid_triangle(g, 1);
    Vec3 d, e;
    do {
      d = gvec(g, 1);
      e = gvec(g, 1);
    } while (!nondegenerate_triangle(t.a, d, e));
    Shape b = triangle_shape(t.a, d, e);
    return neighbours(triangle_shape(t.a, t.b, t.c), b, 0, main_axis(cross(t.b - t.a, t.c - t.a)), g);
  });
}

TEST_F(EngineCgalNear, CoplanarCrossingTriangles) {
  run("coplanar crossing triangles", 2005, 16, [](std::mt19937_64& g) {
    const Vec3 o = gvec(g, 0.5), u = gvec(g, 0.25), v = gvec(g, 0.25);
    auto at = [&](int s, int t) { return o + static_cast<double>(s) * u + static_cast<double>(t) * v; };
    Triangle t1, t2;
    do {
      t1 = {at(irand(g, -3, 3), irand(g, -3, 3)), at(irand(g, -3, 3), irand(g, -3, 3)), at(irand(g, -3, 3), irand(g, -3, 3))};
      t2 = {at(irand(g, -3, 3), irand(g, -3, 3)), at(irand(g, -3, 3), irand(g, -3, 3)), at(irand(g, -3, 3), irand(g, -3, 3))};
    } while (!nondegenerate_triangle(t1.a, t1.b, t1.c) || !nondegenerate_triangle(t2.a, t2.b, t2.c) ||
             !CGAL::do_intersect(Tri3(p3(t1.a), p3(t1.b), p3(t1.c)), Tri3(p3(t2.a), p3(t2.b), p3(t2.c))));
    Shape b = triangle_shape(t2.a, t2.b, t2.c);
    return neighbours(triangle_shape(t1.a, t1.b, t1.c), b, 0, main_axis(cross(u, v)), g);
  });
}

TEST_F(EngineCgalNear, PointOnTriangle) {
  run("point on triangle", 2006, 20, [](std::mt19937_64& g) {
    const Triangle t = grid_triangle(g);
    Shape b = point_shape(bary_point(t, g));
    return neighbours(triangle_shape(t.a, t.b, t.c), b, 0, main_axis(cross(t.b - t.a, t.c - t.a)), g);
  });
}

TEST_F(EngineCgalNear, SegmentsCrossing) {
  run("segments crossing", 2007, 20, [](std::mt19937_64& g) {
    const Vec3 a = gvec(g, 1), b = gvec(g, 1);
    const int w = irand(g, 0, 16);
    const Vec3 p = (1.0 / 16) * (w * a + (16 - w) * b);
    const Vec3 d = gvec(g, 0.5);
    Shape s2 = irand(g, 0, 2) == 0 ? segment_shape(p, p + d) : segment_shape(p - d, p + d);
    return neighbours(segment_shape(a, b), s2, irand(g, 0, 2) == 0 ? 0 : -1, main_axis(cross(b - a, d)), g);
  });
}

TEST_F(EngineCgalNear, PointOnSegment) {
  run("point on segment", 2012, 12, [](std::mt19937_64& g) {
    const Vec3 a = gvec(g, 1.5), b = gvec(g, 1.5);
    Shape p = point_shape(a + (irand(g, 0, 16) / 16.0) * (b - a));
    return neighbours(segment_shape(a, b), p, 0, irand(g, 0, 2), g);
  });
}

TEST_F(EngineCgalNear, CollinearSegments) {
  run("collinear segments", 2013, 12, [](std::mt19937_64& g) {
    const Vec3 a = gvec(g, 1), b = gvec(g, 1);
    const int k = irand(g, -8, 24), m = irand(g, 0, 16);
    Shape s2 = segment_shape(a + (k / 16.0) * (b - a), a + (m / 16.0) * (b - a));
    return neighbours(segment_shape(a, b), s2, 0, irand(g, 0, 2), g);
  });
}

TEST_F(EngineCgalNear, CoincidentPoints) {
  run("coincident points", 2014, 8, [](std::mt19937_64& g) {
    const Vec3 a = gvec(g, 2);
    Shape p = point_shape(a);
    return neighbours(point_shape(a), p, 0, irand(g, 0, 2), g);
  });
}

TEST_F(EngineCgalNear, PointOnBoxFace) {
  run("point on box boundary", 2008, 20, [](std::mt19937_64& g) {
    const BoxFacePoint f = grid_box_face_point(g);
    return face_neighbours(f, point_shape(f.p), g);
  });
}

TEST_F(EngineCgalNear, TriangleVertexOnBoxFace) {
  run("triangle vertex on box face", 2009, 20, [](std::mt19937_64& g) {
    const BoxFacePoint f = grid_box_face_point(g);
    // Other vertices outside, beyond the face: + alpha * s * axes_k + tangential.
    const Triangle t = triangle_on_face_point(f, [&] {
      const double al = std::ldexp(irand(g, 1, 8), -3);
      return beyond(f, al, g);
    });
    return face_neighbours(f, triangle_shape(t.a, t.b, t.c), g);
  });
}

TEST_F(EngineCgalNear, SegmentEndOnBoxFace) {
  run("segment end on box face", 2010, 16, [](std::mt19937_64& g) {
    const BoxFacePoint f = grid_box_face_point(g);
    const int mode = irand(g, 0, 2);
    // mode 0: along the face (touching along a segment), else leaving the face outward.
    const double al = mode == 0 ? 0.0 : std::ldexp(irand(g, 1, 8), -3);
    return face_neighbours(f, segment_shape(f.p, beyond(f, al, g)), g);
  });
}

TEST_F(EngineCgalNear, BoxesFaceToFace) {
  run("boxes face to face / vertex on face", 2011, 16, [](std::mt19937_64& g) {
    const Obb a = grid_box(g);
    Obb b = a;
    const int k = irand(g, 0, 2);
    const double e[3] = {a.e.x, a.e.y, a.e.z};
    if (irand(g, 0, 1) == 0) {
      // B = A shifted by 2 e_k axes_k (shares a face), then slid along the face.
      b.c = a.c + (2 * e[k]) * a.axes[k] + (dyadic_t(g) * e[(k + 1) % 3]) * a.axes[(k + 1) % 3];
    } else {
      // A box of other axes whose vertex (-,-,-) is a point of A's face.
      int kk = 0, s = 0;
      const Vec3 p = box_face_point(a, g, &kk, &s);
      b = grid_box(g);
      const double eb[3] = {b.e.x, b.e.y, b.e.z};
      b.c = p;
      for (int i = 0; i < 3; ++i) b.c = b.c + eb[i] * b.axes[i];
    }
    return neighbours(box_shape(a), box_shape(b), -1, 0, g);
  });
}

// =====================================================================================
// hand cases: exact contacts along a line (the Minkowski difference is a
// segment or a point). The contract would allow Undecided there (|distance|
// = 0 < 2^-200 * scale), but a touching certificate exists; the engine left
// these Undecided until it tried planes through the common line (feature
// directions crossed with the axes). Kept with their exact inputs as
// regressions: Touching is now required.
// =====================================================================================

namespace {

void expect_line_contact(const Shape& sa, const Shape& sb, const char* name) {
  SCOPED_TRACE(std::string(name) + ": A = " + show(sa) + ", B = " + show(sb));
  const CShape ca = cgal_shape(sa), cb = cgal_shape(sb);
  const Truth t = exact_truth(ca, cb);
  ASSERT_TRUE(t.intersect && !t.interior) << "not an exact touching pair";
  const ConvexShape A = engine_shape(sa), B = engine_shape(sb);
  // A touching certificate, found by brute force among simple candidates.
  std::vector<QVec> dirs = {QVec{1, 0, 0}, QVec{0, 1, 0}, QVec{0, 0, 1}};
  for (const auto* v : {&A.points, &B.points})
    for (std::size_t i = 0; i < v->size(); ++i)
      for (std::size_t j = i + 1; j < v->size(); ++j)
        for (const QVec& e : {QVec{1, 0, 0}, QVec{0, 1, 0}, QVec{0, 0, 1}}) dirs.push_back(cross((*v)[j] - (*v)[i], e));
  std::optional<QVec> n, x;
  for (const QVec& d : dirs)
    if (!(d.x == 0 && d.y == 0 && d.z == 0) && check_separation(A, B, {d}, false)) {
      n = d;
      break;
    }
  for (const auto* v : {&A.points, &B.points})
    for (const QVec& p : *v)
      if (!x && check_common_point(A, B, p)) x = p;
  ASSERT_TRUE(n && x) << "no simple touching certificate";
  EXPECT_LE(indep_sep_sign(qverts(sa), qverts(sb), *n), 0);
  EXPECT_TRUE(contains(ca, p3(*x)) && contains(cb, p3(*x)));
  for (bool filter : {true, false}) {
    EngineOptions opt;
    opt.filter = filter;
    const DistanceResult r = classify(A, B, opt);
    SCOPED_TRACE(describe(r));
    EXPECT_EQ(r.verdict, Verdict::Touching) << name << ": a touching certificate n = " << qs(*n) << ", x = " << qs(*x)
                                            << " passes check_separation(strict = false) and check_common_point";
    EXPECT_TRUE(r.distance.lo <= 0 && r.distance.hi >= 0);
  }
}

}  // namespace

// =====================================================================================
// (e) zero-radius cylinders: Cylinder{p, q, 0} is exactly the segment pq, so
//     cylinder/box is a polyhedral pair CGAL decides exactly. Held to it: the
//     engine's verdict on the cylinder shape, and production's
//     overlap(Cylinder, Obb) outside its verdict band (1e-14 * scale).
// =====================================================================================

namespace {
// A box of the grid whose axes are exactly orthonormal (production's
// contract): signed permutations of the coordinate axes, either handedness.
Obb grid_orthonormal_box(std::mt19937_64& g) {
  Obb b = grid_box(g);
  int perm[3] = {0, 1, 2};
  std::shuffle(perm, perm + 3, g);
  for (int i = 0; i < 3; ++i) b.axes[i] = axis_vec(perm[i], irand(g, 0, 1) ? 1.0 : -1.0);
  return b;
}
}  // namespace

/// The zero-radius cylinder tests: their seed and generator, the draw of a
/// cylinder, the checks against CGAL's verdict, and the counts they report.
class EngineCgalCylinder0 : public ::testing::Test {
 protected:
  /// A zero-radius cylinder (its axis segment) and CGAL's exact verdict on
  /// it against the other shape.
  struct Drawn {
    Cylinder cyl;
    bool truth = false;
  };

  /// A zero-radius cylinder whose ends are grid points within `lim` (modes
  /// 0..grid_modes of 0..6) or on() (points of `other`), the latter moved by
  /// one ulp in mode 6, with CGAL's verdict against `other` (counted in
  /// `meets`); nothing when the ends coincide.
  template <class On>
  std::optional<Drawn> draw(int grid_modes, double lim, On on, const Shape& other) {
    auto end = [&]() {
      const int mode = irand(g, 0, 6);
      if (mode <= grid_modes) return gvec(g, lim);
      Vec3 p = on();
      if (mode == 6) p = ulp_move(p, irand(g, 0, 2), irand(g, 0, 1) ? 1 : -1);
      return p;
    };
    const Vec3 a = end(), b = end();
    if (a == b) return std::nullopt;
    const bool truth = cgal_intersect(cgal_shape(segment_shape(a, b)), cgal_shape(other));
    meets += truth;
    return Drawn{Cylinder{a, b, 0.0}, truth};
  }

  /// The engine's decided verdict r on (d.cyl, other) must be CGAL's, and
  /// where r's distance is outside `band` so must production's
  /// overlap(d.cyl, other); counted in `checked` and `prod_checked`.
  template <class Other>
  void expect_as_cgal(const Drawn& d, const Other& other, const DistanceResult& r, const Q& band,
                      const std::string& where) {
    ASSERT_EQ(d.truth, r.verdict != Verdict::Separated) << where << " engine " << to_string(r.verdict);
    ++checked;
    if (r.distance.lo > band || r.distance.hi < -band) {
      ++prod_checked;
      ASSERT_EQ(d.truth, overlap(d.cyl, other)) << where << " production disagrees with CGAL outside the band";
    }
  }

  /// Between a fifth and four fifths of the checked pairs meet.
  void expect_balanced() const {
    EXPECT_GT(meets, checked / 5);
    EXPECT_LT(meets, checked * 4 / 5);
  }

  const std::uint64_t seed = 20261122;
  std::mt19937_64 g{seed};
  int checked = 0, meets = 0, prod_checked = 0;
};

TEST_F(EngineCgalCylinder0, ZeroRadiusCylinderAgainstBox) {
  for (int i = 0; i < 3000; ++i) {
    const Obb box = grid_orthonormal_box(g);
    // Segment ends: grid points, points on the box's boundary (touching),
    // and boundary points moved by one ulp.
    const auto d = draw(3, 3, [&] { return box_face_point(box, g); }, box_shape(box));
    if (!d) continue;
    const Vec3 a = d->cyl.p, b = d->cyl.q;
    const DistanceResult r = classify(make_shape(d->cyl), make_shape(box));
    const std::string where = "seed " + std::to_string(seed) + " #" + std::to_string(i) + ": Cylinder{" + hex(a) + ", " +
                              hex(b) + ", 0} vs Obb{c=" + hex(box.c) + ", e=" + hex(box.e) + "}";
    ASSERT_NE(r.verdict, Verdict::Undecided) << where;
    const double scale = std::max({max_abs(a), max_abs(b), max_abs(box.c), max_abs(box.e), length(b - a)});
    ASSERT_NO_FATAL_FAILURE(expect_as_cgal(*d, box, r, to_q(1e-14) * to_q(scale), where));
  }
  std::printf("[EngineCgalCylinder0] seed %llu: %d pairs, %d meeting; production checked outside the band on %d\n",
              static_cast<unsigned long long>(seed), checked, meets, prod_checked);
  expect_balanced();
}

// The same for triangles (collide_cylinder_triangle): a zero-radius cylinder
// is its axis segment; grid triangles, some made degenerate (two equal
// vertices, a vertex at the midpoint of the opposite edge), against segments
// whose ends are grid points, points of the triangle, or such points moved
// by one ulp. CGAL decides segment-triangle intersection exactly.
TEST_F(EngineCgalCylinder0, ZeroRadiusCylinderAgainstTriangle) {
  int undecided = 0;
  for (int i = 0; i < 1500; ++i) {
    Triangle t = grid_triangle(g);
    const int deg = irand(g, 0, 9);
    if (deg == 0) t.c = t.b;
    if (deg == 1) t.c = 0.5 * (t.a + t.b);
    const auto d = draw(2, 2, [&] { return bary_point(t, g); }, triangle_shape(t.a, t.b, t.c));
    if (!d) continue;
    const Vec3 a = d->cyl.p, b = d->cyl.q;
    DistanceResult r = classify(make_shape(d->cyl), make_shape(t));
    if (r.verdict == Verdict::Undecided) {
      EngineOptions opt;
      opt.rel_width = 1e-20;
      r = classify(make_shape(d->cyl), make_shape(t), opt);
    }
    const std::string where = "seed " + std::to_string(seed) + " #" + std::to_string(i) + ": Cylinder{" + hex(a) + ", " +
                              hex(b) + ", 0} vs Triangle{" + hex(t.a) + ", " + hex(t.b) + ", " + hex(t.c) + "}";
    const double scale = std::max({max_abs(a), max_abs(b), max_abs(t.a), max_abs(t.b), max_abs(t.c), length(b - a)});
    const Q band = to_q(1e-14) * to_q(scale);
    if (r.verdict == Verdict::Undecided) {
      // The engine does not decide a zero-radius cylinder against a
      // degenerate triangle (two segments: their Minkowski difference is
      // flat), nor a segment that meets the triangle only on its boundary
      // (distance exactly 0, no interior to certify: a segment one ulp off
      // a vertex, crossing the plane exactly on an edge). It must say so
      // only there; production is then held to CGAL's exact squared
      // distance.
      const Q d2 = decomposed_d2(cgal_shape(segment_shape(a, b)), cgal_shape(triangle_shape(t.a, t.b, t.c)));
      ASSERT_TRUE(t.c == t.b || t.c == 0.5 * (t.a + t.b) || d2 == 0)
          << where << " undecided: " << to_string(r.distance) << ", CGAL distance^2 " << to_double(d2);
      ++undecided;
      if (d2 > band * band) {
        ASSERT_FALSE(overlap(d->cyl, t)) << where << " production overlaps; CGAL distance^2 " << to_double(d2);
      }
      continue;
    }
    ASSERT_NO_FATAL_FAILURE(expect_as_cgal(*d, t, r, band, where));
  }
  std::printf("[EngineCgalCylinder0] triangles, seed %llu: %d pairs, %d meeting; production checked outside the band on "
              "%d; engine undecided (touching within the band) on %d\n",
              static_cast<unsigned long long>(seed), checked, meets, prod_checked, undecided);
  EXPECT_LT(undecided, checked / 10);
  expect_balanced();
}

TEST(EngineCgalHand, PointOnSegment) {
  expect_line_contact(segment_shape({0x1.1bdf4p+0, 0x1.d6584p-1, 0x1.9587ep-1}, {-0x1.4c64fp+0, 0x1.168c2p-1, 0x1.409b3p+0}),
                      point_shape({-0x1.179f42p-1, 0x1.527beap-1, 0x1.1bc7ecp+0}), "point on segment");
}

TEST(EngineCgalHand, CollinearOverlappingSegments) {
  expect_line_contact(
      segment_shape({-0x1.d5cccp-2, -0x1.72e7p-3, 0x1.fe428p-3}, {-0x1.1fafcp-1, -0x1.0f666p-1, -0x1.b1e8cp-1}),
      segment_shape({-0x1.22fc56p-1, -0x1.1a912ap-1, -0x1.d50056p-1}, {-0x1.f6ca9cp-2, -0x1.291f64p-2, -0x1.7f2a7p-4}),
      "collinear segments");
}

TEST(EngineCgalHand, CollinearSegmentsSharingAnEndpoint) {
  expect_line_contact(
      segment_shape({0x1.b9188p-3, 0x1.bc9f4p-1, 0x1.43e3cp-1}, {0x1.b656ap-1, 0x1.5d07p-3, 0x1.f569p-2}),
      segment_shape({0x1.80948p-2, 0x1.6347ep-1, 0x1.3197fp-1}, {0x1.b656ap-1, 0x1.5d07p-3, 0x1.f569p-2}),
      "collinear segments sharing an endpoint");
}

TEST(EngineCgalHand, CoincidentPoints) {
  expect_line_contact(point_shape({0x1.f820fp+0, -0x1.5a2ep+0, -0x1.777cp-2}),
                      point_shape({0x1.f820fp+0, -0x1.5a2ep+0, -0x1.777cp-2}), "coincident points");
}

TEST(EngineCgalHand, PointOnDegenerateTriangle) {
  expect_line_contact(triangle_shape({0x1.c0bebp+0, -0x1.2c568p-1, 0x1.1cbp-5}, {0x1.c0bebp+0, -0x1.2c568p-1, 0x1.1cbp-5},
                                     {0x1.ff20ap-1, 0x1.7edecp-2, -0x1.223acp-2}),
                      point_shape({0x1.23c902p+0, 0x1.8ce918p-3, -0x1.ca4738p-3}), "point on a degenerate triangle");
}

// =====================================================================================
// time of impact against a ray cast into the exact Minkowski difference
// =====================================================================================

namespace {

struct ImpactStats {
  int pairs = 0, flat = 0, nohit = 0, starts = 0, hit = 0, undecided = 0;
  double engine_ms = 0;
};

/// A + t delta meets B <=> -t delta in A - B. With the facet planes of
/// A - B: t * (-n.delta) <= h for every facet; the feasible t of [0, 1] form
/// an interval [t_lo, t_hi]; the time of impact is t_lo.
void check_impact(const Shape& sa, Vec3 delta, const Shape& sb, const std::string& label, ImpactStats& st) {
  const std::string what = label + ": moving " + show(sa) + ", delta " + hex(delta) + ", B = " + show(sb);
  SCOPED_TRACE(what);
  const CShape ca = cgal_shape(sa), cb = cgal_shape(sb);
  const MinkowskiPlanes m = minkowski_planes(ca, cb);
  ++st.pairs;
  if (!m.full) {
    ++st.flat;
    return;
  }
  const QVec d = to_q(delta);
  // Unclamped feasible interval [Lo, Hi] of t (infinite ends as flags).
  Q Lo = 0, Hi = 0;
  bool has_lo = false, has_hi = false, feasible = true;
  for (const auto& [n, h] : m.f) {
    const Q c = -dot(n, d);
    if (c > 0) {
      const Q v = h / c;
      if (!has_hi || v < Hi) Hi = v;
      has_hi = true;
    } else if (c < 0) {
      const Q v = h / c;
      if (!has_lo || v > Lo) Lo = v;
      has_lo = true;
    } else if (h < 0) {
      feasible = false;
    }
  }
  const Q first = has_lo && Lo > 0 ? Lo : Q(0);      // earliest contact at t >= 0
  const bool contact = feasible && first <= 1 && (!has_hi || first <= Hi);
  const bool grazing = has_lo && has_hi && Lo == Hi;  // meets at one instant only
  const ConvexShape A = engine_shape(sa), B = engine_shape(sb);
  const std::optional<ImpactResult> answer =
      engine_call("time_of_impact", st.engine_ms, [&] { return time_of_impact(A, d, B); });
  if (!answer) return;
  const ImpactResult& r = *answer;
  SCOPED_TRACE(std::string("engine ") + to_string(r.kind) + " t [" + qs(r.t.lo) + ", " + qs(r.t.hi) + "] note " + r.note);
  switch (r.kind) {
    case ImpactResult::Kind::NoHit: ++st.nohit; break;
    case ImpactResult::Kind::Hit: ++st.hit; break;
    case ImpactResult::Kind::StartsInside: ++st.starts; break;
    case ImpactResult::Kind::Undecided: ++st.undecided; break;
  }
  if (!contact) {
    EXPECT_EQ(r.kind, ImpactResult::Kind::NoHit) << "exact: no contact for t in [0, 1]";
    return;
  }
  if (first == 0) {
    EXPECT_EQ(r.kind, ImpactResult::Kind::StartsInside) << "exact: the shapes meet at t = 0";
    return;
  }
  // First contact at t* = first in (0, 1]: Hit with t.lo < t* <= t.hi (the
  // sweep over [0, t.lo] is certified separated). A grazing contact (one
  // instant, no overlap) may be left Undecided.
  if (grazing && r.kind == ImpactResult::Kind::Undecided) return;
  EXPECT_EQ(r.kind, ImpactResult::Kind::Hit) << "exact time of impact " << qs(first) << (grazing ? " (grazing)" : "");
  if (r.kind == ImpactResult::Kind::Hit) {
    EXPECT_TRUE(r.t.lo < first && first <= r.t.hi) << "time interval misses the exact time of impact " << qs(first);
  }
}

}  // namespace

/// The time-of-impact checks: `n` motions (moving A, its delta, resting B)
/// from `make(g, i)` on the seed, each checked by check_impact; prints the
/// counts.
class EngineCgalImpact : public ::testing::Test {
 protected:
  void run(const char* name, std::uint64_t seed, int n,
           const std::function<std::tuple<Shape, Vec3, Shape>(std::mt19937_64&, int)>& make) {
    std::printf("[%s] seed %llu\n", name, static_cast<unsigned long long>(seed));
    std::mt19937_64 g(seed);
    ImpactStats st;
    for (int i = 0; i < n; ++i) {
      const auto [a, delta, b] = make(g, i);
      check_impact(a, delta, b, std::string(name) + " seed " + std::to_string(seed) + " #" + std::to_string(i), st);
    }
    std::printf("[%s] pairs %d (%d flat A - B skipped): %d no hit, %d hit, %d starts inside, %d undecided; engine %.0f "
                "ms\n",
                name, st.pairs, st.flat, st.nohit, st.hit, st.starts, st.undecided, st.engine_ms);
  }
};

TEST_F(EngineCgalImpact, RandomPairs) {
  run("impact random", 3001, 100, [](std::mt19937_64& g, int i) {
    Shape a, b;
    switch (i % 5) {
      case 0: { const Triangle t = random_triangle(g); a = triangle_shape(t.a, t.b, t.c); b = box_shape(random_box(g)); break; }
      case 1: a = box_shape(random_box(g)); b = box_shape(random_box(g)); break;
      case 2: { const Triangle t = random_triangle(g), u = random_triangle(g); a = triangle_shape(t.a, t.b, t.c); b = triangle_shape(u.a, u.b, u.c); break; }
      case 3: a = segment_shape(uvec(g), uvec(g)); b = box_shape(random_box(g)); break;
      default: { const Triangle t = random_triangle(g); a = segment_shape(uvec(g), uvec(g)); b = triangle_shape(t.a, t.b, t.c); break; }
    }
    const Vec3 delta = uvec(g, -3, 3);
    return std::make_tuple(a, delta, b);
  });
}

TEST_F(EngineCgalImpact, TriangleVertexLandsOnBoxFace) {
  // The triangle's vertex reaches a box face exactly at t = 1/2 (or 1, or
  // never: delta too short / pointing away).
  run("impact onto face", 3002, 24, [](std::mt19937_64& g, int i) {
    const BoxFacePoint f = grid_box_face_point(g);
    const double al = std::ldexp(irand(g, 1, 8), -3);
    const Vec3 off = (f.s * al) * f.box.axes[f.k];
    // Other vertices outside, beyond the face.
    const Triangle t = triangle_on_face_point(f, [&] {
      return f.p + (f.s * std::ldexp(irand(g, 1, 8), -3)) * f.box.axes[f.k] + dyadic_t(g) * f.box.axes[(f.k + 1) % 3] +
             dyadic_t(g) * f.box.axes[(f.k + 2) % 3];
    });
    const Shape tri_s = triangle_shape(t.a + off, t.b + off + off, t.c + off + off);
    const double d = (i % 4 == 0) ? 1.0 : (i % 4 == 1 ? 2.0 : (i % 4 == 2 ? 4.0 : -2.0));
    const Vec3 delta = (-d) * off;  // contact at t = 1/d
    return std::make_tuple(tri_s, delta, box_shape(f.box));
  });
}

// =====================================================================================
// (c) forged certificates, hand-made
// =====================================================================================

namespace {

/// The overlap certificate of the tetrahedron a[0..3] (points of A) around
/// the point x (B, a single point).
OverlapCertificate certificate_around(const Vec3 (&a)[4], Vec3 x) {
  OverlapCertificate c;
  for (int i = 0; i < 4; ++i) {
    c.a[i] = to_q(a[i]);
    c.b[i] = to_q(x);
  }
  return c;
}

}  // namespace

TEST(EngineCgalForged, CylinderRimPushedOutByOneUlp) {
  // Cylinder p = 0, q = (0, 0, 2), r = 5: (3, -4, 0), (-3, -4, 0), (0, 5, 0)
  // lie exactly on the rim, (0, 0, 2) is the top cap centre; their
  // tetrahedron holds (0, 0, 1/2) strictly.
  const Cylinder cyl{{0, 0, 0}, {0, 0, 2}, 5};
  const Vec3 x{0, 0, 0.5};
  const ConvexShape A = make_shape(cyl), B = make_point(x);
  const Vec3 a[4] = {{3, -4, 0}, {-3, -4, 0}, {0, 5, 0}, {0, 0, 2}};
  const OverlapCertificate c = certificate_around(a, x);
  EXPECT_TRUE(check_overlap(A, B, c)) << "genuine rim certificate rejected";
  const Vec3 forged[] = {{std::nextafter(3.0, 4.0), -4, 0},
                         {3, std::nextafter(-4.0, -5.0), 0},
                         {0, std::nextafter(5.0, 6.0), 0},
                         {3, -4, std::nextafter(0.0, -1.0)},
                         {0, 0, std::nextafter(2.0, 3.0)}};
  for (const Vec3& f : forged) {
    OverlapCertificate d = c;
    const int i = f.z > 1 ? 3 : (f.y > 4 ? 2 : 0);
    d.a[i] = to_q(f);
    EXPECT_FALSE(check_overlap(A, B, d)) << "forged rim point accepted: a[" << i << "] = " << hex(f);
    EXPECT_FALSE(check_common_point(A, B, to_q(f))) << hex(f);
  }
  // The genuine certificate from classify.
  const DistanceResult r = classify(A, B, without_filter());
  ASSERT_EQ(r.verdict, Verdict::Overlapping) << r.note;
  ASSERT_TRUE(r.overlap.has_value());
  EXPECT_TRUE(check_overlap(A, B, *r.overlap));
}

TEST(EngineCgalForged, TiltedCylinderRimPushedOut) {
  // Axis (1, 2, 2) (length 3), r = 3: (2, 1, -2) and (2, -2, 1) are unit*3
  // perpendicular to the axis, so +-(2, 1, -2), +-(2, -2, 1) lie on the rim
  // of the bottom cap exactly.
  const Cylinder cyl{{0, 0, 0}, {1, 2, 2}, 3};
  const ConvexShape A = make_shape(cyl);
  const Vec3 rim[4] = {{2, 1, -2}, {-2, -1, 2}, {2, -2, 1}, {-2, 2, -1}};
  for (const Vec3& p : rim) {
    EXPECT_TRUE(contains(A, to_q(p))) << hex(p);
    for (int k = 0; k < 3; ++k) {
      // One ulp away from the axis in coordinate k (radial component grows).
      const Vec3 f = ulp_move(p, k, p[k] > 0 ? 1 : -1);
      const QVec y = to_q(f), ax = to_q(cyl.q);
      const QVec cr = cross(y, ax);
      const bool truth = dot(y, ax) >= 0 && dot(y, ax) <= dot(ax, ax) && dot(cr, cr) <= Q(9) * dot(ax, ax);
      EXPECT_FALSE(truth) << "test bug " << hex(f);
      EXPECT_EQ(contains(A, y), truth) << hex(f);
    }
  }
  // With u = (2, 1, -2), v = (2, -2, 1): the tetrahedron u, -u, v (bottom
  // rim) and q - v (top rim) holds x = q/4 with all barycentric weights 1/4.
  const Vec3 x{0.25, 0.5, 0.5};
  const ConvexShape B = make_point(x);
  const Vec3 a[4] = {{2, 1, -2}, {-2, -1, 2}, {2, -2, 1}, {-1, 4, 1}};
  const Vec3 cap[4] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 2, 2}};
  const OverlapCertificate c = certificate_around(a, x);
  EXPECT_TRUE(check_overlap(A, B, c)) << "genuine tilted rim certificate rejected";
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      const double radial = a[i][k] - cap[i][k];
      if (radial == 0) continue;
      const Vec3 f = ulp_move(a[i], k, radial > 0 ? 1 : -1);
      OverlapCertificate d = c;
      d.a[i] = to_q(f);
      EXPECT_FALSE(check_overlap(A, B, d)) << "forged tilted rim point accepted: a[" << i << "] = " << hex(f);
      // One ulp inwards (towards the axis): inside when the axial
      // coordinate stays within the caps.
      const Vec3 h = ulp_move(a[i], k, radial > 0 ? -1 : 1);
      const QVec y = to_q(h), ax = to_q(cyl.q);
      const QVec cr = cross(y, ax);
      const bool truth = dot(y, ax) >= 0 && dot(y, ax) <= dot(ax, ax) && dot(cr, cr) <= Q(9) * dot(ax, ax);
      d.a[i] = y;
      EXPECT_EQ(check_overlap(A, B, d), truth) << "rim point moved inwards: a[" << i << "] = " << hex(h);
    }
}

TEST(EngineCgalForged, BoxVertexPushedOut) {
  const Obb box{{0.5, -0.25, 1}, {{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}}, {1, 0.5, 0.25}};
  const ConvexShape A = make_shape(box);
  const Vec3 x{0.5, -0.25, 1};  // the centre
  const ConvexShape B = make_point(x);
  // Vertices (-,-,-), (+,-,-), (-,+,-), (-,-,+) ... their tetrahedron does
  // not hold the centre; use (+,+,+) with three of its far neighbours.
  const Vec3 v[4] = {{1.5, 0.25, 1.25}, {-0.5, -0.75, 1.25}, {-0.5, 0.25, 0.75}, {1.5, -0.75, 0.75}};
  const OverlapCertificate c = certificate_around(v, x);
  EXPECT_TRUE(check_overlap(A, B, c)) << "genuine box-vertex certificate rejected";
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      OverlapCertificate d = c;
      const Vec3 f = ulp_move(v[i], k, v[i][k] > x[k] ? 1 : -1);
      d.a[i] = to_q(f);
      EXPECT_FALSE(check_overlap(A, B, d)) << "box vertex pushed out by one ulp accepted: " << hex(f);
      EXPECT_FALSE(check_common_point(A, B, to_q(f)));
      // Pushed in by one ulp: still a valid certificate.
      d.a[i] = to_q(ulp_move(v[i], k, v[i][k] > x[k] ? -1 : 1));
      EXPECT_TRUE(check_overlap(A, B, d)) << "box vertex pushed in by one ulp rejected";
    }
}

TEST(EngineCgalForged, CommonPointOneUlpOutside) {
  // Triangle vertex exactly on the top face of a box (z = 1.25): touching.
  const Obb box{{0.5, -0.25, 1}, {{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}}, {1, 0.5, 0.25}};
  const Triangle t{{0.75, 0, 1.25}, {2, 1, 3}, {-1, 2, 2.5}};
  const ConvexShape A = make_shape(box), B = make_shape(t);
  const DistanceResult r = classify(A, B, without_filter());
  EXPECT_EQ(r.verdict, Verdict::Touching) << r.note;
  EXPECT_TRUE(check_common_point(A, B, to_q(t.a)));
  for (int k = 0; k < 3; ++k)
    for (int dir : {-1, 1}) {
      const Vec3 f = ulp_move(t.a, k, dir);
      EXPECT_FALSE(check_common_point(A, B, to_q(f))) << "point one ulp off the triangle accepted: " << hex(f);
    }
  // The touching plane z = 1.25, tilted by 2^-60: cuts one of the shapes.
  const QVec n{0, 0, 1};
  EXPECT_TRUE(check_separation(A, B, {n}, false));
  EXPECT_FALSE(check_separation(A, B, {n}, true));
  const Q eps = Q(1) / Q(boost::multiprecision::mpz_int(1) << 60);
  for (const QVec& m : {QVec{eps, 0, 1}, QVec{-eps, 0, 1}, QVec{0, eps, 1}, QVec{0, -eps, 1}})
    EXPECT_FALSE(check_separation(A, B, {m}, false)) << "tilted touching plane accepted " << qs(m);
}

TEST(EngineCgalForged, SeparationCheckMatchesExactSupport) {
  // RapidCheck: for grid shapes and a direction near the genuine one, the
  // exact check equals the independent exact support sign.
  const bool ok = rc::check("check_separation == independent support sign", [] {
    const auto gv = [] {
      return rc::gen::apply([](int x, int y, int z) { return Vec3{std::ldexp(x, -10), std::ldexp(y, -10), std::ldexp(z, -10)}; },
                            rc::gen::inRange(-2048, 2049), rc::gen::inRange(-2048, 2049), rc::gen::inRange(-2048, 2049));
    };
    const Vec3 a0 = *gv(), a1 = *gv(), a2 = *gv(), b0 = *gv(), b1 = *gv();
    const Vec3 n = *gv();
    const int tilt = *rc::gen::inRange(0, 80);
    const Shape sa = triangle_shape(a0, a1, a2), sb = segment_shape(b0, b1);
    RC_LOG() << show(sa) << " " << show(sb) << " n " << hex(n) << " tilt 2^-" << tilt << "\n";
    const ConvexShape A = engine_shape(sa), B = engine_shape(sb);
    // Direction: between the inner points, tilted by 2^-tilt * n.
    const QVec base = centroid(qverts(sb)) - centroid(qverts(sa));
    const QVec d = base + (Q(1) / Q(boost::multiprecision::mpz_int(1) << tilt)) * to_q(n);
    RC_PRE(!(d.x == 0 && d.y == 0 && d.z == 0));
    const int s = indep_sep_sign(qverts(sa), qverts(sb), d);
    RC_ASSERT(check_separation(A, B, {d}, true) == (s < 0));
    RC_ASSERT(check_separation(A, B, {d}, false) == (s <= 0));
  });
  EXPECT_TRUE(ok);
}
