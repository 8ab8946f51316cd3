// geomcheck — MuJoCo 2.2.2 as a peer subject: the conversions, the engine
// calls and the reading of its answers (include/geomcheck/peers/mujoco.hpp
// says what each one means and why).
#include "geomcheck/peers/mujoco.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace geomcheck::peers {

namespace {

// --- the model ---------------------------------------------------------------

/// The geoms of the peer's model, by index (each in a mocap body of its
/// own; nothing but their sizes and poses is ever changed).
enum GeomIndex { kCylinderA = 0, kSphere = 1, kCapsule = 2, kBox = 3, kCylinderB = 4, kSphereA = 5, kCapsuleA = 6 };

/// The peer's model: one geom of every type asked, margins and gaps zero
/// (MuJoCo's defaults too, written out), default options (mpr_tolerance
/// 1e-6, mpr_iterations 50, multi-point CCD off). The sizes are
/// placeholders: the adapter writes each case's sizes into geom_size.
constexpr const char kModelXml[] = R"(<mujoco model="geomcheck-peer">
  <default><geom margin="0" gap="0"/></default>
  <worldbody>
    <body name="a" mocap="true"><geom name="cylinder_a" type="cylinder" size="1 1"/></body>
    <body name="sphere" mocap="true"><geom name="sphere" type="sphere" size="1"/></body>
    <body name="capsule" mocap="true"><geom name="capsule" type="capsule" size="1 1"/></body>
    <body name="box" mocap="true"><geom name="box" type="box" size="1 1 1"/></body>
    <body name="b" mocap="true"><geom name="cylinder_b" type="cylinder" size="1 1"/></body>
    <body name="sphere_a" mocap="true"><geom name="sphere_a" type="sphere" size="1"/></body>
    <body name="capsule_a" mocap="true"><geom name="capsule_a" type="capsule" size="1 1"/></body>
  </worldbody>
</mujoco>
)";

constexpr const char kModelFile[] = "geomcheck_peer_mujoco.xml";

/// The compiled model, loaded once (mj_loadXML from an in-memory VFS);
/// every thread works on its own copy.
const mjModel& base_model() {
  static const std::unique_ptr<mjModel, void (*)(mjModel*)> model = [] {
    auto vfs = std::make_unique<mjVFS>();  // ~2 MB: not on the stack
    mj_defaultVFS(vfs.get());
    const int size = static_cast<int>(sizeof(kModelXml) - 1);
    if (mj_makeEmptyFileVFS(vfs.get(), kModelFile, size) != 0) throw std::runtime_error("MuJoCo: no VFS file");
    const int file = mj_findFileVFS(vfs.get(), kModelFile);
    std::memcpy(vfs->filedata[file], kModelXml, size);
    char error[1000] = "";
    mjModel* m = mj_loadXML(kModelFile, vfs.get(), error, sizeof(error));
    mj_deleteVFS(vfs.get());
    if (!m) throw std::runtime_error(std::string("MuJoCo refused the peer's model: ") + error);
    return std::unique_ptr<mjModel, void (*)(mjModel*)>(m, mj_deleteModel);
  }();
  return *model;
}

/// One thread's model and data: the adapter writes geom sizes (mjModel)
/// and geom poses (mjData) before each call, so no two threads may share
/// them.
struct Engine {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  Engine() {
    m = mj_copyModel(nullptr, &base_model());
    if (m) d = mj_makeData(m);
    if (!m || !d) {
      if (m) mj_deleteModel(m);
      throw std::runtime_error("MuJoCo: could not copy the peer's model");
    }
  }
  ~Engine() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
};

/// This thread's engine.
Engine& engine() {
  thread_local Engine e;
  return e;
}

// --- conversions -----------------------------------------------------------

/// Length of v, scaled first so that neither underflow nor overflow enters
/// the squares.
double norm(const Vec3& v) {
  const double m = max_abs(v);
  return m > 0 ? m * length((1.0 / m) * v) : 0.0;
}

/// Unit vector along a non-zero finite v (scaled like `norm`).
Vec3 unit(const Vec3& v) {
  const Vec3 s = (1.0 / max_abs(v)) * v;
  return (1.0 / length(s)) * s;
}

/// A geom as MuJoCo holds it: position (geom_xpos), frame (the columns of
/// geom_xmat: the geom's local x, y, z axes in the world) and geom_size.
struct GeomPose {
  Vec3 pos;
  Vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double size[3] = {0, 0, 0};
};

