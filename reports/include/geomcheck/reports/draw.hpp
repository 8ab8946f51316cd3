// geomcheck — counterexamples drawn for the campaign report: the two shapes
// in three orthographic views (top: x-y, front: x-z, side: y-z), with
// production's contact or hit point and its normal, the exact oracle's
// witness, and optionally another engine's answer, as inline SVG.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geomcheck/predicates2d.hpp"
#include "geomcheck/registry.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/triangle_mesh.hpp"

namespace geomcheck::draw {

/// What production answered, drawn over the shapes: a point and a normal.
struct Answer {
  bool hit = false;
  Vec3 point, normal;
  std::string label;  ///< e.g. "production: hit, depth 0.25"
};

/// Production's answer to the case of query Q.
template <QueryId Q>
Answer production_answer(const typename QueryTraits<Q>::Case& c);
/// Any implementation's answer; `who` heads the label ("production", a variant's name).
Answer answer_of(const Contact& k, const std::string& who);
Answer answer_of(const CastHit& h, const std::string& who);

/// Something drawn over the shapes.
struct Mark {
  enum class Kind {
    PointNormal,  ///< a dot at p, an arrow along the unit q (40 px)
    Arrow,        ///< a dot at p, an arrow to q (to scale)
    Segment,      ///< p to q, dots at both ends
    Ball,         ///< a dot at p and the outline of the ball of radius r
  } kind = Kind::PointNormal;
  Vec3 p, q;
  double r = 0;
  std::string color, label;
};

/// The exact oracle's witness, certified by the engine (oracles/engine.hpp)
/// or the closed-form cast: separated, the nearest points; touching, a
/// common point; overlapping, a common point and the minimal translation
/// of B (depth along the penetration direction); a cast, the first touch
/// S(t); a sweep, the ball at its first touch. Empty for invalid input or
/// when the oracle cannot say. `hint`: a point worth trying as the certified
/// common point (the drawn answer's).
template <QueryId Q>
std::vector<Mark> oracle_witness(const typename QueryTraits<Q>::Case& c, const Vec3* hint = nullptr);

/// Three views of a case's shapes A (blue) and B (orange), production's
/// answer (red), the oracle's witness (green) and `extra` marks, fitted to
/// all of them; `title` heads the figure. Non-finite coordinates are left
/// out (a figure with nothing finite says so).
/// `answer`: the implementation's answer drawn in red (default: production's).
template <class Case>
std::string views(const Case& c, const std::string& title, const std::vector<Mark>& extra = {},
                  const Answer* answer = nullptr);

/// Three views of a mesh case: the cylinder (blue), the faces whose boxes
/// come within the cylinder's size of it (orange; the answer's face first,
/// at most 400, the whole mesh's count in the title), the answer `k` of
/// `who` on face `face` (red: its point and normal, and the face's edges),
/// and the certified engine's witness for that face (green).
std::string mesh_views(const Cylinder& cyl, const TriangleMesh& mesh, const Contact& k, std::uint32_t face,
                       const std::string& who, const std::string& title);

/// A point set and a subject's triangles (input-index triples) in the
/// plane, fitted to the finite points; `title` (HTML) heads the figure.
std::string point_set_view(const std::vector<Vec2>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                           const std::string& title);

}  // namespace geomcheck::draw
