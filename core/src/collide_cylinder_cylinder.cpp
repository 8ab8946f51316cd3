#include "geomcheck/collide_cylinder_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/cylinder_pair.hpp"
#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

namespace detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Newton on a circle of normals stops when its half-angle step is below
// this (the angle is then rounding),
constexpr double kStopHalf = 0x1p-40;
// Or when the step would lower the overlap by less than this fraction of it:
// the stop is relative to the depth, so that a shallow contact between large
// cylinders (overlap 4 at radii of 1e9, where an angle of 2^-9 weighs 2000)
// is searched as far as a deep one.
constexpr double kStopGain = 0x1p-12;
// The earlier absolute stop (a half-angle of 2^-10; CylinderPairOptions::relative_stop off).
constexpr double kStopHalfAbsolute = 0x1p-10;

// -1 where `neg`, else 1, without a branch; multiplying by it is the
// negation or the identity, bit for bit.
inline double sign_if(bool neg) { return 1.0 - 2.0 * double(neg); }

// The roles: the frame cylinder ("B", its axis is z) comes first in this
// order, so that (a, b) and (b, a) run the same computation: the larger
// radius, then the longer axis, then the larger sum of squares of the end
// points. The keys are invariant under swapping a cylinder's caps,
// reflections, point inversion and power-of-two scalings (the half length is
// a function of a sum of squares, and scales with the scene), so those keep
// the roles.
// A cylinder's unit axis, half length and middle (in the scaled scene).
struct Axis {
  Vec3 u;
  double half;
  Vec3 mid;
};

// One term of G: c - al * kA(y) - be * kB(y).
struct Term {
  double c, al, be;
};

// The pair in a canonical frame of B: origin B's centre, z along B's axis,
// y the common perpendicular, x completing the frame. A's centre is at
// (X0, y0, Z0) and its axis direction is (sX, 0, cZ); the signs of x, y, z
// and of A's direction are chosen so that X0, y0, Z0, sX >= 0 (ties broken
// by sX * cZ >= 0). Every such choice describes the same pair (B is
// symmetric in each coordinate plane through its centre, A's axis has no
// direction), so swapping either cylinder's caps, which flips z or u_A
// exactly, gives the same canonical numbers bit for bit, and the answer
// depends on nothing else.
//
// In a slice y = const, B is the rectangle |X| <= kB(y), |Z| <= hB and A the
// rectangle |a - a0| <= hA, |b - b0| <= kA(y) in A's coordinates a = (X, Z)
// . (sX, cZ), b = (X, Z) . (cZ, -sX), with k the half widths
// sqrt(r^2 - (y - y_axis)^2).
struct Frame {
  double rA, rB, hA, hB;
  Vec3 origin, x, y, z, uA;
  double sX, cZ, cZa, X0, y0, Z0, a0, b0;
  Term t[4];
  double lo, hi;  // the slices where both cylinders have a section

  Frame(double radius_a, const Axis& axA, double radius_b, const Axis& axB, const CylinderPairOptions& opt)
      : rA(radius_a), rB(radius_b), hA(axA.half), hB(axB.half) {
    uA = axA.u;
    z = axB.u;
    origin = axB.mid;
    const Vec3 v = axA.mid - origin;
    const double c = dot(uA, z);
    // The common perpendicular. u_B x u_A loses digits as 1 / theta (the
    // products cancel); u_B x (u_A -+ u_B) does not: the difference of two
    // near-equal unit vectors is exact or nearly so, and the cross product
    // of u_B with it has no cancellation. (Below 60 degrees from
    // perpendicular only: the branch depends on |c|, so that flipping
    // either axis negates the cross product exactly.)
    // (k is 0 or +-1, from the sign bit; uA - 0 z is uA up to the sign of
    // a zero component, and uA - (-1) z is uA + z exactly.)
    const double k = opt.accurate_frame && std::fabs(c) > 0.5 ? std::copysign(1.0, c) : 0.0;
    const Vec3 cr = cross(z, uA - k * z);
    double sx0, cz0;
    if (max_abs(cr) == 0 && opt.parallel_branch) {
      // Parallel or anti-parallel axes: x towards A's axis, y = 0 through
      // both.
      x = unit_perpendicular_part(v, z);
      y = cross(z, x);
      y0 = 0;
      sx0 = 0;
      cz0 = c;
      X0 = dot(x, v);
    } else {
      // The products with the unnormalised cr and xr = cr x z (as long as
      // cr, which is perpendicular to z) go alongside the square root and
      // the division, off the critical path; the scale comes last. cr is
      // first scaled by a power of two (exact) where its square would leave
      // the normal range. (cr = 0 only without the parallel branch: inv is
      // infinite and the frame NaN, that tooth's failure.)
      Vec3 cs = cr;
      if (const double m = max_abs(cr), l2 = dot(cr, cr); m > 0 && !(l2 > kSafeLo * kSafeLo && l2 < kSafeHi * kSafeHi))
        cs = scaled_down(cr, m);
      const Vec3 xr = cross(cs, z);
      const double yv = dot(cs, v), xv = dot(xr, v), xu = dot(xr, uA);
      const double inv = (yv == 0 ? 1.0 : std::copysign(1.0, yv)) / std::sqrt(dot(cs, cs));
      y = inv * cs, y0 = inv * yv;
      x = inv * xr, X0 = inv * xv, sx0 = inv * xu;
      cz0 = dot(z, uA);
    }
    Z0 = dot(z, v);
    // The canonical signs (see above). Each is a coin toss on random
    // poses, so it is taken from the sign bit (no branch to mispredict);
    // only the ties, a zero coordinate, branch.
    double fx = std::copysign(1.0, X0);
    if (X0 == 0) fx = sign_if(sx0 * cz0 < 0);
    x = fx * x, X0 = fx * X0, sx0 = fx * sx0;
    double fz = std::copysign(1.0, Z0);
    if (Z0 == 0) fz = sign_if(sx0 * cz0 < 0);
    z = fz * z, Z0 = fz * Z0, cz0 = fz * cz0;
    double fu = std::copysign(1.0, sx0);
    if (sx0 == 0) fu = sign_if(cz0 < 0);
    uA = fu * uA, sx0 = fu * sx0, cz0 = fu * cz0;
    X0 = std::fabs(X0), Z0 = std::fabs(Z0), y0 = std::fabs(y0);  // no -0
    sX = sx0, cZ = cz0, cZa = std::fabs(cZ);
    a0 = sX * X0 + cZ * Z0;
    b0 = std::fabs(cZ * X0 - sX * Z0);
    // The separating axes of the two rectangles of a slice: B's cap planes
    // (the false-positive planes: A reaches kA sX beyond its axis along z),
    // B's side, A's cap planes, A's side.
    t[0] = {Z0 - hB - hA * cZa, sX, 0};
    t[1] = {X0 - hA * sX, cZa, 1};
    t[2] = {std::fabs(a0) - hA - hB * cZa, 0, sX};
    t[3] = {b0 - hB * sX, 1, cZa};
    if (!opt.false_positive_planes) {
      // The augmented cylinders' square ends: the full reach r sin theta
      // at every slice (corner false positives).
      t[0].c -= sX * rA, t[0].al = 0;
      t[2].c -= sX * rB, t[2].be = 0;
    }
    lo = std::max(-rB, y0 - rA);
    hi = std::min(rB, y0 + rA);
  }

