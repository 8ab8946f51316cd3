#include "geomcheck/oracles/ball_pairs.hpp"

namespace geomcheck::oracle {

namespace {
Q norm2(const QVec& v) { return dot(v, v); }
}  // namespace

Q point_segment_distance2(const QVec& x, const QVec& p, const QVec& q) {
  const QVec d = q - p, w = x - p;
  const Q dd = norm2(d);
  const Q wd = dot(w, d);
  if (dd == 0 || wd <= 0) return norm2(w);
  if (wd >= dd) return norm2(x - q);
  // |w|^2 - (w.d)^2 / d.d: the residual of the projection, exactly.
  return norm2(w) - wd * wd / dd;
}

Q segment_distance2(const QVec& p1, const QVec& q1, const QVec& p2, const QVec& q2) {
  const QVec u = q1 - p1, v = q2 - p2, w = p2 - p1;
  const QVec m = cross(u, v);
  const Q mm = norm2(m);
  if (mm != 0) {
    // w = s u - t v + N, N along m.
    const Q s = dot(cross(w, v), m) / mm, t = dot(cross(w, u), m) / mm;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      const Q wm = dot(w, m);
      return wm * wm / mm;
    }
  }
  Q best = point_segment_distance2(p1, p2, q2);
  for (const Q& d : {point_segment_distance2(q1, p2, q2), point_segment_distance2(p2, p1, q1),
                     point_segment_distance2(q2, p1, q1)})
    if (d < best) best = d;
  return best;
}

QBallSegment to_ball_segment(const Sphere& s) { return {to_q(s.c), to_q(s.c), to_q(s.r)}; }
QBallSegment to_ball_segment(const Capsule& c) { return {to_q(c.p), to_q(c.q), to_q(c.r)}; }

BallPairTruth solve_ball_pair(const QBallSegment& a, const QBallSegment& b) {
  BallPairTruth t;
  t.dist2 = segment_distance2(a.p, a.q, b.p, b.q);
  const Q R = a.r + b.r;
  const Q R2 = R * R;
  t.verdict = t.dist2 < R2 ? Verdict::Overlapping : (t.dist2 == R2 ? Verdict::Touching : Verdict::Separated);
  t.dist = sqrt_interval(t.dist2);
  t.signed_distance = t.dist - point(R);
  if (t.verdict == Verdict::Touching) t.signed_distance = point(Q(0));
  t.text = std::string(to_string(t.verdict)) + " signed_distance=" + to_string(t.signed_distance) +
           " segment_distance=" + to_string(t.dist);
  return t;
}

QInterval overlap_along(const QBallSegment& a, const QBallSegment& b, const QVec& n) {
  const Q pa = dot(a.p, n), qa = dot(a.q, n), pb = dot(b.p, n), qb = dot(b.q, n);
  const Q ha = pa > qa ? pa : qa;   // max over A of x . n, less A's radius
  const Q lb = pb < qb ? pb : qb;   // min over B of x . n, less B's radius
  const QInterval len = sqrt_interval(norm2(n));
  return (point(ha - lb) / len) + point(a.r + b.r);
}

QInterval signed_distance(const QBallSegment& s, const QVec& x) {
  return sqrt_interval(point_segment_distance2(x, s.p, s.q)) - point(s.r);
}

}  // namespace geomcheck::oracle
