// geomcheck — the exact signs of the 3D predicates' determinants in
// rationals (oracle::Q), independent of the predicates' own big-integer
// stage: the reference of test_filters and test_predicates3d.
#pragma once

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/vec3.hpp"

namespace geomcheck::test {

inline int sign_of_q(const oracle::Q& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

/// Sign of det [a - d; b - d; c - d].
inline int orient3d_q(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const oracle::QVec qd = oracle::to_q(d);
  return sign_of_q(oracle::dot(oracle::to_q(a) - qd, oracle::cross(oracle::to_q(b) - qd, oracle::to_q(c) - qd)));
}

/// Sign of the 4x4 determinant of rows (p - e, |p - e|^2), p = a, b, c, d,
/// expanded along the lifts, with the sign of Shewchuk's insphere (positive
/// inside for a positively oriented a, b, c, d).
inline int insphere_q(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const oracle::QVec qe = oracle::to_q(e);
  const Vec3 p[4] = {a, b, c, d};
  oracle::QVec r[4];
  oracle::Q lift[4];
  for (int i = 0; i < 4; ++i) r[i] = oracle::to_q(p[i]) - qe, lift[i] = oracle::dot(r[i], r[i]);
  auto det3 = [](const oracle::QVec& u, const oracle::QVec& v, const oracle::QVec& w) {
    return oracle::dot(u, oracle::cross(v, w));
  };
  return sign_of_q(-lift[0] * det3(r[1], r[2], r[3]) + lift[1] * det3(r[0], r[2], r[3]) -
                   lift[2] * det3(r[0], r[1], r[3]) + lift[3] * det3(r[0], r[1], r[2]));
}

}  // namespace geomcheck::test