  double kA(double yy) const {
    const double d = yy - y0;
    return std::sqrt(std::max(0.0, (rA - d) * (rA + d)));
  }
  double kB(double yy) const { return std::sqrt(std::max(0.0, (rB - yy) * (rB + yy))); }

  // G(y) and, where G > 0, the slope of its active term (+-inf at the ends
  // of [lo, hi]).
  double eval(double yy, double& slope) const {
    const double ka = kA(yy), kb = kB(yy);
    // The largest term and its index, by selects (which term wins is a coin
    // toss on random poses: a branch would be mispredicted).
    double g = t[0].c - t[0].al * ka - t[0].be * kb;
    int best = 0;
    for (int j = 1; j < 4; ++j) {
      const double v = t[j].c - t[j].al * ka - t[j].be * kb;
      best = v > g ? j : best;
      g = v > g ? v : g;
    }
    slope = 0;
    if (g <= 0) return g;  // decided: no slope needed
    if (t[best].al != 0) slope += t[best].al * ((yy - y0) / ka);
    if (t[best].be != 0) slope += t[best].be * (yy / kb);
    return g;
  }

  // The overlap of the shapes along a great circle of unit normals:
  //   f(P, Q) = R1 + R2 sqrt(P^2 + cZ^2 Q^2) + K Q - y0 P,  P, Q >= 0,
  // with its first two derivatives in the angle (P = cos, Q = sin). The
  // circle perpendicular to u_A (A's side against B) is n = -(P y + Q nA'),
  // nA' = A's side normal towards A's centre side, with R1 = rA, R2 = rB,
  // K = hB sX - |b0|; the circle perpendicular to u_B (B's side against A)
  // is n = -(P y + Q x) with R1 = rB, R2 = rA, K = hA sX - X0. Both are
  // h_A(n) + h_B(-n); the square root is written without the cancelling
  // 1 - sX^2 Q^2.
  struct Circle {
    double R1, R2, K, y0, c2, s2;
    double value(double P, double Q, double& S) const {
      S = std::sqrt(P * P + c2 * Q * Q);
      return R1 + R2 * S + K * Q - y0 * P;
    }
    // Half the Newton step in the angle at (P, Q), -f' / (2 f''), as the
    // fraction a / b (b > 0; both derivatives multiplied by S^3), clamped
    // to +-1/4; a fixed 1/8 downhill where f'' <= 0, and towards P > 0 from
    // the kink S = 0 (cZ = 0 at Q = 1: rim against side). As a fraction, the
    // rotation by it needs one division, not two.
    void half_step(double P, double Q, double S, double& a, double& b, double& gain) const {
      gain = kInf;
      if (!(S > 0)) {
        a = -1, b = 8;
        return;
      }
      const double S2 = S * S, S3 = S2 * S, pq = P * Q;
      const double d1 = -R2 * s2 * pq * S2 + (K * P + y0 * Q) * S3;
      const double d2 = -R2 * s2 * ((P * P - Q * Q) * S2 + s2 * pq * pq) + (y0 * P - K * Q) * S3;
      if (!(d2 > 0)) {
        a = d1 > 0 ? -1 : 1, b = 8;
        return;
      }
      // What the full Newton step would gain: f'^2 / (2 f'') = d1^2 / (2 d2 S^3).
      gain = d1 * (d1 / (2 * d2 * S3));
      a = -d1, b = 2 * d2;
      if (!(b > 0x1p-400 && b < 0x1p+400)) a = a / b, b = 1;  // squares kept normal
      if (!(std::fabs(a) <= 0.25 * b)) a = std::copysign(1.0, a), b = 4;
    }
    // A lower bound of f on the quarter circle from S >= P: R1 plus the
    // minimum of the linear (R2 - y0) P + K Q there.
    double lower_bound() const {
      const double a = R2 - y0, b = K;
      return a < 0 && b < 0 ? -kInf : R1 + std::min(a, b);
    }
    // Newton on the angle from (P, Q), each step kept only if it lowers f
    // (halved once otherwise), kept in the quadrant. The rotation by the
    // step is the rational one (tan of half the angle), unit to rounding
    // without a square root.
    double min(double& P, double& Q, double end_q1, int steps, bool relative_stop) const {
      double S;
      double o = value(P, Q, S);
      // Or an end of the quadrant, if lower (their values are known).
      const double end_p1 = R1 + R2 - y0;
      if (end_p1 < o || end_q1 < o) {
        if (end_p1 <= end_q1) P = 1, Q = 0, o = end_p1, S = 1;
        else P = 0, Q = 1, o = end_q1, S = std::sqrt(c2);
      }
      for (int it = 0; it < steps; ++it) {
        double a, b, gain;
        half_step(P, Q, S, a, b, gain);
        if (relative_stop ? (std::fabs(a) <= kStopHalf * b || gain <= kStopGain * o)
                          : std::fabs(a) <= kStopHalfAbsolute * b) {
          // Converged by the local model, unless that is the kink's: within
          // P <= 2 Q |cZ| of the end Q = 1, |cZ| < 1/16 (a rim nearly across a side), the
          // square root's curvature, R2 sX^2 / |cZ|, makes Newton's step tiny
          // and its gain look spent while f goes on falling far beyond (a
          // perpendicular cap on a side: the end 5.4 times the minimum 1.2
          // rad away). There a fixed step out of the kink is tried first.
          if (!(relative_stop && a < 0 && c2 < 0x1p-8 && P <= 2 * Q * std::sqrt(c2))) break;
          a = -1, b = 8;
        }
        bool moved = false;
        for (int k = 0; k < 2 && !moved; ++k, b *= 2) {
          // The rotation by the angle of half-angle tangent t = a / b:
          // ((1 - t^2), 2 t) / (1 + t^2), here times b^2 / b^2.
          const double a2 = a * a, b2 = b * b, w = 1 / (a2 + b2), cr = (b2 - a2) * w, sr = 2 * a * b * w;
          double P2 = P * cr - Q * sr, Q2 = Q * cr + P * sr;
          if (P2 < 0) P2 = 0, Q2 = 1;  // past an end of the quadrant: the end
          if (Q2 < 0) P2 = 1, Q2 = 0;
          double S2;
          const double o2 = value(P2, Q2, S2);
          if (o2 < o) {
            P = P2, Q = Q2, o = o2, S = S2, moved = true;
            // A full step that was kept, where f is far from quadratic (a
            // hyperbola's arm, rim against side at a shallow angle), may be
            // short: the same rotation again while it lowers f (at most 3).
            for (int j = 0; k == 0 && j < 3 && relative_stop; ++j) {
              double P3 = P * cr - Q * sr, Q3 = Q * cr + P * sr, S3;
              if (!(P3 >= 0 && Q3 >= 0)) break;
              const double o3 = value(P3, Q3, S3);
              if (!(o3 < o)) break;
              P = P3, Q = Q3, o = o3, S = S3;
            }
          }
        }
        if (!moved) break;
      }
      return o;
    }
  };
  Circle circle_a() const { return {rA, rB, hB * sX - b0, y0, cZ * cZ, sX * sX}; }
  Circle circle_b() const { return {rB, rA, hA * sX - X0, y0, cZ * cZ, sX * sX}; }
  // A's side normal cZ x - sX z, turned towards A's centre (from B's).
  // The sign that turns A's side normal cZ x - sX z towards A's centre.
  double nA_sign() const { return cZ * X0 - sX * Z0 >= 0 ? 1.0 : -1.0; }
  Vec3 nA_signed() const { return nA_sign() * (cZ * x - sX * z); }

