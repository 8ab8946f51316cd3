// geomcheck — libccd re-entered: the guarded support function (see
// fcl_libccd.hpp).
#include "fcl_libccd.hpp"

#include <limits>

namespace geomcheck::peers::fcl_detail {

thread_local SupportGuard* t_support_guard = nullptr;

namespace {
bool finite3(const ccd_vec3_t* v) {
  return std::isfinite(v->v[0]) && std::isfinite(v->v[1]) && std::isfinite(v->v[2]);
}

}  // namespace

void guarded_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* v) {
  SupportGuard& g = *t_support_guard;
  if (g.left <= 0) {
    // Shape 1 is asked along dir, shape 2 along -dir: the Minkowski point is
    // then -2e300 dir, behind every portal and beyond every tolerance.
    g.spent = true;
    ccdVec3Copy(v, dir);
    ccdVec3Scale(v, -1e300);
    return;
  }
  --g.left;
  if (!finite3(dir)) {
    g.non_finite = true;
    ccdVec3Set(v, 0, 0, 0);
    return;
  }
  // A support function that leaves its output unset is seen as non-finite.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ccdVec3Set(v, nan, nan, nan);
  (obj == g.obj1 ? g.support1 : g.support2)(obj, dir, v);
  if (!finite3(v)) {
    g.non_finite = true;
    ccdVec3Set(v, 0, 0, 0);
  }
}

}  // namespace geomcheck::peers::fcl_detail
