// geomcheck — ODE as a peer subject (include/geomcheck/peers/ode.hpp says
// what ODE is asked, the conversions and the conventions).
#include "geomcheck/peers/ode.hpp"

#include <ode/ode.h>
#include <ode/version.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace geomcheck::peers {

static_assert(std::is_same_v<dReal, double>, "the ODE peer expects ODE built in double precision (dDOUBLE)");

namespace {

// --- the library ------------------------------------------------------------

/// ODE's error and debug handlers: ODE's message as an exception (ODE says
/// these handlers must not return; after an assertion it would abort).
[[noreturn]] void throw_ode_error(int num, const char* msg, va_list ap) {
  char text[512];
  std::vsnprintf(text, sizeof text, msg, ap);
  throw std::runtime_error("ODE error " + std::to_string(num) + ": " + text);
}

/// ODE's informational messages: dropped.
void drop_ode_message(int, const char*, va_list) {}

/// ODE initialised once for the process, its data allocated once per thread.
void ensure_ode() {
  static const bool initialised = [] {
    dInitODE2(0);
    dSetErrorHandler(&throw_ode_error);
    dSetDebugHandler(&throw_ode_error);
    dSetMessageHandler(&drop_ode_message);
    return true;
  }();
  thread_local const bool allocated = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
  (void)initialised;
  if (!allocated) throw std::runtime_error("ODE: dAllocateODEDataForThread failed");
}

/// A geom, destroyed with its owner (also when an ODE error unwinds).
class Geom {
 public:
  /// Owns `id`.
  explicit Geom(dGeomID id) : id_(id) {}
  /// Takes over `other`'s geom.
  Geom(Geom&& other) noexcept : id_(other.id_) { other.id_ = nullptr; }
  Geom(const Geom&) = delete;
  Geom& operator=(const Geom&) = delete;
  Geom& operator=(Geom&&) = delete;
  /// Destroys the geom (none after a move).
  ~Geom() {
    if (id_) dGeomDestroy(id_);
  }
  /// The geom.
  dGeomID get() const { return id_; }

 private:
  dGeomID id_;
};

/// A trimesh's data (vertices and indices owned here, as ODE only points to
/// them) and its geom, destroyed geom first.
class TriangleGeom {
 public:
  /// The triangle as a two-faced trimesh at the identity pose.
  explicit TriangleGeom(const Triangle& t)
      : vertices_{t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z},
        indices_{0, 1, 2, 0, 2, 1},  // both windings: ODE's trimesh is one-sided
        data_(dGeomTriMeshDataCreate()) {
    dGeomTriMeshDataBuildDouble(data_, vertices_.data(), 3 * sizeof(double), 3, indices_.data(),
                                static_cast<int>(indices_.size()), 3 * sizeof(dTriIndex));
    geom_ = dCreateTriMesh(nullptr, data_, nullptr, nullptr, nullptr);
  }
  TriangleGeom(const TriangleGeom&) = delete;
  TriangleGeom& operator=(const TriangleGeom&) = delete;
  /// Destroys the geom, then its data.
  ~TriangleGeom() {
    if (geom_) dGeomDestroy(geom_);
    dGeomTriMeshDataDestroy(data_);
  }
  /// The trimesh geom.
  dGeomID get() const { return geom_; }