  // A point of both rectangles of slice yy, in (X, Z).
  void common_point(double yy, double& X, double& Z) const {
    const double ka = kA(yy), kb = kB(yy);
    const double bs = cZ * X0 - sX * Z0;  // b0 with its sign
    // Rounding of the tests below (a few ulps of the largest term), far
    // inside the point bound.
    const double slack = 0x1p-50 * std::max(std::max(std::max(X0, Z0), std::max(hA, hB)), std::max(rA, rB));
    auto a_of = [&](double xx, double zz) { return xx * sX + zz * cZ; };
    auto b_of = [&](double xx, double zz) { return xx * cZ - zz * sX; };
    // How far (X, Z) is outside A's and B's rectangles (<= 0: inside).
    auto out_a = [&](double xx, double zz) {
      return std::max(std::fabs(a_of(xx, zz) - a0) - hA, std::fabs(b_of(xx, zz) - bs) - ka);
    };
    auto out_b = [&](double xx, double zz) { return std::max(std::fabs(xx) - kb, std::fabs(zz) - hB); };
    // Cheap first: A's centre clamped into B, then B's centre clamped into
    // A; either is in both whenever the rectangles cross (the usual case).
    X = std::min(X0, kb);
    Z = std::min(Z0, hB);
    if (out_a(X, Z) <= slack) return;
    {
      const double a = std::clamp(0.0, a0 - hA, a0 + hA), b = std::clamp(0.0, bs - ka, bs + ka);
      const double xx = a * sX + b * cZ, zz = a * cZ - b * sX;
      if (out_b(xx, zz) <= slack) {
        X = std::clamp(xx, -kb, kb), Z = std::clamp(zz, -hB, hB);
        return;
      }
    }
    // A's rectangle clipped by B's four sides (Sutherland-Hodgman); the
    // centre of the vertices.
    double buf[2][2][8];
    double* px = buf[0][0];
    double* pz = buf[0][1];
    double* qx = buf[1][0];
    double* qz = buf[1][1];
    const double ux = hA * sX, uz = hA * cZ, nx = ka * cZ, nz = -ka * sX;
    const double cx = X0, cz = Z0;
    double vx[8], vz[8];  // A's corners, then B's
    vx[0] = cx + ux + nx, vz[0] = cz + uz + nz;
    vx[1] = cx - ux + nx, vz[1] = cz - uz + nz;
    vx[2] = cx - ux - nx, vz[2] = cz - uz - nz;
    vx[3] = cx + ux - nx, vz[3] = cz + uz - nz;
    vx[4] = kb, vz[4] = hB;
    vx[5] = -kb, vz[5] = hB;
    vx[6] = -kb, vz[6] = -hB;
    vx[7] = kb, vz[7] = -hB;
    int n = 4;
    for (int i = 0; i < 4; ++i) px[i] = vx[i], pz[i] = vz[i];
    for (int side = 0; side < 4 && n > 0; ++side) {
      const bool on_x = side < 2;
      const double sign = (side & 1) ? -1.0 : 1.0;
      const double bound = on_x ? kb : hB;
      const double* pa = on_x ? px : pz;
      int m = 0;
      double vi = sign * pa[0] - bound;
      for (int i = 0; i < n; ++i) {
        const int j = i + 1 == n ? 0 : i + 1;
        const double vj = sign * pa[j] - bound;
        if (vi <= 0) qx[m] = px[i], qz[m] = pz[i], ++m;
        if ((vi < 0 && vj > 0) || (vi > 0 && vj < 0)) {
          const double t = vi / (vi - vj);
          qx[m] = on_x ? sign * bound : px[i] + t * (px[j] - px[i]);
          qz[m] = on_x ? pz[i] + t * (pz[j] - pz[i]) : sign * bound;
          ++m;
        }
        vi = vj;
      }
      n = m;
      std::swap(px, qx);
      std::swap(pz, qz);
    }
    if (n > 0) {
      double sx = 0, sz = 0;
      for (int i = 0; i < n; ++i) sx += px[i], sz += pz[i];
      X = std::clamp(sx / n, -kb, kb);
      Z = std::clamp(sz / n, -hB, hB);
      if (out_a(X, Z) <= slack) return;
    }
    // Touching to rounding (the rectangles share a vertex or an edge): the
    // corner of one that is least outside the other.
    double worst = kInf;
    for (int i = 0; i < 8; ++i) {
      const double o = i < 4 ? out_b(vx[i], vz[i]) : out_a(vx[i], vz[i]);
      if (o < worst) worst = o, X = vx[i], Z = vz[i];
    }
    X = std::clamp(X, -kb, kb);
    Z = std::clamp(Z, -hB, hB);
  }
};

