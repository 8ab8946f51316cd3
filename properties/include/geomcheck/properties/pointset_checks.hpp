// geomcheck — the checks of the point-set family (delaunay_2d), written once
// for every subject and every runner: the campaign, verify(), replay and the
// fuzz target call check_point_set (the property suite drives the oracles
// themselves, and their teeth).
//
// A subject is a PointSetImpl: a name and triangulate(points) ->
// DelaunayTriangulation. Production answers the whole structure
// (delaunay_2d.hpp); a user's triangulator answers triangles alone, which
// triangulation_of() completes the way delaunay_2d's semantics state them
// (indices mapped to the smallest input index of equal coordinates,
// neighbours across shared edges, the hull's edges, the dimension), so that
// both are held to the same exact checker.
//
// The properties of one point set, the first failing one reported:
//   subject-threw              the subject threw (anything but a rejection)
//   finite-input-rejected      it threw DelaunayInputError on finite input
//   non-finite-input-accepted  it answered input with a NaN or an infinity
//                              (only a subject that claims any input:
//                              `any_input`; the others are not asked such sets)
//   rejection-index            its DelaunayInputError names another index than
//                              the first non-finite point's (any_input)
//   valid                      the exact validity checker rejects the answer
//                              (oracle::check_delaunay: orientation, local
//                              Delaunay, hull, coverage, duplicates)
//   agrees-with-cgal           its triangles differ from CGAL's beyond the
//                              cocircular choices both may make
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

/// Triangles as triples of input indices, counter-clockwise.
using IndexTriangles = std::vector<std::array<std::uint32_t, 3>>;

/// A subject of a point-set query: triangulate(points) under a name.
struct PointSetImpl {
  const char* name;
  /// The whole structure (production's entry point); empty when the
  /// subject answers `triangles`.
  Callable<DelaunayTriangulation(const std::vector<Vec2>&)> triangulate;
  /// Triangles alone (a user's triangulator), completed by
  /// triangulation_of; an index beyond the input fails `valid`.
  Callable<IndexTriangles(const std::vector<Vec2>&)> triangles{};
  /// The subject claims any input: it rejects a NaN or infinite coordinate
  /// with DelaunayInputError naming the first such index. Without the
  /// claim, sets with a non-finite coordinate are not asked.
  bool any_input = true;
};

/// Production (delaunay_2d) as a subject.
const PointSetImpl& production_point_set();
/// The built-in subject of the point-set query called `name`: "production"
/// (or empty) gives production; nullptr for any other name.
const PointSetImpl* point_set_subject(std::string_view name);

/// The whole structure of a triangulation answered as triangles alone: each
/// index mapped to the smallest input index of equal coordinates,
/// neighbours across each edge used in both directions, the hull's edges
/// (edges without a neighbour), the count of distinct points and the
/// dimension (plane when there are triangles; else what the distinct points
/// span, exactly). An index beyond the input is an error ("" when none).
DelaunayTriangulation triangulation_of(const std::vector<Vec2>& points, const IndexTriangles& triangles,
                                       std::string* error);

/// Whether every coordinate is finite.
bool all_finite(const std::vector<Vec2>& points);

/// What checking one point set gave.
struct PointSetOutcome {
  CheckResult failure;       ///< the first failing property, if any
  bool asked = true;         ///< false: the subject does not claim this input (not asked)
  std::string answer;        ///< the subject's answer in words (DelaunayTriangulation::summary, or what it threw)
  IndexTriangles triangles;  ///< the subject's triangles as it answered them (for a drawing)
  bool cgal_differs = false; ///< triangles other than CGAL's where cocircular points allow both
  double subject_us = NAN, cgal_us = NAN;  ///< the two triangulations' times (NaN: not timed)
};

/// Holds `subject`'s answer on `points` to every property above. CGAL is
/// asked for sets of at most `cgal_up_to` points (agrees-with-cgal); larger
/// sets are held to the exact checker alone. `timed`: CGAL's triangulation
/// also timed on its own beside the subject's (and cgal_differs set).
PointSetOutcome check_point_set(const std::vector<Vec2>& points, const PointSetImpl& subject,
                                std::size_t cgal_up_to = static_cast<std::size_t>(-1), bool timed = true);

}  // namespace geomcheck
