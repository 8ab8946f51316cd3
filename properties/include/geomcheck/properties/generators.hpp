// geomcheck — RapidCheck generators that reach the hard places.
//
// Every generator draws from rc::gen::inRange (size-independent, shrinks
// towards the first choice), so shrunk counterexamples go to the simplest
// mode, scale and offset.
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <string>
#include <vector>

#include "geomcheck/predicates2d.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/mesh_checks.hpp"

namespace geomcheck::gen {

/// Uniform double in [lo, hi).
rc::Gen<double> real(double lo, double hi);
/// A value nudged by k ulps, k in [-kmax, kmax].
double nudge(double v, int k);

/// A generated case and the generator mode that made it.
template <class Case>
using Tagged = std::pair<Case, std::string>;

/// Query Q's targeted cases, tagged by mode: each mode reaches a hard place
/// of the query (properties/src/generators/<id>.cpp lists them at its head).
template <QueryId Q>
rc::Gen<Tagged<typename QueryTraits<Q>::Case>> targeted();
/// Query Q's wild cases: every number drawn by wild_double.
template <QueryId Q>
rc::Gen<typename QueryTraits<Q>::Case> wild();
#define GEOMCHECK_X(id, kind, A, B, summary)                                  \
  template <> rc::Gen<Tagged<PairCase<A, B, QueryId::id>>> targeted<QueryId::id>(); \
  template <> rc::Gen<PairCase<A, B, QueryId::id>> wild<QueryId::id>();
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

/// The random source of the seed's sequence of Q's cases: one sequence per
/// query, so that the same seed draws the same cases of Q in verify(), in a
/// campaign of every query and in the benchmarks.
template <QueryId Q>
rc::Random sequence(std::uint64_t seed) {
  return rc::Random(seed ^ (0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(Q) + 1)));
}
/// The seed's first n targeted cases of Q (size 50), each tagged by its mode.
template <QueryId Q>
std::vector<Tagged<typename QueryTraits<Q>::Case>> draw(std::uint64_t seed, int n) {
  const auto gen = targeted<Q>();
  rc::Random random = sequence<Q>(seed);
  std::vector<Tagged<typename QueryTraits<Q>::Case>> cases;
  cases.reserve(n > 0 ? n : 0);
  for (int i = 0; i < n; ++i) cases.push_back(gen(random.split(), 50).value());
  return cases;
}

/// Query `From`'s targeted cases as cases of query `To` over the same two
/// shapes (the same modes and shrinking): for a second query of a pair.
template <QueryId To, QueryId From>
rc::Gen<Tagged<typename QueryTraits<To>::Case>> targeted_as() {
  return rc::gen::map(targeted<From>(), [](const Tagged<typename QueryTraits<From>::Case>& t) {
    return Tagged<typename QueryTraits<To>::Case>{{t.first.a, t.first.b}, t.second};
  });
}
/// Query `From`'s wild cases as cases of query `To` over the same shapes.
template <QueryId To, QueryId From>
rc::Gen<typename QueryTraits<To>::Case> wild_as() {
  return rc::gen::map(wild<From>(), [](const typename QueryTraits<From>::Case& c) {
    return typename QueryTraits<To>::Case{c.a, c.b};
  });
}
/// Defines query `to`'s targeted and wild generators as query `from`'s
/// (targeted_as, wild_as); used inside namespace geomcheck::gen.
#define GEOMCHECK_GENERATORS_AS(to, from)                                                       \
  template <>                                                                                   \
  rc::Gen<Tagged<QueryTraits<QueryId::to>::Case>> targeted<QueryId::to>() {                     \
    return targeted_as<QueryId::to, QueryId::from>();                                           \
  }                                                                                             \
  template <>                                                                                   \
  rc::Gen<QueryTraits<QueryId::to>::Case> wild<QueryId::to>() {                                 \
    return wild_as<QueryId::to, QueryId::from>();                                               \
  }

// --- point sets (delaunay_2d) -----------------------------------------------
/// Uniform points in [-scale, scale)^2 (any count, 53 random bits each).
rc::Gen<std::vector<Vec2>> uniform_points(double scale);
/// A random subset of an integer grid (up to 11 x 11), in random order, scaled by 2^e, |e| <= 30.
rc::Gen<std::vector<Vec2>> grid_points();
/// Exactly collinear points; `almost`: one of them moved off the line by a few ulps.
rc::Gen<std::vector<Vec2>> collinear_points(bool almost);
/// A generator of point sets and the name of its mode.
struct PointSetMode {
  const char* name;
  rc::Gen<std::vector<Vec2>> gen;
};
/// Every mode of point set (properties/src/generators/delaunay_2d.cpp).
std::vector<PointSetMode> point_set_modes();
/// A point set of any mode, tagged by its mode.
rc::Gen<Tagged<std::vector<Vec2>>> point_sets();
/// The first n point sets of a run with this seed (point_sets(), each
/// tagged by its mode): what the campaign and verify() of a point-set
/// subject draw, so that one seed gives both the same sets.
std::vector<Tagged<std::vector<Vec2>>> draw_point_sets(std::uint64_t seed, int n);

// --- meshes (collide_cylinder_mesh) ------------------------------------------
/// A cylinder and a mesh built around a cylinder/triangle case of
/// gen::targeted (properties/src/generators/collide_cylinder_mesh.cpp);
/// `grid`: a third of them also get a heightfield of up to 1152 faces.
rc::Gen<MeshCase> meshes(bool grid = true);
/// The first n meshes of a run with this seed (meshes(true), each tagged
/// by its mode): what the campaign and verify() of a mesh subject draw, so
/// that one seed gives both the same meshes.
std::vector<Tagged<MeshCase>> draw_meshes(std::uint64_t seed, int n);

/// A raw double: NaN, inf, subnormal, zero of either sign, huge, tiny, max, or plain.
rc::Gen<double> wild_double();

}  // namespace geomcheck::gen