 private:
  std::array<double, 9> vertices_;
  std::array<dTriIndex, 6> indices_;
  dTriMeshDataID data_;
  dGeomID geom_ = nullptr;
};

// --- conversion ---------------------------------------------------------------

/// A direction's length and unit vector, computed after dividing by its
/// largest component (no overflow or underflow of the squares); length
/// infinite when it exceeds the largest double, zero for the zero vector.
struct Direction {
  double length = 0;
  Vec3 unit;
};
/// d's length and direction (see Direction).
Direction direction_of(Vec3 d) {
  const double m = max_abs(d);
  if (!(m > 0)) return {};
  const Vec3 s{d.x / m, d.y / m, d.z / m};
  const double ls = geomcheck::length(s);
  return {m * ls, (1.0 / ls) * s};
}

/// ODE's 3x4 row-major rotation with columns c0, c1, c2.
void set_rotation(dGeomID g, Vec3 c0, Vec3 c1, Vec3 c2) {
  dMatrix3 r = {c0.x, c1.x, c2.x, 0, c0.y, c1.y, c2.y, 0, c0.z, c1.z, c2.z, 0};
  dGeomSetRotation(g, r);
}

/// Places g at the mid point of pq with its local z along the unit axis u.
void place_on_axis(dGeomID g, Vec3 p, Vec3 q, Vec3 u) {
  const Vec3 mid = 0.5 * p + 0.5 * q;
  dGeomSetPosition(g, mid.x, mid.y, mid.z);
  const Vec3 e1 = any_perpendicular(u);
  set_rotation(g, e1, cross(u, e1), u);
}

/// std::isfinite, short.
bool finite(double v) { return std::isfinite(v); }

/// The cylinder as ODE's geom (a centred z-axis cylinder, rotated).
Geom make_geom(const Cylinder& c) {
  const Direction d = direction_of(c.q - c.p);
  Geom g(dCreateCylinder(nullptr, c.r, d.length));
  place_on_axis(g.get(), c.p, c.q, d.unit);
  return g;
}

/// The sphere as ODE's geom.
Geom make_geom(const Sphere& s) {
  Geom g(dCreateSphere(nullptr, s.r));
  dGeomSetPosition(g.get(), s.c.x, s.c.y, s.c.z);
  return g;
}

/// The capsule as ODE's geom (a centred z-axis capsule, rotated; a ball
/// when p == q).
Geom make_geom(const Capsule& c) {
  if (c.p == c.q) {
    Geom g(dCreateCapsule(nullptr, c.r, 0));
    dGeomSetPosition(g.get(), c.p.x, c.p.y, c.p.z);
    return g;
  }
  const Direction d = direction_of(c.q - c.p);
  Geom g(dCreateCapsule(nullptr, c.r, d.length));
  place_on_axis(g.get(), c.p, c.q, d.unit);
  return g;
}

/// The box as ODE's geom (full side lengths, the axes as the rotation's
/// columns, a left-handed frame's third axis negated).
Geom make_geom(const Obb& b) {
  Geom g(dCreateBox(nullptr, 2 * b.e.x, 2 * b.e.y, 2 * b.e.z));
  dGeomSetPosition(g.get(), b.c.x, b.c.y, b.c.z);
  const bool left_handed = dot(cross(b.axes[0], b.axes[1]), b.axes[2]) < 0;
  set_rotation(g.get(), b.axes[0], b.axes[1], left_handed ? -b.axes[2] : b.axes[2]);
  return g;
}

// --- what ODE can express -------------------------------------------------------

// --- one shape each: valid, and its converted values finite.

/// A cylinder: its length and mid point finite.
bool expressible(const Cylinder& c) {
  if (!is_valid(c)) return false;
  const Direction d = direction_of(c.q - c.p);
  return finite(d.length) && d.length > 0 && is_finite(0.5 * c.p + 0.5 * c.q);
}
/// A sphere: any valid one.
bool expressible(const Sphere& s) { return is_valid(s); }
/// A capsule: its length and mid point finite.
bool expressible(const Capsule& c) {
  if (!is_valid(c)) return false;
  return c.p == c.q || (finite(direction_of(c.q - c.p).length) && is_finite(0.5 * c.p + 0.5 * c.q));
}
/// A box: sides of at least DBL_MIN, their doubles finite, axes
/// orthonormal to 1e-12.
bool expressible(const Obb& b) {
  if (!is_valid(b)) return false;
  // ODE's box collider asserts (dxNormalize3) on a zero or subnormal side.
  if (!(b.e.x >= DBL_MIN && b.e.y >= DBL_MIN && b.e.z >= DBL_MIN)) return false;
  if (!(finite(2 * b.e.x) && finite(2 * b.e.y) && finite(2 * b.e.z))) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(b.axes[i], b.axes[j]) - (i == j ? 1.0 : 0.0)) <= 1e-12)) return false;
  return true;
}
/// A triangle: a finite, non-zero face normal.
bool expressible(const Triangle& t) {
  if (!is_valid(t)) return false;
  const Vec3 n = cross(t.b - t.a, t.c - t.a);
  return is_finite(n) && n != Vec3{};
}
/// A segment: a direction (a != b) of finite length.
bool expressible(const Segment& s) {
  if (!is_valid(s) || s.a == s.b) return false;
  return finite(direction_of(s.b - s.a).length);
}

