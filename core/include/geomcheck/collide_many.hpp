// geomcheck — list queries: one cylinder against many spheres, capsules or
// boxes.
//
// Semantics: element i of the output is exactly what the scalar query gives
// for the pair (cyl, b[i]), bit for bit (overlap: the same bool; collide:
// the same Contact, every field), whatever the batch holds; a property
// (properties/tests/test_many.cpp) holds it. An invalid shape anywhere in a
// batch gives that element no contact (as the scalar query), never a crash,
// and leaves the other elements alone; an invalid cylinder gives none to
// all. `out` holds n elements and may not overlap the input.
//
// Algorithm: the engine talk's "list" (do the primitives meet?) and "full"
// (the contact) flavours over a span. overlap_many(Cylinder, Sphere*) is a
// batch kernel: the cylinder's axis d = q - p, d.d and r^2 d.d are formed
// once, then each sphere runs the scalar predicate's own arithmetic on them
// (the same operations in the same order: collide_cylinder_sphere.cpp; two
// spheres at a time in SSE2 where the target has it), so the verdicts are
// the scalar ones; a sphere or axis outside the range where the scalar
// query needs no rescaling, or an invalid sphere, is answered by the scalar
// query itself. overlap_many(Cylinder, Capsule*) decides a capsule that is
// clearly apart or clearly meeting in doubles, with a margin of 2^-32 of
// the pair's reach (far above the filter's rounding and the scalar query's
// band of touching), and asks the scalar query for every other one;
// collide_many(Cylinder, Capsule*) gives a capsule that filter finds clearly
// apart collide's answer for a miss (Contact{}) and calls the scalar collide
// for the rest. The other list queries call the scalar query per element
// after validating the cylinder once (their cost is the query's, not the
// call's).
//
// Bit-identity assumes one floating-point environment for both paths (the
// default rounding mode; no FMA contraction that differs between the inlined
// copies: the build does not enable FMA, -ffp-contract is the compiler's
// default for x86-64).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// out[i] = overlap(cyl, b[i]) for i < n (batch kernel; see above).
void overlap_many(const Cylinder& cyl, const Sphere* b, std::size_t n, bool* out);
/// out[i] = overlap(cyl, b[i]) for i < n.
void overlap_many(const Cylinder& cyl, const Capsule* b, std::size_t n, bool* out);
/// out[i] = overlap(cyl, b[i]) for i < n.
void overlap_many(const Cylinder& cyl, const Obb* b, std::size_t n, bool* out);

/// out[i] = collide(cyl, b[i]) for i < n.
void collide_many(const Cylinder& cyl, const Sphere* b, std::size_t n, Contact* out);
/// out[i] = collide(cyl, b[i]) for i < n.
void collide_many(const Cylinder& cyl, const Capsule* b, std::size_t n, Contact* out);
/// out[i] = collide(cyl, b[i]) for i < n.
void collide_many(const Cylinder& cyl, const Obb* b, std::size_t n, Contact* out);

namespace detail {
/// The list query as a loop over the scalar one, the cylinder validated
/// once: out[i] = query(cyl, b[i]), or R{} for all when cyl is invalid.
template <class B, class R, class Query>
void each_scalar(const Cylinder& cyl, const B* b, std::size_t n, R* out, Query query) {
  if (!is_valid(cyl)) {
    for (std::size_t i = 0; i < n; ++i) out[i] = R{};
    return;
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = query(cyl, b[i]);
}
}  // namespace detail

/// overlap(cyl, b[i]) for every element of b.
template <class B>
std::vector<bool> overlap_many(const Cylinder& cyl, const std::vector<B>& b) {
  const std::unique_ptr<bool[]> raw(new bool[b.size()]);
  overlap_many(cyl, b.data(), b.size(), raw.get());
  return std::vector<bool>(raw.get(), raw.get() + b.size());
}
/// collide(cyl, b[i]) for every element of b.
template <class B>
std::vector<Contact> collide_many(const Cylinder& cyl, const std::vector<B>& b) {
  std::vector<Contact> out(b.size());
  collide_many(cyl, b.data(), b.size(), out.data());
  return out;
}

}  // namespace geomcheck