// Is min over [lo, hi] of the convex G at most 0? On success `ybest` is a
// slice with G <= 0 (or the best found when the answer is decided only to
// `tol`).
bool slices_meet(const Frame& f, double tol, double& ybest) {
  double lo = f.lo, hi = f.hi;
  const double r = std::max(f.rA, f.rB);
  double slope;
  if (!(hi > lo)) {  // one slice (a radius 0, or the axes' lines rA + rB apart)
    ybest = lo;
    return f.eval(lo, slope) <= tol;
  }
  // The engine's slice: in the scaled space A's axis line passes at y0 from
  // B's axis and the augmented section is a circle of radius rA + rB, widest
  // where it divides y0 as rB : rA. It maximises kA + kB; with the axes
  // parallel it is the answer.
  double yy = f.rA + f.rB > 0 ? f.y0 * (f.rB / (f.rA + f.rB)) : 0.0;
  yy = std::clamp(yy, lo, hi);
  struct Tangent {
    double y = 0, g = 0, d = 0;
    bool ok = false;
  } L, R;
  double best = kInf, width_before = hi - lo;
  ybest = yy;
  for (int it = 0; it < 100; ++it) {
    const double g = f.eval(yy, slope);
    if (g < best) best = g, ybest = yy;
    if (g <= 0) return true;
    if (slope > 0) {
      hi = yy;
      if (std::isfinite(slope)) R = {yy, g, slope, true};
    } else if (slope < 0) {
      lo = yy;
      if (std::isfinite(slope)) L = {yy, g, slope, true};
    } else {
      return false;  // a stationary point: the minimum, and it is > 0
    }
    // A lower bound of G on [lo, hi] from the tangents (convexity).
    double lb = -kInf, ycut = 0.5 * (lo + hi);
    if (L.ok && R.ok) {
      ycut = (R.g - L.g + L.d * L.y - R.d * R.y) / (L.d - R.d);
      ycut = std::clamp(ycut, lo, hi);
      lb = std::max(L.g + L.d * (ycut - L.y), R.g + R.d * (ycut - R.y));
    } else if (L.ok) {
      lb = L.g + L.d * (hi - L.y);
    } else if (R.ok) {
      lb = R.g + R.d * (lo - R.y);
    }
    if (lb > 0) return false;
    if (best - lb <= tol || hi - lo <= 0x1p-52 * r) break;
    // Next: the tangents' crossing, kept off the ends of the bracket; a
    // bisection whenever two steps did not halve it.
    const double w = hi - lo;
    double next = ycut;
    if (!(L.ok && R.ok) || (it % 2 == 1 && w > 0.5 * width_before)) next = 0.5 * (lo + hi);
    if (it % 2 == 1) width_before = w;
    yy = std::clamp(next, lo + w * 0x1p-4, hi - w * 0x1p-4);
  }
  return best <= tol;
}

