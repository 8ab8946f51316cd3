// geomcheck — the point-set family's checks (pointset_checks.hpp).
#include <algorithm>
#include <chrono>
#include <numeric>
#include <utility>

#include "geomcheck/detail/delaunay_links.hpp"
#include "geomcheck/oracles/delaunay_2d.hpp"
#include "geomcheck/predicates2d.hpp"
#include "geomcheck/properties/pointset_checks.hpp"

namespace geomcheck {

namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

DelaunayTriangulation production_triangulate(const std::vector<Vec2>& p) { return delaunay_2d(p); }

const PointSetImpl kProduction{"production", production_triangulate, {}, true};

}  // namespace

const PointSetImpl& production_point_set() { return kProduction; }

const PointSetImpl* point_set_subject(std::string_view name) {
  return name.empty() || name == kProduction.name ? &kProduction : nullptr;
}

bool all_finite(const std::vector<Vec2>& points) {
  return std::all_of(points.begin(), points.end(), [](Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); });
}

DelaunayTriangulation triangulation_of(const std::vector<Vec2>& points, const IndexTriangles& triangles,
                                       std::string* error) {
  const std::size_t n = points.size();
  DelaunayTriangulation t;
  // Each index to the smallest input index of equal coordinates (-0.0 == 0.0).
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return points[a].x != points[b].x ? points[a].x < points[b].x : points[a].y < points[b].y;
  });
  t.vertex_of.assign(n, 0);
  std::vector<std::uint32_t> distinct;
  for (std::size_t k = 0; k < n; ++k) {
    const bool same = k > 0 && points[order[k]] == points[order[k - 1]];
    t.vertex_of[order[k]] = same ? t.vertex_of[order[k - 1]] : order[k];
    if (!same) distinct.push_back(order[k]);
  }
  t.vertex_count = distinct.size();
  if (error) error->clear();
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    std::array<std::uint32_t, 3> x = triangles[i];
    for (std::uint32_t& v : x) {
      if (v >= n) {
        if (error && error->empty())
          *error = "triangle " + std::to_string(i) + " names index " + std::to_string(v) + " of " + std::to_string(n) +
                   " points";
        v = 0;
        continue;
      }
      v = t.vertex_of[v];
    }
    t.triangles.push_back(x);
  }
  // Neighbours: the triangle holding each edge in the other direction.
  t.hull_edges = detail::link_neighbors(t);
  // The dimension: plane with triangles; else what the distinct points span.
  if (!t.triangles.empty()) t.dimension = DelaunayDimension::plane;
  else if (distinct.empty()) t.dimension = DelaunayDimension::empty;
  else if (distinct.size() == 1) t.dimension = DelaunayDimension::point;
  else {
    t.dimension = DelaunayDimension::line;
    for (std::size_t k = 2; k < distinct.size() && t.dimension == DelaunayDimension::line; ++k)
      if (orient2d(points[distinct[0]], points[distinct[1]], points[distinct[k]]) != 0)
        t.dimension = DelaunayDimension::plane;
  }
  if (t.dimension != DelaunayDimension::plane) t.hull_edges = 0;
  return t;
}

PointSetOutcome check_point_set(const std::vector<Vec2>& p, const PointSetImpl& subject, std::size_t cgal_up_to,
                                bool timed) {
  PointSetOutcome o;
  std::size_t first_bad = p.size();
  for (std::size_t i = 0; i < p.size() && first_bad == p.size(); ++i)
    if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y)) first_bad = i;
  const bool finite = first_bad == p.size();
  if (!finite && !subject.any_input) {
    o.asked = false;
    return o;
  }
  DelaunayTriangulation t;
  IndexTriangles answered;  // a user subject's triangles, as given
  std::string index_error;
  const auto t0 = Clock::now();
  auto t1 = t0;
  try {
    if (subject.triangles) {
      answered = subject.triangles(p);
      t1 = Clock::now();
    } else {
      t = subject.triangulate(p);
      t1 = Clock::now();
    }
  } catch (const DelaunayInputError& e) {
    o.answer = std::string("rejected: ") + e.what();
    if (finite) o.failure = Failure{"finite-input-rejected", e.what()};
    else if (e.index() != first_bad)
      o.failure = Failure{"rejection-index", "the rejection names index " + std::to_string(e.index()) +
                                                 ", the first non-finite point is " + std::to_string(first_bad)};
    return o;
  } catch (const std::exception& e) {
    o.answer = std::string("threw: ") + e.what();
    o.failure = Failure{"subject-threw", e.what()};
    return o;
  } catch (...) {
    o.answer = "threw a non-standard exception";
    o.failure = Failure{"subject-threw", o.answer};
    return o;
  }
  if (subject.triangles && !finite) {  // answered input it claims to reject: no structure to complete
    o.answer = std::to_string(answered.size()) + " triangles";
    o.failure = Failure{"non-finite-input-accepted", "point " + std::to_string(first_bad) + " is not finite"};
    return o;
  }
  if (subject.triangles) t = triangulation_of(p, answered, &index_error);
  o.answer = t.summary();
  o.triangles = subject.triangles ? answered : t.triangles;
  if (!finite) {
    o.failure = Failure{"non-finite-input-accepted", "point " + std::to_string(first_bad) + " is not finite"};
    return o;
  }
  if (timed && p.size() <= cgal_up_to) {
    const auto cgal = oracle::cgal_delaunay(p);
    o.subject_us = micros(t0, t1), o.cgal_us = micros(t1, Clock::now());
    o.cgal_differs = oracle::canonical_triangles(t) != cgal;
  }
  if (!index_error.empty()) o.failure = Failure{"valid", index_error};
  else if (std::string v = oracle::check_delaunay(p, t); !v.empty()) o.failure = Failure{"valid", v};
  else if (p.size() <= cgal_up_to) {
    if (std::string w = oracle::compare_with_cgal(p, t); !w.empty()) o.failure = Failure{"agrees-with-cgal", w};
  }
  return o;
}

}  // namespace geomcheck
