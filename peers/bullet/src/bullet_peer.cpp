// geomcheck — Bullet as a peer subject (see include/geomcheck/peers/bullet.hpp
// for what Bullet is asked and how its answers are read).
#include "geomcheck/peers/bullet.hpp"

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>

#include <cmath>
#include <string>
#include <type_traits>

namespace geomcheck::peers {

namespace {

/// geomcheck's vector as Bullet's (btScalar is double in the double-precision build).
btVector3 to_bt(Vec3 v) { return btVector3(v.x, v.y, v.z); }
/// Bullet's vector as geomcheck's.
Vec3 from_bt(const btVector3& v) { return {double(v.x()), double(v.y()), double(v.z())}; }
/// The pose translating by c, no rotation.
btTransform translation(Vec3 c) { return btTransform(btMatrix3x3::getIdentity(), to_bt(c)); }

/// The pose and half length of a shape built along +z from p to q: the
/// centre p/2 + q/2 (no overflow), a rotation taking +z to the unit axis
/// (columns: any_perpendicular(u), u x that, u), the half length computed
/// from the axis scaled by its largest component (no overflow or underflow
/// of squares). p == q: the identity rotation, half length 0. `ok` is false
/// where the conversion leaves the doubles (q - p or the length overflows).
struct AxisFrame {
  btTransform pose;
  double half = 0;
  bool ok = false;
};

AxisFrame axis_frame(Vec3 p, Vec3 q) {
  AxisFrame f;
  const Vec3 centre = 0.5 * p + 0.5 * q;
  f.pose = translation(centre);
  const Vec3 d = q - p;
  if (!is_finite(d) || !is_finite(centre)) return f;
  const double m = max_abs(d);
  if (m == 0) {
    f.ok = true;
    return f;
  }
  const Vec3 s{d.x / m, d.y / m, d.z / m};
  const double ls = length(s);
  const Vec3 u = (1.0 / ls) * s;
  f.half = 0.5 * m * ls;
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  // btMatrix3x3 takes rows; the columns are the frame's axes.
  f.pose.setBasis(btMatrix3x3(e1.x, e2.x, u.x, e1.y, e2.y, u.y, e1.z, e2.z, u.z));
  f.ok = std::isfinite(f.half) && is_finite(u) && is_finite(e1) && is_finite(e2);
  return f;
}

/// Box axes orthonormal to 1e-12 (|a_i . a_j - delta_ij|): a rotation (or a
/// reflection of one) Bullet can take for a basis.
bool orthonormal(const Obb& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(b.axes[i], b.axes[j]) - (i == j ? 1.0 : 0.0)) <= 1e-12)) return false;
  return true;
}

// --- what Bullet can be given ---------------------------------------------------

// Whether Bullet can be given the shape (see the header's "Not expressed").
/// A valid cylinder whose axis frame stays in the doubles.
bool expressible(const Cylinder& c) { return is_valid(c) && axis_frame(c.p, c.q).ok; }
/// A valid sphere.
bool expressible(const Sphere& s) { return is_valid(s); }
/// A valid capsule whose axis frame stays in the doubles.
bool expressible(const Capsule& c) { return is_valid(c) && axis_frame(c.p, c.q).ok; }
/// A valid box with orthonormal axes.
bool expressible(const Obb& b) { return is_valid(b) && orthonormal(b); }
/// A valid triangle (degenerate ones included).
bool expressible(const Triangle& t) { return is_valid(t); }
/// A valid segment (a == b included).
bool expressible(const Segment& s) { return is_valid(s); }
/// A valid moving sphere (its end position finite).
bool expressible(const MovingSphere& m) { return is_valid(m); }

/// PeerSubject::expresses: both shapes can be given to Bullet.
template <class Case>
bool expresses_case(const Case& c) {
  return expressible(c.a) && expressible(c.b);
}

// --- the shapes, converted ---------------------------------------------------------
// Each holds a Bullet shape and a collision object posed in the world. The
// collision margins that would widen a shape are set to zero and the implicit
// dimensions to the exact half extents (setMargin(0) alone recomputes them as
// (h - 0.04) + 0.04, which rounds).

/// A shape along z (btCylinderShapeZ, btCapsuleShapeZ) of radius r on the
/// axis frame: its implicit dimensions set to the exact (r, r, frame.half),
/// `object` holding it at the frame's pose.
template <class Shape>
void place_on_axis(Shape& shape, btCollisionObject& object, const AxisFrame& frame, double r) {
  shape.setImplicitShapeDimensions(btVector3(r, r, frame.half));
  object.setCollisionShape(&shape);
  object.setWorldTransform(frame.pose);
}

