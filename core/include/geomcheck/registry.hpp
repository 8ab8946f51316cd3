// geomcheck — the single registry of query ids.
//
// One line per query in GEOMCHECK_QUERY_LIST, and its header included below.
// Everything generic (case files, replay, campaigns, reports, fuzz targets,
// corpus folders, the build's target lists) derives from this list; adding a
// query is the checklist of docs/ARCHITECTURE.md.
//
//   X(id, entry, ShapeA, ShapeB, summary)
//
// `entry` is production's entry point, which generic code calls (and from
// which the query's kind follows): Collide (overlap(A, B) and collide(A,
// B)), Penetration (overlap(A, B) and penetration(A, B): the exact
// penetration depth), Cast (cast(Segment, B)) or Sweep (sweep(MovingSphere,
// B)). The id is also the file stem of the query, the name of its test, its fuzz
// binary, its corpus folder and its report row.
#pragma once

#include <cstddef>
#include <cstring>
#include <optional>
#include <string_view>

#include "geomcheck/shapes.hpp"

#define GEOMCHECK_QUERY_LIST(X)                                                          \
  X(collide_cylinder_sphere, Collide, Cylinder, Sphere,                                  \
    "overlap/collide(Cylinder, Sphere): true penetration depth, minimal translation")   \
  X(cast_segment_cylinder, Cast, Segment, Cylinder,                                      \
    "cast(Segment, Cylinder): first hit from the segment start")                         \
  X(collide_cylinder_capsule, Collide, Cylinder, Capsule,                                \
    "overlap/collide(Cylinder, Capsule): exact verdict; true depth while the capsule's segment stays outside") \
  X(sweep_sphere_cylinder, Sweep, MovingSphere, Cylinder,                                \
    "sweep(Sphere, delta, Cylinder): first time of contact of a moving sphere")          \
  X(collide_cylinder_obb, Collide, Cylinder, Obb,                                        \
    "overlap/collide(Cylinder, Obb): exact verdict; consistent contact (depth = overlap along the normal, within 1 + 1/64 of the penetration depth)") \
  X(collide_cylinder_triangle, Collide, Cylinder, Triangle,                              \
    "overlap/collide(Cylinder, Triangle): exact verdict; consistent contact (depth = overlap along the normal, within 1 + 1/64 of the penetration depth)") \
  X(collide_cylinder_cylinder, Collide, Cylinder, Cylinder,                              \
    "overlap/collide(Cylinder, Cylinder): exact verdict; consistent contact (depth = overlap along the normal, an upper bound)") \
  X(penetration_cylinder_obb, Penetration, Cylinder, Obb,                                    \
    "overlap/penetration(Cylinder, Obb): exact verdict; the penetration depth over the Minkowski patches") \
  X(penetration_cylinder_triangle, Penetration, Cylinder, Triangle,                          \
    "overlap/penetration(Cylinder, Triangle): exact verdict; the penetration depth over the Minkowski patches") \
  X(collide_sphere_sphere, Collide, Sphere, Sphere,                                      \
    "overlap/collide(Sphere, Sphere): true penetration depth, minimal translation")     \
  X(collide_sphere_capsule, Collide, Sphere, Capsule,                                    \
    "overlap/collide(Sphere, Capsule): true penetration depth, minimal translation")    \
  X(collide_capsule_capsule, Collide, Capsule, Capsule,                                  \
    "overlap/collide(Capsule, Capsule): true penetration depth (parallel and crossing segments included)")

// Queries over a set of points, a family of their own: their case files hold
// points (corpora/include/geomcheck/pointset_file.hpp), not two shapes.
//
//   X(id, summary)
#define GEOMCHECK_POINTSET_QUERY_LIST(X)                                                         \
  X(delaunay_2d,                                                                                 \
    "delaunay_2d(points): Delaunay triangulation, exact predicates; duplicates merged, degenerate input says so")

// Queries of a cylinder against a triangle mesh, a family of their own: their
// case files hold a cylinder and any number of vertices and faces
// (corpora/include/geomcheck/mesh_file.hpp), not two fixed-size shapes.
//
//   X(id, summary)
#define GEOMCHECK_MESH_QUERY_LIST(X)                                                             \
  X(collide_cylinder_mesh,                                                                       \
    "overlap/collide(Cylinder, TriangleMesh): exact verdict; the deepest face's contact, bit for bit the brute force's")