/// Half of q - p, exactly when q - p is finite, and as 0.5 q - 0.5 p
/// (which cannot overflow) when it is not.
Vec3 half_of(const Vec3& p, const Vec3& q) {
  const Vec3 d = q - p;
  return is_finite(d) ? 0.5 * d : 0.5 * q - 0.5 * p;
}

/// A segment pq (p != q) as a centred z-axis geom: position the midpoint
/// (0.5 p + 0.5 q, which cannot overflow), z axis the unit axis, x axis
/// any_perpendicular of it, y = z x x; size[1] the half length.
GeomPose z_axis_pose(const Vec3& p, const Vec3& q, double r) {
  const Vec3 half = half_of(p, q);
  GeomPose g;
  g.pos = 0.5 * p + 0.5 * q;
  const Vec3 u = unit(half);
  g.axis[0] = any_perpendicular(u);
  g.axis[1] = cross(u, g.axis[0]);
  g.axis[2] = u;
  g.size[0] = r;
  g.size[1] = norm(half);
  return g;
}

GeomPose pose_of(const Cylinder& c) { return z_axis_pose(c.p, c.q, c.r); }

GeomPose pose_of(const Sphere& s) {
  GeomPose g;
  g.pos = s.c;
  g.size[0] = s.r;
  return g;
}

/// A capsule p != q is MuJoCo's capsule; p == q (a ball) is MuJoCo's
/// sphere, whose compiler refuses a capsule of half length 0.
GeomPose pose_of(const Capsule& c) {
  if (c.p == c.q) return pose_of(Sphere{c.p, c.r});
  return z_axis_pose(c.p, c.q, c.r);
}

/// The box frame: the stored axes as columns; a left-handed frame gets its
/// third axis negated (the same set: the box is symmetric).
GeomPose pose_of(const Obb& b) {
  GeomPose g;
  g.pos = b.c;
  const bool left_handed = dot(cross(b.axes[0], b.axes[1]), b.axes[2]) < 0;
  g.axis[0] = b.axes[0];
  g.axis[1] = b.axes[1];
  g.axis[2] = left_handed ? -b.axes[2] : b.axes[2];
  g.size[0] = b.e.x;
  g.size[1] = b.e.y;
  g.size[2] = b.e.z;
  return g;
}

/// MuJoCo's row-major geom_xmat of a pose: mat[3 i + j] = axis[j][i].
void to_xmat(const GeomPose& g, mjtNum* mat) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mat[3 * i + j] = g.axis[j][i];
}

/// Writes a pose into geom `index` of this thread's model and data.
void place(Engine& e, int index, const GeomPose& g) {
  for (int i = 0; i < 3; ++i) {
    e.d->geom_xpos[3 * index + i] = g.pos[i];
    e.m->geom_size[3 * index + i] = g.size[i];
  }
  to_xmat(g, e.d->geom_xmat + 9 * index);
}

/// The geom that holds B.
int geom_of(const Sphere&) { return kSphere; }
int geom_of(const Capsule& c) { return c.p == c.q ? kSphere : kCapsule; }
int geom_of(const Obb&) { return kBox; }
int geom_of(const Cylinder&) { return kCylinderB; }
/// The geom that holds A (a geom of its own, so that A and B may be of one type).
int geom_of_a(const Cylinder&) { return kCylinderA; }
int geom_of_a(const Sphere&) { return kSphereA; }
int geom_of_a(const Capsule& c) { return c.p == c.q ? kSphereA : kCapsuleA; }

// --- what MuJoCo can represent ------------------------------------------------

/// MuJoCo's compiler: "sizes must be positive" (every size of a geom type).
bool sizes_positive(const GeomPose& g, int n) {
  for (int i = 0; i < n; ++i)
    if (!(g.size[i] > 0 && std::isfinite(g.size[i]))) return false;
  return is_finite(g.pos);
}

bool representable(const Cylinder& c) { return is_valid(c) && sizes_positive(pose_of(c), 2); }
bool representable(const Sphere& s) { return is_valid(s) && sizes_positive(pose_of(s), 1); }
bool representable(const Capsule& c) {
  return is_valid(c) && sizes_positive(pose_of(c), c.p == c.q ? 1 : 2);
}
/// A box: positive half sizes, and a frame MuJoCo can hold (a rotation
/// matrix, from a quaternion): the stored axes orthonormal to 1e-12.
bool representable(const Obb& b) {
  if (!is_valid(b) || !sizes_positive(pose_of(b), 3)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(b.axes[i], b.axes[j]) - (i == j ? 1.0 : 0.0)) <= 1e-12)) return false;
  return true;
}
bool representable(const Segment& s) { return is_valid(s); }

