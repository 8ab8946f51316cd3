#include "capsule_truth.hpp"

#include <sstream>

namespace geomcheck {

using oracle::Q;
using oracle::QInterval;
using oracle::QVec;
using oracle::Verdict;

QInterval overlap_along(const oracle::ConvexShape& a, const oracle::ConvexShape& b, const QVec& n) {
  const QVec m{-n.x, -n.y, -n.z};
  const QInterval h = oracle::support_value(a, n) + oracle::support_value(b, m);
  return h / oracle::sqrt_interval(oracle::dot(n, n));
}

QInterval capsule_signed_distance(const QVec& p, const QVec& q, const Q& r, const QVec& x) {
  const QVec d = q - p;
  const Q dd = oracle::dot(d, d);
  Q t = dd > 0 ? oracle::dot(x - p, d) / dd : Q(0);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  const QVec off = x - (p + t * d);
  return oracle::sqrt_interval(oracle::dot(off, off)) - oracle::point(r);
}

CapsuleTruth capsule_truth(const oracle::ConvexShape& cyl, const QVec& p, const QVec& q, const Q& r) {
  CapsuleTruth t;
  std::ostringstream o;
  oracle::EngineOptions opt;
  opt.rel_width = 1e-20;
  opt.certificates = false;
  const oracle::ConvexShape seg = oracle::make_capsule(p, q, Q(0));
  const oracle::DistanceResult s = oracle::classify(cyl, seg, opt);
  bool decided = false;
  if (s.verdict == Verdict::Separated) {
    t.core_outside = true;
    t.core_distance = s.distance;
    t.signed_distance = s.distance - oracle::point(r);
    if (t.signed_distance.lo > 0) t.verdict = Verdict::Separated, decided = true;
    else if (t.signed_distance.hi < 0) t.verdict = Verdict::Overlapping, decided = true;
  } else if (s.verdict == Verdict::Overlapping || s.verdict == Verdict::Touching) {
    if (r > 0) {
      // pq meets the cylinder: every separating translation is at least r
      // long; the overlap along the axis bounds the depth from above.
      t.verdict = Verdict::Overlapping;
      const QInterval along = overlap_along(cyl, oracle::make_capsule(p, q, r), cyl.axis);
      t.signed_distance = {-along.hi, -r};
      decided = true;
    } else {
      t.verdict = s.verdict;
      t.signed_distance = s.distance;
      decided = true;
    }
  }
  if (!decided) {
    // The capsule within reach of touching (or the segment undecided): the
    // capsule itself, exactly (touching is certified there).
    const oracle::DistanceResult c = oracle::classify(cyl, oracle::make_capsule(p, q, r), opt);
    t.verdict = c.verdict;
    if (!t.core_outside) t.signed_distance = c.distance;
    else if (c.verdict == Verdict::Touching) t.signed_distance = oracle::point(Q(0));
  }
  o << oracle::to_string(t.verdict) << " signed_distance=" << oracle::to_string(t.signed_distance)
    << (t.core_outside ? " (segment outside)" : " (segment meets the cylinder)");
  t.text = o.str();
  return t;
}

}  // namespace geomcheck