// The best direction refined on the sphere of directions: from n (frame
// coordinates in m), safeguarded Newton steps for the overlap along m,
//   F(m) = hA |m.u_A| + rA |m - (m.u_A) u_A| + hB |m_z| + rB |(m_x, m_y)| + m.C_A,
// with the signs of m.u_A and m_z held over a step (a step across a sign
// is evaluated as it is). F is convex and of degree 1 in R^3, so on the
// sphere its gradient is the tangential part of grad F and its Hessian the
// tangential part of Hess F less F times the identity. A step is kept only
// if it lowers F (halved until it does, 30 times at most); the search stops
// when a step would gain less than kStopGain of F, or after `steps`.
//
// The candidates above end on F's kinks: the circles of side normals
// (m.u_A = 0, m_z = 0) and the axes (where a side's term is a cone). There
// the search first asks whether F falls off the kink: the slope of F's
// smooth rest against the kink's own rise (h per radian across a circle,
// r per radian off an axis). Where it does not (a true minimum of the
// kink's patch, the common case) the search ends there, after a few dozen
// operations; where it does, F is followed down that way (a step of 1/4,
// halved until F is lower) and the Newton steps go on from there: the
// minimum then lies in the rim x rim patch, off every circle. A start off
// every kink (the rim x rim direction) is taken as it is: Newton from it
// made the query about 1.6 times slower on contacts for a max depth ratio
// of 1.09 instead of 1.35 over the campaign's first 20000 cases.
double refine_rims(const Frame& f, Vec3& m, double o, int steps) {
  const Vec3 u{f.sX, 0, f.cZ}, C{f.X0, f.y0, f.Z0};
  auto F = [&](Vec3 v) {
    const double t = dot(v, u);
    const Vec3 pa = v - t * u;
    return f.hA * std::fabs(t) + f.rA * std::sqrt(dot(pa, pa)) + f.hB * std::fabs(v.z) +
           f.rB * std::sqrt(v.x * v.x + v.y * v.y) + dot(v, C);
  };
  constexpr double kKink = 0x1p-30;
  auto descend = [&](Vec3 w) {  // a step of 1/4 along w, halved until F is lower
    for (double th = 0.25; th > 0x1p-60; th *= 0.5) {
      Vec3 m2 = m + th * w;
      m2 = (1 / std::sqrt(dot(m2, m2))) * m2;
      const double o2 = F(m2);
      if (o2 < o) {
        m = m2, o = o2;
        return true;
      }
    }
    return false;
  };
  for (int it = 0; it < steps; ++it) {
    const double t = dot(m, u);
    const bool on_a = std::fabs(t) <= kKink, on_b = std::fabs(m.z) <= kKink;
    if (on_a && on_b) break;  // two kinks (the common perpendicular): left as found
    if (on_a) {
      // Across circle a (|Pa m| = 1 there): F's slope along +-u_A is
      // +-(the rest of grad F).u_A + hA.
      const double rb = std::sqrt(m.x * m.x + m.y * m.y);
      if (!(rb > kKink)) break;
      const double ga = dot(C, u) + f.rB * (m.x * u.x) / rb + f.hB * std::copysign(1.0, m.z) * u.z;
      if (!(std::fabs(ga) > f.hA) || !descend((ga > 0 ? -1.0 : 1.0) * u)) break;
      continue;
    }
    if (on_b) {
      // Across circle b (|m_xy| = 1 there): along +-z, +-(the rest).z + hB.
      const double ra2 = 1 - t * t;
      if (!(ra2 > kKink * kKink)) break;
      const double ra = std::sqrt(ra2);
      const double gz = C.z + f.hA * std::copysign(1.0, t) * u.z - f.rA * (t * u.z) / ra;
      if (!(std::fabs(gz) > f.hB) || !descend(Vec3{0, 0, gz > 0 ? -1.0 : 1.0})) break;
      continue;
    }
    const Vec3 pa = m - t * u;
    const double ra = std::sqrt(dot(pa, pa)), rb = std::sqrt(m.x * m.x + m.y * m.y);
    const bool axis_a = ra <= kKink, axis_b = rb <= kKink;
    if (axis_a || axis_b) {
      if (axis_a && axis_b) break;
      // Off an axis: every way F rises by r, plus the rest's slope.
      Vec3 gs = C;
      if (axis_a) gs = gs + (f.hA * std::copysign(1.0, t)) * u + Vec3{f.rB / rb * m.x, f.rB / rb * m.y, 0};
      else gs = gs + (f.rA / ra) * pa + Vec3{0, 0, f.hB * std::copysign(1.0, m.z)};
      gs = gs + (axis_a ? Vec3{0, 0, f.hB * std::copysign(1.0, m.z)} : (f.hA * std::copysign(1.0, t)) * u);
      const Vec3 gt = gs - dot(gs, m) * m;
      const double gl = std::sqrt(dot(gt, gt));
      if (!(gl > (axis_a ? f.rA : f.rB)) || !descend((-1 / gl) * gt)) break;
      continue;
    }
    if (it == 0) break;  // a start off every kink is taken as it is (see above)
    const Vec3 qa = (1 / ra) * pa, qb{m.x / rb, m.y / rb, 0};
    const Vec3 g = (f.hA * std::copysign(1.0, t)) * u + f.rA * qa + Vec3{0, 0, f.hB * std::copysign(1.0, m.z)} +
                   f.rB * qb + C;
    const Vec3 e1 = any_perpendicular(m), e2 = cross(m, e1);
    const double g1 = dot(e1, g), g2 = dot(e2, g);
    // Hess F (v, w) = rA / ra (v.w - (v.u)(w.u) - (v.qa)(w.qa)) + rB / rb (v_xy.w_xy - (v.qb)(w.qb)).
    auto hess = [&](Vec3 v, Vec3 w) {
      return f.rA / ra * (dot(v, w) - dot(v, u) * dot(w, u) - dot(v, qa) * dot(w, qa)) +
             f.rB / rb * (v.x * w.x + v.y * w.y - dot(v, qb) * dot(w, qb));
    };
    const double h11 = hess(e1, e1) - o, h12 = hess(e1, e2), h22 = hess(e2, e2) - o;
    const double det = h11 * h22 - h12 * h12;
    double d1, d2, gain;
    if (h11 > 0 && det > 0) {
      d1 = -(h22 * g1 - h12 * g2) / det, d2 = -(h11 * g2 - h12 * g1) / det;
      gain = -0.5 * (g1 * d1 + g2 * d2);
    } else {
      const double gl = std::sqrt(g1 * g1 + g2 * g2);
      if (!(gl > 0)) break;
      d1 = -0.125 * g1 / gl, d2 = -0.125 * g2 / gl, gain = kInf;
    }
    if (!(gain > kStopGain * o)) break;
    const double dl = std::sqrt(d1 * d1 + d2 * d2);
    // At most 1/4, and at most half the way to the nearer axis: F's terms
    // there are cones, whose tips the quadratic model does not see (two wide
    // cylinders stacked 1e-4 from anti-parallel: Newton's step 10 times the
    // distance to the tips, halved 4 times in vain, stopped the search at 4.8
    // times the penetration depth).
    const double cap = std::min(0.25, 0.5 * std::min(ra, rb));
    if (dl > cap) d1 *= cap / dl, d2 *= cap / dl;
    // A step across a kink stops on it (the kink's own test decides next).
    bool moved = false;
    const double o_before = o;
    for (int k = 0; k < 4 && !moved; ++k, d1 *= 0.5, d2 *= 0.5) {
      Vec3 m2 = m + d1 * e1 + d2 * e2;
      const double t2 = dot(m2, u);
      if ((t2 > 0) != (t > 0)) m2 = m2 - t2 * u;
      if ((m2.z > 0) != (m.z > 0)) m2.z = 0;
      m2 = (1 / std::sqrt(dot(m2, m2))) * m2;
      const double o2 = F(m2);
      if (o2 < o) m = m2, o = o2, moved = true;
      // A full step that was kept may be far short where F is far from
      // quadratic (near an axis, a side's term is a cone: shallow contacts
      // of wide cylinders meeting at their rims took 20 Newton steps
      // growing by 1.5 each). The step, doubled, again while it lowers F
      // (at most 4 times), stopping on a kink it would cross.
      Vec3 dir = d1 * e1 + d2 * e2;
      for (int j = 0; moved && k == 0 && j < 4; ++j) {
        dir = 2 * dir;
        const double tm = dot(m, u);
        Vec3 m3 = m + dir;
        const double t3 = dot(m3, u);
        const bool cross_a = (t3 > 0) != (tm > 0), cross_b = (m3.z > 0) != (m.z > 0);
        if (cross_a) m3 = m3 - t3 * u;
        if (cross_b) m3.z = 0;
        m3 = (1 / std::sqrt(dot(m3, m3))) * m3;
        const double o3 = F(m3);
        if (!(o3 < o)) break;
        m = m3, o = o3;
        if (cross_a || cross_b) break;
      }
    }
    if (!moved || o_before - o <= kStopGain * 0x1p-8 * o) break;
  }
  return o;
}