/// Cylinder{p, q, r}: btCylinderShapeZ, half extents (r, r, |q - p| / 2),
/// margin 0, at the axis frame.
struct BtCylinder {
  AxisFrame frame;
  btCylinderShapeZ shape;
  btCollisionObject object;
  explicit BtCylinder(const Cylinder& c)
      : frame(axis_frame(c.p, c.q)), shape(btVector3(c.r, c.r, frame.half)) {
    shape.setMargin(0);
    place_on_axis(shape, object, frame, c.r);
  }
};

/// Sphere{c, r}: btSphereShape(r) (a point whose margin is r) at c.
struct BtSphere {
  btSphereShape shape;
  btCollisionObject object;
  explicit BtSphere(const Sphere& s) : shape(s.r) {
    object.setCollisionShape(&shape);
    object.setWorldTransform(translation(s.c));
  }
};

/// Capsule{p, q, r}: btCapsuleShapeZ (a segment of half height |q - p| / 2
/// whose margin is r) at the axis frame.
struct BtCapsule {
  AxisFrame frame;
  btCapsuleShapeZ shape;
  btCollisionObject object;
  explicit BtCapsule(const Capsule& c) : frame(axis_frame(c.p, c.q)), shape(c.r, 0) {
    place_on_axis(shape, object, frame, c.r);
  }
};

/// Obb{c, axes, e}: btBoxShape, half extents e, margin 0, basis columns the
/// axes (axes[2] negated in a left-handed frame: the same box).
struct BtBox {
  btBoxShape shape;
  btCollisionObject object;
  explicit BtBox(const Obb& b) : shape(to_bt(b.e)) {
    shape.setMargin(0);
    shape.setImplicitShapeDimensions(to_bt(b.e));
    const bool left_handed = dot(cross(b.axes[0], b.axes[1]), b.axes[2]) < 0;
    const Vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = left_handed ? -b.axes[2] : b.axes[2];
    object.setCollisionShape(&shape);
    object.setWorldTransform(
        btTransform(btMatrix3x3(a0.x, a1.x, a2.x, a0.y, a1.y, a2.y, a0.z, a1.z, a2.z), to_bt(b.c)));
  }
};

/// Triangle{a, b, c}: btTriangleShape of the three vertices in world
/// coordinates (identity pose), margin 0.
struct BtTriangle {
  btTriangleShape shape;
  btCollisionObject object;
  explicit BtTriangle(const Triangle& t) : shape(to_bt(t.a), to_bt(t.b), to_bt(t.c)) {
    shape.setMargin(0);
    object.setCollisionShape(&shape);
    object.setWorldTransform(translation({0, 0, 0}));
  }
};

/// The converted shape of geomcheck's shape S.
template <class S> struct BtOf;
template <> struct BtOf<Cylinder> { using type = BtCylinder; };
template <> struct BtOf<Sphere> { using type = BtSphere; };
template <> struct BtOf<Capsule> { using type = BtCapsule; };
template <> struct BtOf<Obb> { using type = BtBox; };
template <> struct BtOf<Triangle> { using type = BtTriangle; };

// --- the engine ----------------------------------------------------------------

/// One collision world per thread: the default collision configuration (its
/// convex-convex algorithm: GJK, EPA for penetration), a dispatcher, a
/// dynamic AABB tree broadphase. contactPairTest needs no object in the
/// world; rayTest and convexSweepTest see the cylinder only while it is in.
struct Engine {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
};

/// This thread's collision world.
btCollisionWorld& world() {
  static thread_local Engine engine;
  return engine.world;
}

/// The object in the world for the lifetime of this guard.
class InWorld {
 public:
  /// Adds `o` to this thread's world.
  explicit InWorld(btCollisionObject& o) : o_(o) { world().addCollisionObject(&o_); }
  /// Removes it.
  ~InWorld() { world().removeCollisionObject(&o_); }
  InWorld(const InWorld&) = delete;
  InWorld& operator=(const InWorld&) = delete;

 private:
  btCollisionObject& o_;
};

/// The deepest manifold point contactPairTest reports, in A's and B's terms
/// (a swapped pair is swapped back).
struct DeepestPoint : btCollisionWorld::ContactResultCallback {
  /// Collects the points of the pair whose first object is `a`.
  explicit DeepestPoint(const btCollisionObject* a) : a_(a) {}
  bool any = false;
  double distance = 0;       ///< getDistance(): < 0 penetrating
  Vec3 normal_b_to_a;        ///< m_normalWorldOnB, from B towards A
  Vec3 on_a, on_b;           ///< getPositionWorldOnA / OnB
  /// Keeps the point if it is the deepest so far.
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* w0, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    const double d = cp.getDistance();
    if (any && !(d < distance)) return 0;
    const bool swapped = w0->getCollisionObject() != a_;
    any = true;
    distance = d;
    const Vec3 n = from_bt(cp.m_normalWorldOnB);
    normal_b_to_a = swapped ? -n : n;
    on_a = from_bt(swapped ? cp.getPositionWorldOnB() : cp.getPositionWorldOnA());
    on_b = from_bt(swapped ? cp.getPositionWorldOnA() : cp.getPositionWorldOnB());
    return 0;
  }

 private:
  const btCollisionObject* a_;
};