template <class A, class B, QueryId Q>
bool expresses_pair(const PairCase<A, B, Q>& c) {
  return representable(c.a) && representable(c.b);
}

// --- the engine's answers -----------------------------------------------------

/// mjCOLLISIONFUNC on A (its geom_of_a) and B: the table is upper
/// triangular in the geom types, so a B before A in MuJoCo's type order
/// (sphere, capsule before a cylinder) is geom 1 and the normal, from geom
/// 1 to geom 2, is negated; margin 0.
template <class A, class B>
Contact collide_mj(const A& a, const B& b) {
  Contact out;
  if (!is_valid(a) || !is_valid(b)) return out;
  Engine& e = engine();
  const int ga = geom_of_a(a);
  place(e, ga, pose_of(a));
  const int gb = geom_of(b);
  place(e, gb, pose_of(b));
  const int ta = e.m->geom_type[ga], tb = e.m->geom_type[gb];
  int g1 = ga, g2 = gb;
  bool flip = false;
  mjfCollision f = mjCOLLISIONFUNC[ta][tb];
  if (!f) {
    f = mjCOLLISIONFUNC[tb][ta];
    g1 = gb, g2 = ga, flip = true;
  }
  if (!f) throw std::logic_error("MuJoCo has no collision function for this pair");
  mjContact con[mjMAXCONPAIR];
  const int n = f(e.m, e.d, con, g1, g2, /*margin*/ 0.0);
  if (n <= 0) return out;
  int deepest = 0;  // one contact unless multi-point CCD is enabled (it is not)
  for (int i = 1; i < n; ++i)
    if (con[i].dist < con[deepest].dist) deepest = i;
  const mjContact& c = con[deepest];
  const double s = flip ? -1.0 : 1.0;
  out.hit = true;
  out.depth = -c.dist;
  out.normal = {s * c.frame[0], s * c.frame[1], s * c.frame[2]};
  out.point = {c.pos[0], c.pos[1], c.pos[2]};
  return out;
}

template <class A, class B>
bool overlap_mj(const A& a, const B& b) {
  return collide_mj(a, b).hit;
}

/// The cylinder's outward normal at x, a point on its surface: the cap's
/// axis when x is nearer the cap's plane than the curved side, else the
/// radial direction (MuJoCo 2.2.2's ray returns no normal).
Vec3 surface_normal(const GeomPose& g, const Vec3& x) {
  const Vec3 d = x - g.pos;
  const double lx = dot(d, g.axis[0]), ly = dot(d, g.axis[1]), lz = dot(d, g.axis[2]);
  const double radial = std::hypot(lx, ly);
  const double cap_gap = std::fabs(std::fabs(lz) - g.size[1]);
  const double side_gap = std::fabs(radial - g.size[0]);
  if (cap_gap <= side_gap || !(radial > 0)) return lz < 0 ? -g.axis[2] : g.axis[2];
  return unit(lx * g.axis[0] + ly * g.axis[1]);
}

/// mju_rayGeom (what mj_ray runs on a cylinder geom): the first surface
/// crossing of the ray a + x dir, x >= 0, dir unit. A start in the solid
/// (touching included) is told by rays both ways meeting the surface.
CastHit cast_mj(const Segment& s, const Cylinder& c) {
  CastHit out;
  if (!is_valid(s) || !is_valid(c)) return out;
  const GeomPose g = pose_of(c);
  mjtNum pos[3] = {g.pos.x, g.pos.y, g.pos.z}, mat[9], size[3] = {g.size[0], g.size[1], 0};
  to_xmat(g, mat);
  auto ray = [&](const Vec3& from, const Vec3& dir) {
    const mjtNum pnt[3] = {from.x, from.y, from.z}, vec[3] = {dir.x, dir.y, dir.z};
    return mju_rayGeom(pos, mat, size, pnt, vec, mjGEOM_CYLINDER);
  };
  const bool point = s.a == s.b;
  const Vec3 half = point ? Vec3{} : half_of(s.a, s.b);
  const Vec3 dir = point ? g.axis[2] : unit(half);
  const double ahead = ray(s.a, dir), behind = ray(s.a, -dir);
  if (ahead >= 0 && behind >= 0) {
    out.hit = true;
    out.starts_inside = true;
    out.point = s.a;
    return out;
  }
  if (point || !(ahead >= 0)) return out;
  const double half_length = norm(half);
  if (!(0.5 * ahead <= half_length)) return out;  // beyond b
  out.hit = true;
  out.t = std::fmin((0.5 * ahead) / half_length, 1.0);
  out.point = s.a + out.t * (s.b - s.a);
  out.normal = surface_normal(g, s.a + ahead * dir);
  return out;
}

