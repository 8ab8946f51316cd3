#include "geomcheck/predicates3d.hpp"

#include "exact_integers.hpp"

namespace geomcheck::detail {

using exact_integers::Int;
using exact_integers::Scaled;
using exact_integers::sign_of;

int orient3d_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double xs[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  const Scaled<12> s(xs);
  const Int adx = s[0] - s[9], ady = s[1] - s[10], adz = s[2] - s[11];
  const Int bdx = s[3] - s[9], bdy = s[4] - s[10], bdz = s[5] - s[11];
  const Int cdx = s[6] - s[9], cdy = s[7] - s[10], cdz = s[8] - s[11];
  return sign_of(Int(adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady)));
}

int insphere_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const double xs[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z};
  const Scaled<15> s(xs);
  const Int aex = s[0] - s[12], aey = s[1] - s[13], aez = s[2] - s[14];
  const Int bex = s[3] - s[12], bey = s[4] - s[13], bez = s[5] - s[14];
  const Int cex = s[6] - s[12], cey = s[7] - s[13], cez = s[8] - s[14];
  const Int dex = s[9] - s[12], dey = s[10] - s[13], dez = s[11] - s[14];
  const Int ab = aex * bey - bex * aey, bc = bex * cey - cex * bey, cd = cex * dey - dex * cey;
  const Int da = dex * aey - aex * dey, ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const Int abc = aez * bc - bez * ac + cez * ab;
  const Int bcd = bez * cd - cez * bd + dez * bc;
  const Int cda = cez * da + dez * ac + aez * cd;
  const Int dab = dez * ab + aez * bd + bez * da;
  const Int alift = aex * aex + aey * aey + aez * aez, blift = bex * bex + bey * bey + bez * bez;
  const Int clift = cex * cex + cey * cey + cez * cez, dlift = dex * dex + dey * dey + dez * dez;
  return sign_of(Int((dlift * abc - clift * dab) + (blift * cda - alift * bcd)));
}

}  // namespace geomcheck::detail
