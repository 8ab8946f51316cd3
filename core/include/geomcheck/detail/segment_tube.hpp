// geomcheck — internal: where a segment lies inside a (possibly augmented)
// cylinder, as an interval of its parameter. Shared by the segment cast and
// stage 1 of the swept-sphere query, so both decide alike.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/vec3.hpp"

namespace geomcheck::detail {

/// The parameters t of the line m + t n (m measured from the cylinder's cap
/// centre p) at which the point lies in the slab -ext <= axial <= len + ext
/// along the unit axis u AND within radius R of the axis: the intersection
/// of the slab interval with the infinite cylinder's interval (accepting by
/// interval, not feature by feature, leaves no gap at the rim).
struct TubeInterval {
  bool empty = true;
  double entry = 0, exit = 0;  ///< valid when !empty
  bool side_entry = false;     ///< entry through the side (else a cap plane)
  bool cap_q = false;          ///< cap-plane entry at the q end (else p)
  /// The two intervals (+-inf when unbounded), valid when the line meets
  /// the infinite cylinder and the slab.
  /// NaN where not computed (the line misses the infinite cylinder or the slab).
  double slab_lo = NAN, slab_hi = NAN, cyl_lo = NAN, cyl_hi = NAN;
};

inline TubeInterval tube_interval(Vec3 m, Vec3 n, Vec3 u, double len, double ext, double R) {
  TubeInterval out;
  const double mu = dot(m, u);
  const double nu = dot(n, u);
  const Vec3 mxu = cross(m, u);
  const Vec3 nxu = cross(n, u);
  // |perp(S(t))|^2 - R^2 = qa t^2 + 2 qb t + qc
  const double qa = dot(nxu, nxu);
  const double qb = dot(mxu, nxu);
  const double qc = dot(mxu, mxu) - R * R;
  const double inf = std::numeric_limits<double>::infinity();
  double slab_lo = -inf, slab_hi = inf;
  if (nu == 0) {
    if (mu < -ext || mu > len + ext) return out;
  } else {
    slab_lo = (-ext - mu) / nu;
    slab_hi = (len + ext - mu) / nu;
    if (slab_lo > slab_hi) std::swap(slab_lo, slab_hi);
  }
  double cyl_lo = -inf, cyl_hi = inf;
  if (qa == 0) {
    if (qc > 0) return out;  // parallel to the axis and outside the radius
  } else {
    // disc = qb^2 - qa qc, in the form that cannot cancel:
    //  * qc <= 0 (start inside the infinite cylinder): qb^2 + qa |qc|, a sum
    //    of non-negative terms (cast regression 0003: a segment parallel to
    //    the axis to 1e-15 rad, where |n x u| is rounding noise);
    //  * qc > 0: R^2 |n x u|^2 - (n.(m x u))^2 by Lagrange's identity, the
    //    triple product being the lines' offset (cast regression 0001: the
    //    textbook form cancels when the line passes near the axis).
    double sq;
    if (qc <= 0) {
      sq = std::sqrt(qb * qb - qa * qc);
    } else {
      const double triple = dot(n, mxu);
      const double disc = R * R * qa - triple * triple;
      if (disc < 0) return out;
      sq = std::sqrt(disc);
    }
    // Roots without cancellation: k / qa and qc / k with k = -(qb + sign(qb) sq).
    // qb == 0 takes +sq whatever the sign of the zero: a reflected scene
    // gives -0 where the original gives +0, and must get the same roots
    // (collide_cylinder_capsule regression 0001).
    const double k = -(qb + (qb < 0 ? -sq : sq));
    if (k == 0) {
      cyl_lo = cyl_hi = 0;
    } else {
      cyl_lo = k / qa;
      cyl_hi = qc / k;
      if (cyl_lo > cyl_hi) std::swap(cyl_lo, cyl_hi);
    }
  }
  out.entry = std::max(slab_lo, cyl_lo);
  out.exit = std::min(slab_hi, cyl_hi);
  out.empty = !(out.entry <= out.exit);
  out.side_entry = !(slab_lo >= cyl_lo);
  out.cap_q = !(nu > 0);
  out.slab_lo = slab_lo;
  out.slab_hi = slab_hi;
  out.cyl_lo = cyl_lo;
  out.cyl_hi = cyl_hi;
  return out;
}

}  // namespace geomcheck::detail