// --- the subjects ---------------------------------------------------------------

/// "MuJoCo 2.2.2", from the library's own mj_version().
const char* engine_name() {
  static const std::string name = [] {
    const int v = mj_version();
    return "MuJoCo " + std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
  }();
  return name.c_str();
}

/// What MuJoCo claims on top of a query's spec `spec` (whose truth is
/// production's): an inexact verdict, the point in both shapes, touching
/// not a contact, no margin; its depth `depth` and its normal `normal`.
Claims mujoco_claims(const Claims& spec, Claims::Depth depth, const char* normal) {
  Claims c = spec;
  c.exact_verdict = false;
  c.depth = depth;
  c.point_in_both = true;
  c.normal = normal;
  c.touching_is_contact = false;
  c.margin = 0;
  return c;
}

/// What MuJoCo claims for a collide query (the header's "Claims").
template <QueryId Q>
const Claims* collide_claims() {
  static const Claims claims = mujoco_claims(
      spec_of<Q>().claims, Claims::Depth::Penetration,
      "MuJoCo's contact normal (libccd MPR's direction, then mjc_fixNormal's analytic normal for a sphere, a "
      "capsule and a cylinder's curved side; for the sphere and capsule pairs, the function MuJoCo's collision table "
      "holds for those geom types), negated when B is MuJoCo's geom 1: from A towards B");
  return &claims;
}

/// What MuJoCo claims for the cast.
const Claims* cast_claims() {
  static const Claims claims = mujoco_claims(
      spec_of<QueryId::cast_segment_cylinder>().claims, Claims::Depth::None,
      "the cylinder's outward normal at MuJoCo's hit point (cap or curved side, whichever surface is nearer; "
      "mju_rayGeom gives no normal); zero when the segment starts inside");
  return &claims;
}

/// The pairs MuJoCo is asked about: the cylinder against a sphere, capsule,
/// box or cylinder, and the sphere and capsule pairs.
template <class A, class B>
inline constexpr bool kCollidable =
    (std::is_same_v<A, Cylinder> && (std::is_same_v<B, Sphere> || std::is_same_v<B, Capsule> ||
                                     std::is_same_v<B, Obb> || std::is_same_v<B, Cylinder>)) ||
    ((std::is_same_v<A, Sphere> || std::is_same_v<A, Capsule>) &&
     (std::is_same_v<B, Sphere> || std::is_same_v<B, Capsule>));

/// The subject of query Q, or a null one where MuJoCo cannot express Q.
template <QueryId Q>
PeerSubject<Q> make_peer() {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  constexpr QueryKind kind = QueryTraits<Q>::kind;
  if constexpr (kind == QueryKind::Collide && kCollidable<A, B>) {
    static const ImplOf<Q> subject{"MuJoCo", &overlap_mj<A, B>, &collide_mj<A, B>, collide_claims<Q>()};
    return {&subject, &expresses_pair<A, B>, engine_name()};
  } else if constexpr (kind == QueryKind::Cast && std::is_same_v<A, Segment> && std::is_same_v<B, Cylinder>) {
    static const ImplOf<Q> subject{"MuJoCo", &cast_mj, cast_claims()};
    return {&subject, &expresses_pair<A, B>, engine_name()};
  } else {
    // Triangles: MuJoCo's only triangle is a mesh face, and its compiler
    // refuses a flat mesh. Sweeps: MuJoCo 2.2.2 has no continuous collision.
    return {};
  }
}

}  // namespace

#define GEOMCHECK_X(id, kind, A, B, summary) \
  template <>                                \
  PeerSubject<QueryId::id> peer_mujoco<QueryId::id>() { return make_peer<QueryId::id>(); }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck::peers
