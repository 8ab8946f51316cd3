// geomcheck — counterexamples drawn for the campaign report: the two shapes
// in three orthographic views (top: x-y, front: x-z, side: y-z), with
// production's contact or hit point and its normal, as inline SVG.
#pragma once

#include <string>

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::draw {

/// What production answered, drawn over the shapes: a point and a normal.
struct Answer {
  bool hit = false;
  Vec3 point, normal;
  std::string label;  ///< e.g. "production: hit, depth 0.25"
};

Answer production_answer(const Cylinder& a, const Sphere& b);
Answer production_answer(const Segment& a, const Cylinder& b);
Answer production_answer(const Cylinder& a, const Capsule& b);
Answer production_answer(const MovingSphere& a, const Cylinder& b);
Answer production_answer(const Cylinder& a, const Obb& b);
Answer production_answer(const Cylinder& a, const Triangle& b);

/// Three views of shapes A (blue) and B (orange) and the answer (red),
/// fitted to the shapes; `title` heads the figure. Non-finite coordinates
/// are left out (a figure with nothing finite says so).
template <class A, class B>
std::string views(const A& a, const B& b, const std::string& title);

}  // namespace geomcheck::draw