// Production's entry points of every registered query, so that generic code
// can call them by the shapes' types (production_of<Q>, checks.hpp).
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/collide_capsule_capsule.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/collide_sphere_capsule.hpp"
#include "geomcheck/collide_sphere_sphere.hpp"
#include "geomcheck/penetration_cylinder_obb.hpp"
#include "geomcheck/penetration_cylinder_triangle.hpp"
#include "geomcheck/sweep_sphere_cylinder.hpp"

namespace geomcheck {

/// What a query answers.
enum class QueryKind {
  Collide,  ///< overlap(A, B) -> bool and collide(A, B) -> Contact
  Cast,     ///< cast(Segment, B) -> CastHit
  Sweep,    ///< sweep(Sphere, delta, B) -> CastHit
};

/// Production's entry point of a query: the registry's `entry` column.
enum class EntryPoint {
  Collide,      ///< overlap(A, B) and collide(A, B)
  Penetration,  ///< overlap(A, B) and penetration(A, B): the exact penetration depth
  Cast,         ///< cast(Segment, B)
  Sweep,        ///< sweep(MovingSphere, B)
};

/// The kind of a query answered by entry point `e`.
constexpr QueryKind kind_of(EntryPoint e) {
  return e == EntryPoint::Cast ? QueryKind::Cast : e == EntryPoint::Sweep ? QueryKind::Sweep : QueryKind::Collide;
}

/// Every registered query.
enum class QueryId {
#define GEOMCHECK_X(id, kind, A, B, summary) id,
  GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
};

/// Static facts about one query.
struct QueryInfo {
  QueryId id;
  const char* name;
  QueryKind kind;
  EntryPoint entry;
  const char* shape_a;
  const char* shape_b;
  const char* summary;
};

inline constexpr QueryInfo kQueries[] = {
#define GEOMCHECK_X(id, entry, A, B, summary) {QueryId::id, #id, kind_of(EntryPoint::entry), EntryPoint::entry, #A, #B, summary},
    GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
};
inline constexpr std::size_t kNumQueries = sizeof(kQueries) / sizeof(kQueries[0]);

/// The info row of a query id.
constexpr const QueryInfo& info(QueryId id) { return kQueries[static_cast<std::size_t>(id)]; }

/// Whether Collide query `id` is answered by production's
/// penetration(a, b) (the exact penetration depth and its direction) rather
/// than collide(a, b): its registry line's entry point.
constexpr bool answers_penetration(QueryId id) { return info(id).entry == EntryPoint::Penetration; }

/// A query of a family other than the pairs: its id, name and summary.
template <class Id>
struct FamilyQueryInfo {
  Id id;
  const char* name;
  const char* summary;
};

// The families' ids, from their lists: X(id, summary) -> id, and the info
// rows in the same order.
#define GEOMCHECK_FAMILY_ID(id, summary) id,
#define GEOMCHECK_POINTSET_ROW(id, summary) {PointSetQueryId::id, #id, summary},
#define GEOMCHECK_MESH_ROW(id, summary) {MeshQueryId::id, #id, summary},

/// Every registered point-set query.
enum class PointSetQueryId { GEOMCHECK_POINTSET_QUERY_LIST(GEOMCHECK_FAMILY_ID) };
/// Every registered mesh query.
enum class MeshQueryId { GEOMCHECK_MESH_QUERY_LIST(GEOMCHECK_FAMILY_ID) };
/// A point-set query's id and summary.
using PointSetQueryInfo = FamilyQueryInfo<PointSetQueryId>;
/// A mesh query's id and summary.
using MeshQueryInfo = FamilyQueryInfo<MeshQueryId>;
inline constexpr PointSetQueryInfo kPointSetQueries[] = {GEOMCHECK_POINTSET_QUERY_LIST(GEOMCHECK_POINTSET_ROW)};
inline constexpr MeshQueryInfo kMeshQueries[] = {GEOMCHECK_MESH_QUERY_LIST(GEOMCHECK_MESH_ROW)};
#undef GEOMCHECK_FAMILY_ID
#undef GEOMCHECK_POINTSET_ROW
#undef GEOMCHECK_MESH_ROW

/// The info row of a point-set query.
constexpr const PointSetQueryInfo& info(PointSetQueryId id) { return kPointSetQueries[static_cast<std::size_t>(id)]; }
/// The info row of a mesh query.
constexpr const MeshQueryInfo& info(MeshQueryId id) { return kMeshQueries[static_cast<std::size_t>(id)]; }

/// The three families of queries.
enum class QueryFamily {
  Pair,      ///< two shapes (QueryId, PairCase): collide, cast, sweep
  PointSet,  ///< a set of points (GEOMCHECK_POINTSET_QUERY_LIST)
  Mesh,      ///< a cylinder and a triangle mesh (GEOMCHECK_MESH_QUERY_LIST)
};

/// The family's word in listings and reports: "pair", "point-set", "mesh".
constexpr const char* family_name(QueryFamily f) {
  return f == QueryFamily::Pair ? "pair" : f == QueryFamily::PointSet ? "point-set" : "mesh";
}

/// Every registered query of any family, by name.
struct QueryEntry {
  const char* name;
  QueryFamily family;
  const char* summary;
};
inline constexpr QueryEntry kAllQueries[] = {
#define GEOMCHECK_X(id, kind, A, B, summary) {#id, QueryFamily::Pair, summary},
    GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
#define GEOMCHECK_X(id, summary) {#id, QueryFamily::PointSet, summary},
    GEOMCHECK_POINTSET_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
#define GEOMCHECK_X(id, summary) {#id, QueryFamily::Mesh, summary},
    GEOMCHECK_MESH_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
};

/// The family of the query named `name`; nullopt when no query has that name.
inline std::optional<QueryFamily> family_of(std::string_view name) {
  for (const auto& q : kAllQueries)
    if (name == q.name) return q.family;
  return std::nullopt;
}

/// Looks a query up by its id string.
inline std::optional<QueryId> query_from_name(std::string_view name) {
  for (const auto& q : kQueries)
    if (name == q.name) return q.id;
  return std::nullopt;
}

/// A case of query Q: its two shapes in the query's argument order. The
/// query is part of the type, so that two queries over the same shapes
/// (collide_cylinder_obb, penetration_cylinder_obb) have cases of their own.
template <class A, class B, QueryId Q>
struct PairCase {
  using ShapeA = A;
  using ShapeB = B;
  A a;
  B b;
};

/// Maps a query id to its shape types and case type.
template <QueryId Q> struct QueryTraits;
#define GEOMCHECK_X(id_, entry_, A, B, summary)                     \
  template <> struct QueryTraits<QueryId::id_> {                   \
    using ShapeA = A;                                              \
    using ShapeB = B;                                              \
    using Case = PairCase<A, B, QueryId::id_>;                     \
    static constexpr QueryId id = QueryId::id_;                    \
    static constexpr QueryKind kind = kind_of(EntryPoint::entry_); \
    static constexpr EntryPoint entry = EntryPoint::entry_;        \
    static constexpr const char* name = #id_;                 \
  };
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

/// The query whose case type is Case.
template <class Case> struct QueryOfCase;
template <class A, class B, QueryId Q>
struct QueryOfCase<PairCase<A, B, Q>> { static constexpr QueryId value = Q; };
/// The query whose case type is Case.
template <class Case>
inline constexpr QueryId query_of_case = QueryOfCase<Case>::value;

/// Calls f(std::integral_constant<QueryId, id>{}) for every registered query.
template <class F>
void for_each_query(F&& f) {
#define GEOMCHECK_X(id, kind, A, B, summary) f(std::integral_constant<QueryId, QueryId::id>{});
  GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
}

/// Calls f(std::integral_constant<QueryId, id>{}) for the one query `id`.
template <class F>
decltype(auto) visit_query(QueryId id, F&& f) {
  switch (id) {
#define GEOMCHECK_X(id_, kind, A, B, summary) \
  case QueryId::id_: return f(std::integral_constant<QueryId, QueryId::id_>{});
    GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
  }
  return f(std::integral_constant<QueryId, QueryId::collide_cylinder_sphere>{});
}

}  // namespace geomcheck