/// A cylinder ODE's libccd colliders take: ccdGeomToCyl stops with ODE's
/// fatal error "Invalid cylinder has been passed in ccdGeomToCyl()" when
/// half the length is below DBL_EPSILON (an absolute bound: a cylinder
/// shorter than 2^-51, whatever its radius and the scene's scale).
bool libccd_takes(const Cylinder& c) { return 0.5 * direction_of(c.q - c.p).length >= DBL_EPSILON; }

/// Whether ODE can be asked about the pair: both shapes expressible and,
/// for the cylinder's pairs ODE answers with libccd (capsule, cylinder),
/// every cylinder long enough for it.
template <class A, class B>
bool expressible_pair(const A& a, const B& b) {
  if (!expressible(a) || !expressible(b)) return false;
  if constexpr (std::is_same_v<A, Cylinder> && std::is_same_v<B, Capsule>) return libccd_takes(a);
  if constexpr (std::is_same_v<A, Cylinder> && std::is_same_v<B, Cylinder>) return libccd_takes(a) && libccd_takes(b);
  return true;
}
/// The cast's pair: both shapes expressible.
bool expressible_pair(const Segment& s, const Cylinder& c) { return expressible(s) && expressible(c); }

/// PeerSubject::expresses of every expressed query.
template <class Case>
bool expresses(const Case& c) {
  return expressible_pair(c.a, c.b);
}

// --- asking ODE -------------------------------------------------------------------

constexpr int kMaxContacts = 32;

/// The deepest of ODE's contacts between a (g1) and b (g2), converted:
/// normal negated (ODE's points into g1), depth and position as ODE gives
/// them.
Contact deepest_contact(dGeomID a, dGeomID b) {
  dContactGeom contacts[kMaxContacts];
  const int n = dCollide(a, b, kMaxContacts, contacts, sizeof(dContactGeom));
  if (n <= 0) return {};
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (contacts[i].depth > contacts[best].depth) best = i;
  const dContactGeom& c = contacts[best];
  Contact out;
  out.hit = true;
  out.point = {c.pos[0], c.pos[1], c.pos[2]};
  out.normal = {-c.normal[0], -c.normal[1], -c.normal[2]};
  out.depth = c.depth;
  return out;
}

/// dCollide asked for one contact: does ODE see them meet?
bool any_contact(dGeomID a, dGeomID b) {
  dContactGeom contact;
  return dCollide(a, b, 1, &contact, sizeof(dContactGeom)) > 0;
}

/// overlap(): ODE's verdict with one contact asked for; "no" for a pair
/// ODE cannot express.
template <class A, class B>
bool ode_overlap(const A& a, const B& b) {
  if (!expressible_pair(a, b)) return false;
  ensure_ode();
  const Geom ga = make_geom(a);
  if constexpr (std::is_same_v<B, Triangle>) {
    const TriangleGeom gb(b);
    return any_contact(ga.get(), gb.get());
  } else {
    const Geom gb = make_geom(b);
    return any_contact(ga.get(), gb.get());
  }
}