/// contactPairTest(a, b): its deepest point.
DeepestPoint pair_test(btCollisionObject& a, btCollisionObject& b) {
  DeepestPoint d(&a);
  world().contactPairTest(&a, &b, d);
  return d;
}

/// Bullet's deepest point as geomcheck's contact: a hit when getDistance()
/// <= 0; depth -getDistance(); normal -m_normalWorldOnB (from A towards B);
/// point the midpoint of the two witness points.
Contact contact_of(const DeepestPoint& d) {
  if (!d.any || !(d.distance <= 0)) return {};
  Contact c;
  c.hit = true;
  c.depth = -d.distance;
  c.normal = -d.normal_b_to_a;
  c.point = 0.5 * d.on_a + 0.5 * d.on_b;
  return c;
}

/// collide(A, B): contactPairTest's deepest point as a contact; no hit where not expressible.
template <class A, class B>
Contact bullet_collide(const A& a, const B& b) {
  if (!expressible(a) || !expressible(b)) return {};
  typename BtOf<A>::type ca(a);
  typename BtOf<B>::type cb(b);
  return contact_of(pair_test(ca.object, cb.object));
}

/// overlap(A, B): collide's hit (the same call).
template <class A, class B>
bool bullet_overlap(const A& a, const B& b) {
  return bullet_collide(a, b).hit;
}

/// The hit a ray or convex sweep callback kept (ClosestRayResultCallback,
/// ClosestConvexResultCallback): its fraction, point and normal; no hit
/// when it found none.
template <class Callback>
CastHit first_hit(const Callback& cb) {
  if (!cb.hasHit()) return {};
  CastHit h;
  h.hit = true;
  h.t = cb.m_closestHitFraction;
  h.point = from_bt(cb.m_hitPointWorld);
  h.normal = from_bt(cb.m_hitNormalWorld);
  return h;
}

/// Segment cast: the start inside (a zero-radius sphere at s.a in contact
/// with the cylinder: getDistance() <= 0) is t = 0; otherwise rayTest from
/// s.a to s.b with a ClosestRayResultCallback.
CastHit bullet_cast(const Segment& s, const Cylinder& c) {
  if (!expressible(s) || !expressible(c)) return {};
  BtCylinder cyl(c);
  BtSphere start(Sphere{s.a, 0.0});
  if (contact_of(pair_test(cyl.object, start.object)).hit) {
    return starts_inside_at(s.a);
  }
  const InWorld in(cyl.object);
  btCollisionWorld::ClosestRayResultCallback cb(to_bt(s.a), to_bt(s.b));
  world().rayTest(to_bt(s.a), to_bt(s.b), cb);
  return first_hit(cb);
}

/// Sphere sweep: the ball meeting the cylinder at t = 0 (contactPairTest,
/// getDistance() <= 0) is t = 0 (point: see below); otherwise convexSweepTest of the
/// btSphereShape from c to c + delta (no rotation, allowed penetration 0)
/// with a ClosestConvexResultCallback.
CastHit bullet_sweep(const MovingSphere& m, const Cylinder& c) {
  if (!expressible(m) || !expressible(c)) return {};
  BtCylinder cyl(c);
  BtSphere ball(Sphere{m.c, m.r});
  const DeepestPoint d = pair_test(cyl.object, ball.object);
  const Contact at0 = contact_of(d);
  if (at0.hit) {
    // The point of both (production's: the cylinder point closest to c):
    // Bullet's witness on the cylinder while the centre is outside it (depth
    // r - dist(c, cylinder) < r), the centre itself once inside (depth >= r).
    return starts_inside_at(at0.depth >= m.r ? m.c : d.on_a);
  }
  const InWorld in(cyl.object);
  const btTransform from = translation(m.c), to = translation(m.c + m.delta);
  btCollisionWorld::ClosestConvexResultCallback cb(from.getOrigin(), to.getOrigin());
  world().convexSweepTest(&ball.shape, from, to, cb);
  return first_hit(cb);
}

// --- claims ----------------------------------------------------------------------