Contact scaled(const Cylinder& a, const Axis& ax_a, const Cylinder& b, const Axis& ax_b, bool want_contact,
               const CylinderPairOptions& opt) {
  // The false-positive planes before the frame (step 1): either
  // cylinder's cap planes pushed out by the other's reach along its axis,
  // h |cos theta| + r sin theta, here with r for r sin theta (no square
  // root, no frame). Beyond them: no overlap. Weaker than the frame's own
  // cap terms by r (1 - sin theta) and by a margin of 2^-40 of the scene
  // (their rounding), so that it answers only where those would. Part of
  // the false-positive planes: switched off with them.
  if (opt.false_positive_planes) {
    const Vec3 v = ax_a.mid - ax_b.mid;
    const double c = std::fabs(dot(ax_a.u, ax_b.u));
    const double m = 0x1p-40 * std::max(std::max(max_abs(v), std::max(ax_a.half, ax_b.half)), std::max(a.r, b.r));
    if (std::fabs(dot(ax_b.u, v)) - ax_b.half - ax_a.half * c - a.r > m ||
        std::fabs(dot(ax_a.u, v)) - ax_a.half - ax_b.half * c - b.r > m)
      return {};
  }
  // Roles: B (the frame) is the first in the order above. (Bitwise: which
  // comes first is a coin toss on random pairs; the last key only at a tie.)
  const bool b_is_frame =
      (b.r > a.r) | ((b.r == a.r) & ((ax_b.half > ax_a.half) |
                                     ((ax_b.half == ax_a.half) && dot(b.p, b.p) + dot(b.q, b.q) >= dot(a.p, a.p) + dot(a.q, a.q))));
  const Cylinder& ca = b_is_frame ? a : b;
  const Cylinder& cb = b_is_frame ? b : a;
  const Frame f(ca.r, b_is_frame ? ax_a : ax_b, cb.r, b_is_frame ? ax_b : ax_a, opt);
  Contact out;
  if (!(f.lo <= f.hi)) return out;  // the axes' lines more than rA + rB apart
  // Early-outs: each term bounded below over all slices (k <= r); the cap
  // terms are the two false-positive planes. Their negatives are the
  // overlaps along -z, -x, -+u_A and -+n_A.
  double o[5];
  for (int j = 0; j < 4; ++j) {
    o[j] = -(f.t[j].c - f.t[j].al * f.rA - f.t[j].be * f.rB);
    if (o[j] < 0) return out;
  }
  o[4] = f.rA + f.rB - f.y0;  // along -y
  const double scene = std::max(std::max(std::max(f.X0, f.y0), std::max(f.Z0, f.hA)), std::max(std::max(f.hB, f.rA), f.rB));
  double ys = 0;
  if (!slices_meet(f, 0x1p-48 * scene, ys)) return out;
  out.hit = true;
  if (!want_contact) return out;
  // A pair symmetric under a reflection of the frame (a zero coordinate of
  // A's centre, with A's axis along or across that coordinate's axis) had
  // its canonical sign chosen by a toss-up, so that a reflected scene may
  // run the mirrored numbers: the point is then taken on the mirror plane,
  // the midpoint of a common point and its mirror image (in both shapes:
  // they are convex). In y that is the slice y = 0, the widest of both
  // (where any slice has a common point, it has).
  if (f.y0 == 0) ys = 0;
  double X, Z;
  f.common_point(ys, X, Z);
  if (f.sX * f.cZ == 0) {
    if (f.X0 == 0) X = 0;
    if (f.Z0 == 0) Z = 0;
  }
  out.point = f.origin + (X * f.x + ys * f.y + Z * f.z);
  // The normal: the best of the fixed directions -z, -x, -+u_A, -+n_A, -y,
  // the two great circles of side normals (side of A against B's rim or side,
  // side of B against A's), each minimised by Newton on the angle from the
  // direction between the axes (-y is on both circles), and rim against rim.
  int best = 0;
  double depth = o[0];
  for (int j = 1; j < 5; ++j) {
    best = o[j] < depth ? j : best;
    depth = o[j] < depth ? o[j] : depth;
  }
  Vec3 n, m;  // the normal, and in frame coordinates
  const double sa0 = f.a0 >= 0 ? 1.0 : -1.0;
  const double sn = f.nA_sign();
  switch (best) {
    case 0: n = -f.z, m = {0, 0, -1}; break;
    case 1: n = -f.x, m = {-1, 0, 0}; break;
    case 2: n = -sa0 * f.uA, m = {-sa0 * f.sX, 0, -sa0 * f.cZ}; break;
    case 3: n = -f.nA_signed(), m = {-sn * f.cZ, 0, sn * f.sX}; break;
    default: n = -f.y, m = {0, -1, 0}; break;
  }
  {
    const Frame::Circle ca = f.circle_a(), cb = f.circle_b();
    // Each circle from the direction between the axes in its plane (the
    // answer for parallel axes: from the radial part y0 and the linear
    // coefficient -K), unless a lower bound says it cannot beat the depth
    // found.
    // (Scaled by a power of two where y0^2 + w^2 leaves the normal range:
    // offsets of 1e-154 in a scene of 1 left (P, Q) 8e-11 short of unit,
    // and the normal with it; regression collide_cylinder_cylinder/0032.)
    auto start = [&](const Frame::Circle& c, double& P, double& Q) {
      double y = f.y0, w = std::max(-c.K, 0.0);
      const double l2 = y * y + w * w;
      if (!(l2 > kSafeLo * kSafeLo && l2 < kSafeHi * kSafeHi)) {
        const double mx = std::max(std::fabs(y), w);
        if (mx > 0 && std::isfinite(mx)) {
          const int e = std::ilogb(mx);
          y = std::ldexp(y, -e), w = std::ldexp(w, -e);
        }
      }
      const double l = std::sqrt(y * y + w * w);
      if (l > 0) P = y * (1 / l), Q = w * (1 / l);
      else P = 1, Q = 0;
    };
    double P, Q;
    if (ca.lower_bound() < depth) {
      start(ca, P, Q);
      const double da = ca.min(P, Q, o[3], opt.newton_steps, opt.relative_stop);
      if (da < depth) depth = da, n = -(P * f.y + Q * f.nA_signed()), m = {-Q * sn * f.cZ, -P, Q * sn * f.sX};
    }
    if (cb.lower_bound() < depth) {
      start(cb, P, Q);
      const double db = cb.min(P, Q, o[1], opt.newton_steps, opt.relative_stop);
      if (db < depth) depth = db, n = -(P * f.y + Q * f.x), m = {-Q, -P, 0};
    }
  }
  // Rim against rim: where the common point lies within the best overlap
  // so far of a cap plane of each cylinder, the direction perpendicular to
  // both rims' tangents there (two curves touching at a point have it as
  // their common normal), with the sign that overlaps less. In frame
  // coordinates B's rim tangent at (X, ys, Z) is z x (X, ys, 0) and A's is
  // u_A x d, d the point's offset across A's axis; the overlap along a unit
  // m is S(m) + m.C_A (A's centre C_A, B's at the origin), where S is even
  // in m, so the better sign gives S - |m.C_A|. After the circles, whose
  // depths make the test stricter.
  bool near_both_caps = false;
  if (opt.rim_rim) {
    const double ux = f.sX, uz = f.cZ;  // u_A = (sX, 0, cZ)
    const double wx = X - f.X0, wy = ys - f.y0, wz = Z - f.Z0;
    const double a = wx * ux + wz * uz;
    near_both_caps = std::fabs(Z) >= f.hB - depth && std::fabs(a) >= f.hA - depth;
    if (near_both_caps) {
      bool have_rr = false, rr_better = false;
      double o_rr_signed = kInf;
      Vec3 m_rr{0, 0, 0};
      const double dx = wx - a * ux, dy = wy, dz = wz - a * uz;
      const double tax = -uz * dy, tay = uz * dx - ux * dz, taz = ux * dy;  // u_A x d
      const double tbx = -ys, tby = X;                                       // z x (X, ys, 0)
      const double nx = -taz * tby, ny = taz * tbx, nz = tax * tby - tay * tbx;
      const double mn = max_abs(Vec3{nx, ny, nz});
      if (mn > 0 && std::isfinite(mn)) {
        // Unit even where the square underflows (a rim tangent of subnormal
        // size: the plain 1 / sqrt(l2) left it 2e-7 off unit; fuzzing).
        const Vec3 mu = normalized(Vec3{nx, ny, nz});
        const double mx = mu.x, my = mu.y, mz = mu.z;
        const double t = mx * ux + mz * uz;
        const double rx = mx - t * ux, ry = my, rz = mz - t * uz;
        const double s = f.hA * std::fabs(t) + f.rA * std::sqrt(rx * rx + ry * ry + rz * rz) + f.hB * std::fabs(mz) +
                         f.rB * std::sqrt(mx * mx + my * my);
        const double mc = mx * f.X0 + my * f.y0 + mz * f.Z0;
        const double o_rr = s - std::fabs(mc);
        const double sg = mc > 0 ? -1.0 : 1.0;
        have_rr = true, o_rr_signed = o_rr, m_rr = Vec3{sg * mx, sg * my, sg * mz};
        rr_better = o_rr < depth;
        if (o_rr < depth) {
          // The direction it replaces is searched too, below: it ends on a
          // kink, where the search can leave it for the patch, while a start
          // off every kink is taken as it is.
          if (opt.rim_steps > 0) {
            Vec3 m0 = m;
            const double o0 = refine_rims(f, m0, depth, opt.rim_steps);
            if (o0 < o_rr) {
              depth = o0, n = m0.x * f.x + m0.y * f.y + m0.z * f.z, m = m0;
              rr_better = false;
            }
          }
          if (rr_better) depth = o_rr, n = (sg * mx) * f.x + (sg * my) * f.y + (sg * mz) * f.z, m = m_rr;
        }
      }
      // The patch searched from the rim x rim direction too, where it did
      // not win (the best direction is searched below).
      if (opt.rim_steps > 0 && have_rr && !rr_better) {
        Vec3 start = m_rr;
        const double o_r = refine_rims(f, start, o_rr_signed, opt.rim_steps);
        if (o_r < depth) depth = o_r, n = start.x * f.x + start.y * f.y + start.z * f.z, m = start;
      }
    }
  }
  // The best direction refined on the sphere (a few dozen operations where
  // it is a minimum of its kink's patch, the common case).
  if (opt.rim_steps > 0) {
    const double o_r = refine_rims(f, m, depth, opt.rim_steps);
    if (o_r < depth) depth = o_r, n = m.x * f.x + m.y * f.y + m.z * f.z;
    // Cylinders meeting end to end (the common point near a cap plane of
    // each, axes within 1/16 rad of parallel) can hold the minimum beside an
    // axis direction while the search above ends on a side circle far from
    // it: there each axis direction is searched from too; at larger angles,
    // the axis along which the overlap is the smaller, where that is within
    // twice the depth so far (thin disks 22 degrees apart, cylinders 13 and
    // 12 degrees apart cap on cap: the circles' minima 1.56, 1.79 and 1.61
    // times the penetration depth; 10% to 20% more time per call in
    // bench_collide_cylinder_cylinder).
    if (near_both_caps) {
      const Vec3 axes[2] = {{0, 0, -1}, {-sa0 * f.sX, 0, -sa0 * f.cZ}};
      const double along[2] = {o[0], o[2]};
      const int nearer = along[1] < along[0];
      for (int k = 0; k < 2; ++k) {
        if (!(along[k] > depth)) continue;
        if (!(f.sX < 0x1p-4) && !(k == nearer && along[k] < 2 * depth)) continue;
        Vec3 mk = axes[k];
        const double ok = refine_rims(f, mk, along[k], opt.rim_steps);
        if (ok < depth) depth = ok, n = mk.x * f.x + mk.y * f.y + mk.z * f.z;
      }
    }
  }
  out.depth = std::max(depth, 0.0);
  // The normal points from A to B; A is the caller's a unless a is the frame.
  out.normal = sign_if(!b_is_frame) * n;
  return out;
}

