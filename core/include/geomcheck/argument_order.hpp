// geomcheck — the argument-order wrappers of the pair queries.
//
// The cylinder's pair queries are written with the cylinder first:
// overlap(Cylinder, B) and collide(Cylinder, B[, extra]). The templates
// below answer the other order for every B that has them, once for all of
// them (a pair without the cylinder declares its other order in its own
// header, e.g. collide_sphere_capsule.hpp; a pair of one shape has none):
//   overlap(B, Cylinder)   the same verdict;
//   collide(B, Cylinder)   the same contact with its normal flipped (from B
//                          towards the cylinder); depth and point unchanged;
//   penetration(B, Cylinder)  likewise.
// Cylinder/cylinder has no other order, so B = Cylinder is excluded.
#pragma once

#include <type_traits>

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// overlap(B, Cylinder): the verdict of overlap(Cylinder, B).
template <class B, std::enable_if_t<!std::is_same_v<B, Cylinder>, int> = 0>
auto overlap(const B& a, const Cylinder& b) -> decltype(overlap(b, a)) {
  return overlap(b, a);
}

/// collide(B, Cylinder, extra...): collide(Cylinder, B, extra...) with the
/// normal flipped (from B towards the cylinder).
template <class B, class... Extra, std::enable_if_t<!std::is_same_v<B, Cylinder>, int> = 0>
auto collide(const B& a, const Cylinder& b, Extra... extra) -> decltype(flipped(collide(b, a, extra...))) {
  return flipped(collide(b, a, extra...));
}

/// penetration(B, Cylinder): penetration(Cylinder, B) with the normal
/// flipped (from B towards the cylinder).
template <class B, std::enable_if_t<!std::is_same_v<B, Cylinder>, int> = 0>
auto penetration(const B& a, const Cylinder& b) -> decltype(flipped(penetration(b, a))) {
  return flipped(penetration(b, a));
}

}  // namespace geomcheck