const char* const kCollideNormal =
    "-m_normalWorldOnB of contactPairTest's deepest point: from A towards B; depth -getDistance() "
    "(GJK minus the sphere's / capsule's radius, EPA when the cores meet); point the midpoint of "
    "getPositionWorldOnA and OnB";

/// Bullet's claims for collide query Q: production's `truth` text, the rest
/// Bullet's own.
template <QueryId Q>
const Claims* collide_claims() {
  static const Claims claims = [] {
    Claims c = spec_of<Q>().claims;
    c.exact_verdict = false;             // floating-point GJK / EPA with absolute tolerances
    c.depth = Claims::Depth::Penetration;  // EPA's (or GJK's, margins off) penetration depth
    c.point_in_both = false;             // one witness point on each surface; no point in both is promised
    c.normal = kCollideNormal;
    c.touching_is_contact = false;       // exact touching: GJK's distance of either sign
    c.margin = 0;                        // every widening margin set to zero
    return c;
  }();
  return &claims;
}

/// Bullet's claims for cast or sweep query Q (its normal in words).
template <QueryId Q>
const Claims* moving_claims(const char* normal) {
  static const Claims claims = [normal] {
    Claims c = spec_of<Q>().claims;
    c.exact_verdict = false;
    c.depth = Claims::Depth::None;
    c.point_in_both = true;  // the hit point: on the ray at t (cast), Bullet's point on the cylinder (sweep)
    c.normal = normal;
    c.touching_is_contact = false;
    c.margin = 0;
    return c;
  }();
  return &claims;
}

/// "Bullet <major>.<minor> (double precision)" from the headers' BT_BULLET_VERSION.
const char* engine_name() {
  static const std::string name = "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." +
                                  std::to_string(BT_BULLET_VERSION % 100) +
                                  (sizeof(btScalar) == 8 ? " (double precision)" : " (single precision)");
  return name.c_str();
}

/// The peer subject of collide query Q.
template <QueryId Q>
PeerSubject<Q> collide_peer() {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  static const ImplOf<Q> subject{"Bullet", [](const A& a, const B& b) { return bullet_overlap(a, b); },
                                 [](const A& a, const B& b) { return bullet_collide(a, b); }, collide_claims<Q>()};
  return {&subject, [](const typename QueryTraits<Q>::Case& c) { return expresses_case(c); }, engine_name()};
}

/// The subject of the cast or sweep query Q: `entry` (bullet_cast,
/// bullet_sweep) under moving_claims<Q>(normal).
template <QueryId Q, auto entry>
PeerSubject<Q> moving_peer(const char* normal) {
  static const ImplOf<Q> subject{"Bullet", entry, moving_claims<Q>(normal)};
  return {&subject, [](const typename QueryTraits<Q>::Case& c) { return expresses_case(c); }, engine_name()};
}

}  // namespace

/// Whether Bullet has a shape for geomcheck's shape S (BtOf<S>).
template <class S, class = void>
struct HasBt : std::false_type {};
template <class S>
struct HasBt<S, std::void_t<typename BtOf<S>::type>> : std::true_type {};

/// Bullet's subject of query Q, found from the query's entry point and
/// shapes alone: a collide or penetration query of two shapes Bullet has
/// (btCylinderShapeZ, btSphereShape, btCapsuleShapeZ, btBoxShape,
/// btTriangleShape; held to the query's claims), the segment
/// cast (start test, then rayTest) and the sphere sweep (start test, then
/// convexSweepTest) against the cylinder; a null subject for any other
/// query, so that a query Bullet cannot express needs no code here.
template <QueryId Q>
PeerSubject<Q> peer_bullet() {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  constexpr QueryKind kind = QueryTraits<Q>::kind;
  if constexpr (kind == QueryKind::Collide && HasBt<A>::value && HasBt<B>::value) {
    return collide_peer<Q>();
  } else if constexpr (kind == QueryKind::Cast && std::is_same_v<B, Cylinder>) {
    return moving_peer<Q, &bullet_cast>(
        "rayTest's m_hitNormalWorld: the cylinder's outward normal at the hit (zero when the segment starts inside: "
        "contactPairTest of a zero-radius sphere at the start)");
  } else if constexpr (kind == QueryKind::Sweep && std::is_same_v<B, Cylinder>) {
    return moving_peer<Q, &bullet_sweep>(
        "convexSweepTest's m_hitNormalWorld: the cylinder's normal towards the ball at t (zero when the ball meets "
        "the cylinder at t = 0: contactPairTest)");
  } else {
    return {};
  }
}

// Every registered query: the template above, instantiated.
#define GEOMCHECK_X(id, entry, A, B, summary) template PeerSubject<QueryId::id> peer_bullet<QueryId::id>();
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck::peers
