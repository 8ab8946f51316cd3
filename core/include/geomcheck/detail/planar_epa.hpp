// geomcheck — internal: EPA in the plane of a circle of normals, shared by
// the consistent contacts of collide_cylinder_obb and
// collide_cylinder_triangle (their headers say what it computes).
//
// On a circle of unit normals n (a great circle: n . a = 0 for a fixed unit
// a) the overlap of a cylinder and a polytope is the support function of
// their Minkowski difference projected along a: a convex body K in the
// plane that contains the origin, whose least support value is the distance
// from the origin to its boundary. Points of K in the order of their
// normals span a polygon inside K; its nearest edge's distance bounds that
// distance from below, and the support along that edge's normal is an
// overlap (from above) and a new vertex.
#pragma once

#include <cmath>
#include <limits>

namespace geomcheck::detail {

/// A point of the plane (coordinates along the frame's two axes).
struct PlanarPt {
  double x, y;
};

/// The rim's share of a cylinder's support along a unit n = (c, sn) of the
/// plane, in an orthonormal frame (k, l, j) with j the circle's axis and
/// u = (uk, ul, uj) the cylinder's unit axis: the projection of
/// n - (n.u) u, computed as u x (n x u), whose components do not cancel
/// where n is near u. t1 = (n x u)_j up to sign; |n x u|^2 = uj^2 + t1^2.
struct RimShare {
  double uk = 0, ul = 0, uj = 0;
  PlanarPt rim(double c, double sn, double t1) const {
    const double uj2 = uj * uj;
    return {ul * t1 + uj2 * c, uj2 * sn - uk * t1};
  }
  /// rim() times f (f = r / |n x u|, given).
  PlanarPt scaled(double c, double sn, double f) const {
    const PlanarPt w = rim(c, sn, c * ul - sn * uk);
    return {f * w.x, f * w.y};
  }
};

/// The starting points of a circle's polygon in counter-clockwise order:
/// axis(q) for the four axis directions q = 0..3 ((1, 0), (0, 1), (-1, 0),
/// (0, -1)) and, when `split`, across(1) and across(-1) for the direction
/// m = (mk, ml) across u (strictly inside a quadrant) and -m, each between
/// the axes that bound its quadrant.
template <class Axis, class Across>
void starting_directions(bool split, double mk, double ml, Axis&& axis, Across&& across) {
  if (split) {
    const int qm = (mk > 0) == (ml > 0) ? (mk > 0 ? 0 : 2) : (mk > 0 ? 3 : 1);
    across(1.0);
    axis((qm + 1) & 3);
    axis((qm + 2) & 3);
    across(-1.0);
    axis((qm + 3) & 3);
    axis(qm);
  } else {
    for (int q = 0; q < 4; ++q) axis(q);
  }
}

/// The polygon of one circle and its EPA steps. A step refines the nearest
/// edge; the refinement stops when (1 + kEps) times the nearest edge's
/// distance reaches the least overlap known (its own or the caller's
/// bound), after kMaxIter steps, or once its least overlap is below
/// `floor` (touching: a lower bound that never leaves zero).
class PlanarEpa {
 public:
  static constexpr double kEps = 1.0 / 64;
  static constexpr int kMaxIter = 64;
  static constexpr int kMax = 12 + kMaxIter + 12;  // the start, a step each, room for ties

  /// The least overlap the steps found below `bound` (found = false: none),
  /// and its direction (c, sn).
  struct Least {
    double o;
    double c = 0, sn = 0;
    bool found = false;
  };

  /// An empty polygon; an edge shorter than sqrt(tiny2) is never the nearest.
  void start(double tiny2) { m_ = 0, tiny2_ = tiny2; }
  void add(PlanarPt p) { px_[m_] = p.x, py_[m_] = p.y, ++m_; }
  PlanarPt last() const { return {px_[m_ - 1], py_[m_ - 1]}; }
  /// The starting points added (counter-clockwise): their edges' distances.
  void close() {
    for (int i = 0; i < m_; ++i) edge(i);
  }

  /// EPA steps (see the class comment); support(c, sn) gives K's support
  /// point along the unit (c, sn). Every edge at the nearest distance is
  /// refined (a tie is refined whole, so that a mirrored or reordered scene
  /// takes the same steps), the last first.
  template <class Support>
  Least refine(double bound, double floor, Support&& support) {
    constexpr double o1 = 1 / (1 + kEps);
    Least own{bound};
    for (int it = 0; it < kMaxIter; ++it) {
      double dm = std::numeric_limits<double>::infinity();
      for (int i = 0; i < m_; ++i) dm = d2_[i] < dm ? d2_[i] : dm;
      const double ob = own.o * o1;
      if (!(dm < ob * std::fabs(ob)) || !(own.o > floor)) break;
      int tied[kMax], nt = 0;
      for (int i = 0; i < m_; ++i)
        if (d2_[i] == dm) tied[nt++] = i;
      if (m_ + nt > kMax) break;
      for (int q = nt - 1; q >= 0; --q) {
        const int im = tied[q], i1 = im + 1 == m_ ? 0 : im + 1;
        const double dx = px_[i1] - px_[im], dy = py_[i1] - py_[im];
        const double il = 1 / std::sqrt(dx * dx + dy * dy);
        const double c = dy * il, sn = -dx * il;  // the edge's outward normal
        if (!(std::fabs(c) <= 1 && std::fabs(sn) <= 1)) return own;  // too short to have one
        const PlanarPt p = support(c, sn);
        const double g = c * p.x + sn * p.y;
        if (g < own.o) own.o = g, own.c = c, own.sn = sn, own.found = true;
        for (int i = m_; i > im + 1; --i) px_[i] = px_[i - 1], py_[i] = py_[i - 1], d2_[i] = d2_[i - 1];
        px_[im + 1] = p.x, py_[im + 1] = p.y;
        ++m_;
        edge(im);
        edge(im + 1);
      }
    }
    return own;
  }

 private:
  // Edge i (point i to point i + 1): its signed squared distance from the
  // origin, cross * |cross| / length^2 (no square root; in the distances'
  // order). An edge shorter than sqrt(tiny2) joins two points that are one
  // to rounding (their line is noise): it is never the nearest, which is
  // the polygon with those points merged, to rounding.
  void edge(int i) {
    const int i1 = i + 1 == m_ ? 0 : i + 1;
    const double dx = px_[i1] - px_[i], dy = py_[i1] - py_[i];
    const double l2 = dx * dx + dy * dy;
    const double cr = px_[i] * py_[i1] - py_[i] * px_[i1];
    d2_[i] = l2 > tiny2_ ? cr * std::fabs(cr) / l2 : std::numeric_limits<double>::infinity();
  }

  int m_ = 0;
  double tiny2_ = 0;
  double px_[kMax], py_[kMax], d2_[kMax];
};

}  // namespace geomcheck::detail