/// collide(): ODE's deepest contact, converted; no hit for a pair ODE
/// cannot express.
template <class A, class B>
Contact ode_collide(const A& a, const B& b) {
  if (!expressible_pair(a, b)) return {};
  ensure_ode();
  const Geom ga = make_geom(a);
  if constexpr (std::is_same_v<B, Triangle>) {
    const TriangleGeom gb(b);
    return deepest_contact(ga.get(), gb.get());
  } else {
    const Geom gb = make_geom(b);
    return deepest_contact(ga.get(), gb.get());
  }
}

/// cast(): the start tested with a ball of radius 0, then ODE's ray of
/// length |b - a|; no hit for a pair ODE cannot express.
CastHit ode_cast(const Segment& s, const Cylinder& c) {
  if (!expressible_pair(s, c)) return {};
  ensure_ode();
  const Geom cyl = make_geom(c);
  // The start in the solid (touching included): a ball of radius 0 at a.
  const Geom start = make_geom(Sphere{s.a, 0.0});
  if (any_contact(cyl.get(), start.get())) {
    return starts_inside_at(s.a);
  }
  const Direction d = direction_of(s.b - s.a);
  const Geom ray(dCreateRay(nullptr, d.length));
  dGeomRaySet(ray.get(), s.a.x, s.a.y, s.a.z, d.unit.x, d.unit.y, d.unit.z);
  dContactGeom contacts[kMaxContacts];
  const int n = dCollide(ray.get(), cyl.get(), kMaxContacts, contacts, sizeof(dContactGeom));
  if (n <= 0) return {};
  int first = 0;
  for (int i = 1; i < n; ++i)
    if (contacts[i].depth < contacts[first].depth) first = i;
  const dContactGeom& k = contacts[first];
  CastHit h;
  h.hit = true;
  h.t = std::fmin(std::fmax(k.depth / d.length, 0.0), 1.0);
  h.point = {k.pos[0], k.pos[1], k.pos[2]};
  h.normal = {k.normal[0], k.normal[1], k.normal[2]};
  return h;
}

// --- claims -------------------------------------------------------------------------

/// The claims of ODE's subject of Q: production's `truth` (the same truth
/// judges both), ODE's own everything else.
template <QueryId Q>
Claims ode_claims(const char* normal, bool touching_is_contact, bool point) {
  Claims c = spec_of<Q>().claims;
  c.exact_verdict = false;
  c.depth = QueryTraits<Q>::kind == QueryKind::Collide ? Claims::Depth::UpperBound : Claims::Depth::None;
  c.point_in_both = point;
  c.normal = normal;
  c.touching_is_contact = touching_is_contact;
  c.margin = 0;
  return c;
}

constexpr const char* kEngine = "ODE " dODE_VERSION;

/// A collide query's subject: ODE's overlap and deepest contact.
template <QueryId Q>
PeerSubject<Q> collide_subject(const char* normal, bool touching_is_contact) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  static const Claims claims = ode_claims<Q>(normal, touching_is_contact, false);
  static const ImplOf<Q> subject{"ODE", [](const A& a, const B& b) { return ode_overlap(a, b); },
                                 [](const A& a, const B& b) { return ode_collide(a, b); }, &claims};
  return {&subject, [](const typename QueryTraits<Q>::Case& c) { return expresses(c); }, kEngine};
}

}  // namespace

/// ODE's dGetConfiguration(), ODE initialised first.
const char* ode_configuration() {
  ensure_ode();
  return dGetConfiguration();
}