// A cylinder's axis in the scaled scene: the direction from the caller's
// numbers whenever q - p and its length are finite (the scaled difference can underflow and
// lose it: a disk of radius DBL_MAX and subnormal thickness), else from the
// scaled ones; bit-identical to the scaled computation wherever neither
// overflows or underflows.
Axis axis_of(const Cylinder& c, const SceneScale& sc) {
  const Vec3 p = sc.in(c.p), q = sc.in(c.q), mid = 0.5 * (p + q);
  const Vec3 d = c.q - c.p;
  if (is_finite(d)) {
    const UnitAndLength ul(d);
    if (std::isfinite(ul.len)) return {ul.u, 0.5 * sc.in(ul.len), mid};
  }
  const UnitAndLength ul(q - p);
  return {ul.u, 0.5 * ul.len, mid};
}

}  // namespace

Contact cylinder_pair(const Cylinder& a, const Cylinder& b, bool want_contact, const CylinderPairOptions& opt) {
  if (!is_valid(a) || !is_valid(b)) return {};
  const SceneScale sc(std::max(largest(a), largest(b)));
  if (sc.e == 0) {
    // Not rescaled (every magnitude within [2^-100, 2^100]): the same
    // numbers as below, without the rescaling's copies and tests.
    auto axis = [](const Cylinder& c) {
      const UnitAndLength ul(c.q - c.p);
      return Axis{ul.u, 0.5 * ul.len, 0.5 * (c.p + c.q)};
    };
    return scaled(a, axis(a), b, axis(b), want_contact, opt);
  }
  Contact out = scaled(sc.in(a), axis_of(a, sc), sc.in(b), axis_of(b, sc), want_contact, opt);
  if (out.hit) {
    out.point = sc.out(out.point);
    out.depth = std::min(sc.out(out.depth), std::numeric_limits<double>::max());
  }
  return out;
}

}  // namespace detail

bool overlap(const Cylinder& a, const Cylinder& b) { return detail::cylinder_pair(a, b, false, {}).hit; }

Contact collide(const Cylinder& a, const Cylinder& b) { return detail::cylinder_pair(a, b, true, {}); }

}  // namespace geomcheck