/// What ODE says of its contact between shapes A and B: its normal's
/// convention in words, and whether exactly touching shapes make a contact.
/// A pair without an entry is one ODE is not asked about (its queries get
/// a null subject).
template <class A, class B>
struct OdeContact;
template <>
struct OdeContact<Cylinder, Sphere> {
  static constexpr const char* normal =
      "unit, from the cylinder towards the sphere: ODE's contact normal negated (dCollideCylinderSphere, closed "
      "form); a consistent contact (depth along it), not documented as the minimal translation";
  static constexpr bool touching_is_contact = true;
};
template <>
struct OdeContact<Cylinder, Capsule> {
  static constexpr const char* normal =
      "unit, from the cylinder towards the capsule: ODE's contact normal negated (dCollideCapsuleCylinder: libccd's "
      "MPR); a consistent contact by ODE's convention, MPR's portal direction in fact";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Cylinder, Obb> {
  static constexpr const char* normal =
      "unit, from the cylinder towards the box: ODE's contact normal negated (dCollideCylinderBox: separating "
      "axes); the deepest contact of ODE's clipped manifold";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Cylinder, Triangle> {
  static constexpr const char* normal =
      "unit, from the cylinder towards the triangle: ODE's contact normal negated (dCollideCylinderTrimesh on a "
      "two-faced trimesh, both windings); the deepest contact";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Cylinder, Cylinder> {
  static constexpr const char* normal =
      "unit, from the first cylinder towards the second: ODE's contact normal negated (dCollideCylinderCylinder: "
      "libccd's MPR, a rim ring for parallel axes); the deepest contact";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Sphere, Sphere> {
  static constexpr const char* normal =
      "unit, from the first sphere towards the second: ODE's contact normal negated (dCollideSphereSphere, closed "
      "form); a consistent contact, not documented as the minimal translation";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Sphere, Capsule> {
  static constexpr const char* normal =
      "unit, from the sphere towards the capsule: ODE's contact normal negated (dCollideCapsuleSphere, closed form, "
      "the arguments swapped by dCollide); a consistent contact, not documented as the minimal translation";
  static constexpr bool touching_is_contact = false;
};
template <>
struct OdeContact<Capsule, Capsule> {
  static constexpr const char* normal =
      "unit, from the first capsule towards the second: ODE's contact normal negated (dCollideCapsuleCapsule, closed "
      "form, two contacts for parallel segments); the deepest contact";
  static constexpr bool touching_is_contact = false;
};

/// Whether OdeContact<A, B> has an entry.
template <class A, class B, class = void>
struct HasOdeContact : std::false_type {};
template <class A, class B>
struct HasOdeContact<A, B, std::void_t<decltype(OdeContact<A, B>::normal)>> : std::true_type {};

/// ODE's subject of query Q (ode.hpp), found from the query's entry point
/// and shapes alone: a collide or penetration query of a pair with an
/// OdeContact entry (held to the query's claims), and the
/// segment cast (dCollideRayCylinder); a null subject for any other query
/// (ODE has no sweep, no continuous collision), so that a query ODE cannot
/// express needs no code here.
template <QueryId Q>
PeerSubject<Q> peer_ode() {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  constexpr QueryKind kind = QueryTraits<Q>::kind;
  if constexpr (kind == QueryKind::Collide && HasOdeContact<A, B>::value) {
    return collide_subject<Q>(OdeContact<A, B>::normal, OdeContact<A, B>::touching_is_contact);
  } else if constexpr (kind == QueryKind::Cast && std::is_same_v<B, Cylinder>) {
    static const Claims claims = ode_claims<Q>(
        "ODE's ray contact normal (dCollideRayCylinder, the ray as g1): the cylinder's outward surface normal at the "
        "hit; zero when the start is in the cylinder (asked of ODE with a ball of radius 0)",
        true, true);
    static const ImplOf<Q> subject{"ODE", [](const Segment& s, const Cylinder& c) { return ode_cast(s, c); }, &claims};
    return {&subject, [](const typename QueryTraits<Q>::Case& c) { return expresses(c); }, kEngine};
  } else {
    return {};
  }
}

// Every registered query: the template above, instantiated.
#define GEOMCHECK_X(id, entry, A, B, summary) template PeerSubject<QueryId::id> peer_ode<QueryId::id>();
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck::peers
