// geomcheck — the checks of the mesh family (mesh_checks.hpp): what they
// mean is at the head of the header.
#include "geomcheck/properties/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/properties/tolerances.hpp"

namespace geomcheck {

namespace {

constexpr QueryId kTriangle = QueryId::collide_cylinder_triangle;
constexpr std::uint32_t kNoFace = 0xffffffffu;

std::string describe(const Contact& k) { return geomcheck::describe(k, k.hit); }

bool eq(double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }
bool eq(Vec3 a, Vec3 b) { return eq(a.x, b.x) && eq(a.y, b.y) && eq(a.z, b.z); }
bool same_contact(const Contact& a, const Contact& b) {
  if (a.hit != b.hit) return false;
  return !a.hit || (eq(a.depth, b.depth) && eq(a.normal, b.normal) && eq(a.point, b.point));
}

CheckResult fail(const char* property, std::string detail) { return Failure{property, std::move(detail)}; }

double coord(Vec3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

// True when the triangle's bounding box is apart from the cylinder's (the
// box of its axis grown by r, each bound rounded outwards by one ulp, which
// covers the rounding of the one subtraction or addition): then no point of
// the triangle is in the cylinder, with certainty.
bool boxes_apart(const Cylinder& c, const Triangle& t) {
  for (int k = 0; k < 3; ++k) {
    const double a = coord(c.p, k), b = coord(c.q, k);
    const double lo = std::nextafter(std::min(a, b) - c.r, -INFINITY);
    const double hi = std::nextafter(std::max(a, b) + c.r, INFINITY);
    const double tlo = std::min({coord(t.a, k), coord(t.b, k), coord(t.c, k)});
    const double thi = std::max({coord(t.a, k), coord(t.b, k), coord(t.c, k)});
    if (thi < lo || tlo > hi) return true;
  }
  return false;
}

int strength(oracle::Verdict v) {
  switch (v) {
    case oracle::Verdict::Overlapping: return 3;
    case oracle::Verdict::Undecided: return 2;  // a face's distance within the engine's width of 0, either sign
    case oracle::Verdict::Touching: return 1;
    default: return 0;
  }
}

Contact first_face_collide(const Cylinder& a, const TriangleMesh& m, std::uint32_t* face) {
  if (!is_valid(a) || !m.valid()) return {};
  for (std::uint32_t f = 0; f < m.size(); ++f) {
    const Triangle t = m.triangle(f);
    if (!overlap(a, t)) continue;
    if (face) *face = f;
    return collide(a, t);
  }
  return {};
}

/// A triangle subject answering `k` for the one face it is asked about,
/// under `claims`: the door's mesh answer judged as a triangle answer.
struct FaceAnswer {
  Contact k;
  CollideImpl<Cylinder, Triangle> impl;
  FaceAnswer(const Contact& contact, const char* name, const Claims* claims)
      : k(contact),
        impl{name, [this](const Cylinder&, const Triangle&) { return k.hit; },
             [this](const Cylinder&, const Triangle&) { return k; }, claims} {}
  FaceAnswer(const FaceAnswer&) = delete;
  FaceAnswer& operator=(const FaceAnswer&) = delete;
};

/// The certified penetration depth of the cylinder into face f, enclosed:
/// [0, 0] where the face is certainly touching or apart, nothing where the
/// verdict or the depth is not certified.
std::optional<std::pair<double, double>> face_depth(const Cylinder& cyl, const Triangle& t,
                                                    const std::optional<Evaluation>& e) {
  if (!e || e->verdict == oracle::Verdict::Separated || e->verdict == oracle::Verdict::Touching)
    return std::make_pair(0.0, 0.0);  // no evaluation: the face's box is apart
  if (e->verdict != oracle::Verdict::Overlapping) return std::nullopt;
  const oracle::PenetrationResult p = oracle::penetration(oracle::make_shape(cyl), oracle::make_shape(t), 1e-9);
  if (!p.overlapping) return std::nullopt;
  return std::make_pair(oracle::to_double_down(p.depth.lo), oracle::to_double_up(p.depth.hi));
}

/// check_mesh_oracle for a subject with claims of its own (MeshClaims).
CheckResult check_own_claims(const Cylinder& cyl, const TriangleMesh& m, const MeshTruth& truth, const MeshImpl& impl,
                             const MeshClaims& claims) {
  std::uint32_t idx = kNoFace;
  const Contact k = impl.collide(cyl, m, &idx);
  if (!k.hit) {
    // A miss: every face the truth finds overlapping or touching is judged
    // with no hit under the subject's band; beyond it, a missed face.
    const FaceAnswer none(Contact{}, impl.name, &claims.face);
    for (std::uint32_t f = 0; f < m.size() && f < truth.faces.size(); ++f) {
      if (!truth.faces[f] || !truth.faces[f]->truth_hit) continue;
      const Evaluation e = evaluate(CylinderTriangleCase{cyl, m.triangle(f)}, none.impl);
      for (const Failure& g : judge_every(kTriangle, e, &claims.face))
        if (g.property == "oracle-verdict") return fail("oracle-verdict", "missed face " + std::to_string(f) + ": " + g.detail);
    }
    return std::nullopt;
  }
  if (idx >= m.size()) return fail("oracle-face", "reported face " + std::to_string(idx) + " out of range");
  // The reported face's contact, judged as the triangle query's answer.
  const FaceAnswer answer(k, impl.name, &claims.face);
  const Evaluation e = evaluate(CylinderTriangleCase{cyl, m.triangle(idx)}, answer.impl);
  if (auto g = judge(kTriangle, e, &claims.face))
    return fail(g->property == "oracle-verdict" ? "oracle-verdict" : "oracle-face",
                "face " + std::to_string(idx) + ": " + g->property + ": " + g->detail);
  if (!claims.deepest) return std::nullopt;
  // The deepest face: the reported face's penetration depth, certified,
  // against every overlapping face's.
  double ratio = claims.deepest_ratio;
  if (ratio <= 0)
    ratio = claims.face.depth == Claims::Depth::UpperBound ? tolerances(kTriangle).depth_ratio : 1.0;
  const std::optional<Evaluation> none;
  const auto mine = face_depth(cyl, m.triangle(idx), idx < truth.faces.size() ? truth.faces[idx] : none);
  if (!mine) return std::nullopt;  // not certified: not judged
  const double slack = 2 * e.tol.depth * e.scale;
  for (std::uint32_t f = 0; f < m.size() && f < truth.faces.size(); ++f) {
    if (f == idx || !truth.faces[f] || truth.faces[f]->verdict != oracle::Verdict::Overlapping) continue;
    const auto other = face_depth(cyl, m.triangle(f), truth.faces[f]);
    if (other && other->first > ratio * mine->second + slack)
      return fail("deepest-face", "reported face " + std::to_string(idx) + " (penetration depth at most " +
                                      fmt("%.17g", mine->second) + "), but face " + std::to_string(f) +
                                      " is deeper (at least " + fmt("%.17g", other->first) + fmt(", ratio %.3g", ratio) + ")");
  }
  return std::nullopt;
}

}  // namespace

const MeshImpl& production_mesh() {
  static const MeshImpl impl{
      "production", [](const Cylinder& a, const TriangleMesh& b) { return overlap(a, b); },
      [](const Cylinder& a, const TriangleMesh& b, std::uint32_t* f) { return collide(a, b, f); },
      [](const TriangleMesh& b, const Cylinder& a, std::uint32_t* f) { return collide(b, a, f); }};
  return impl;
}

const std::vector<const MeshImpl*>& mesh_variants() {
  static const MeshImpl first_face{
      "mesh_first_face", [](const Cylinder& a, const TriangleMesh& b) { return overlap(a, b); }, &first_face_collide,
      [](const TriangleMesh& b, const Cylinder& a, std::uint32_t* f) {
        Contact k = first_face_collide(a, b, f);
        if (k.hit) k.normal = -k.normal;
        return k;
      }};
  static const std::vector<const MeshImpl*> all{&first_face};
  return all;
}

const MeshImpl* mesh_subject(const std::string& name) {
  if (name == production_mesh().name) return &production_mesh();
  for (const MeshImpl* v : mesh_variants())
    if (name == v->name) return v;
  return nullptr;
}

CheckResult check_mesh_consistency(const Cylinder& cyl, const TriangleMesh& m, const MeshImpl& impl) {
  std::uint32_t idx = kNoFace, idx_s = kNoFace;
  const Contact k = impl.collide(cyl, m, &idx);
  const bool o = impl.overlap ? impl.overlap(cyl, m) : k.hit;
  if (k.hit != o) return fail("consistency", std::string("collide.hit ") + (k.hit ? "yes" : "no") + ", overlap " + (o ? "yes" : "no"));
  if (!is_valid(cyl) || !m.valid()) {
    if (o) return fail("robust", "invalid input (cylinder or mesh) gives a hit");
    return std::nullopt;
  }
  if (k.hit && (!std::isfinite(k.depth) || !is_finite(k.normal) || !is_finite(k.point)))
    return fail("robust", "non-finite contact: " + describe(k));
  if (impl.collide_flipped) {
    const Contact s = impl.collide_flipped(m, cyl, &idx_s);
    if (s.hit != k.hit || (k.hit && (idx_s != idx || !(s.normal == -k.normal && s.depth == k.depth && s.point == k.point))))
      return fail("symmetry-argument-order", "collide(mesh, cylinder) is not the flipped collide(cylinder, mesh): " +
                                                 describe(s) + " (face " + std::to_string(idx_s) + ")");
  }
  // A subject of its own claims: its answers are held to the truth
  // (check_mesh_oracle), not to production's triangle query.
  if (impl.claims) return std::nullopt;
  // The definition, face by face in index order: the verdict is "some face
  // overlaps" and the contact the deepest face's own (smallest index on ties).
  bool any = false;
  double deepest = -INFINITY;
  std::uint32_t first = kNoFace;
  for (std::uint32_t f = 0; f < m.size(); ++f) {
    const Triangle t = m.triangle(f);
    if (!overlap(cyl, t)) continue;
    any = true;
    const double d = collide(cyl, t).depth;
    if (d > deepest) deepest = d, first = f;
  }
  if (any != o)
    return fail("deepest-face", std::string("mesh verdict ") + (o ? "yes" : "no") + " but some face overlaps: " +
                                    (any ? "yes" : "no"));
  if (o) {
    if (idx != first)
      return fail("deepest-face",
                  "reported face " + std::to_string(idx) + ", the deepest (smallest index) is " + std::to_string(first));
    const Contact kf = collide(cyl, m.triangle(idx));
    if (!same_contact(k, kf))
      return fail("deepest-face", "contact differs from the face's own: " + describe(k) + " vs " + describe(kf));
  }
  // Production's hierarchy and face filter against its brute force, bit for
  // bit (the same answers by another road; a subject of its own has none).
  if (&impl == &production_mesh()) {
    const bool ob = detail::overlap_brute_force(cyl, m);
    std::uint32_t idx_b = kNoFace;
    const Contact kb = detail::collide_brute_force(cyl, m, &idx_b);
    if (o != ob || !same_contact(k, kb) || (k.hit && idx != idx_b))
      return fail("bvh-equals-brute-force", "hierarchy: face " + std::to_string(idx) + " " + describe(k) +
                                                "; brute force: overlap " + (ob ? "yes" : "no") + ", face " +
                                                std::to_string(idx_b) + " " + describe(kb));
  }
  return std::nullopt;
}

MeshTruth mesh_truth(const Cylinder& cyl, const TriangleMesh& m) {
  MeshTruth t;
  t.valid = is_valid(cyl) && m.valid();
  if (!t.valid) return t;
  t.faces.resize(m.size());
  for (std::uint32_t f = 0; f < m.size(); ++f) {
    const Triangle tri = m.triangle(f);
    if (boxes_apart(cyl, tri)) {
      ++t.faces_by_box;
      continue;
    }
    ++t.faces_by_engine;
    Evaluation e = evaluate(CylinderTriangleCase{cyl, tri});
    if (strength(e.verdict) > strength(t.verdict)) t.verdict = e.verdict;
    if (e.truth_hit && !e.near_boundary && !t.robust_hit)
      t.robust_hit = true, t.hit_text = "face " + std::to_string(f) + ": " + e.truth_text;
    t.faces[f] = std::move(e);
  }
  return t;
}

CheckResult check_mesh_oracle(const Cylinder& cyl, const TriangleMesh& m, const MeshTruth& truth,
                              const MeshImpl& impl) {
  if (!truth.valid) return std::nullopt;  // the robust check's
  if (impl.claims) return check_own_claims(cyl, m, truth, impl, *impl.claims);
  std::uint32_t idx = kNoFace;
  const Contact k = impl.collide(cyl, m, &idx);
  if (truth.robust_hit && !k.hit) return fail("oracle-verdict", "missed: " + truth.hit_text);
  if (!k.hit) return std::nullopt;
  if (idx >= m.size()) return fail("oracle-verdict", "reported face " + std::to_string(idx) + " out of range");
  const CylinderTriangleCase face{cyl, m.triangle(idx)};
  // The face's evaluation is production's triangle answer held to the
  // truth: the subject's contact must be that answer to be judged by it.
  if (!same_contact(k, collide(cyl, face.b)))
    return fail("oracle-face", "face " + std::to_string(idx) + ": the contact is not the face's triangle answer: " +
                                   describe(k) + " vs " + describe(collide(cyl, face.b)));
  const Evaluation e = idx < truth.faces.size() && truth.faces[idx] ? *truth.faces[idx] : evaluate(face);
  if (auto f = judge(kTriangle, e))
    return fail("oracle-face", "face " + std::to_string(idx) + ": " + f->property + ": " + f->detail);
  return std::nullopt;
}

CheckResult check_mesh_all(const Cylinder& cyl, const TriangleMesh& m, const MeshImpl& impl, MeshTruth* truth) {
  if (auto f = check_mesh_consistency(cyl, m, impl)) {
    if (truth) *truth = mesh_truth(cyl, m);  // the report's verdict of the failing case
    return f;
  }
  MeshTruth t = mesh_truth(cyl, m);
  CheckResult r = check_mesh_oracle(cyl, m, t, impl);
  if (truth) *truth = std::move(t);
  return r;
}

std::string describe_mesh(const Cylinder& cyl, const std::vector<Vec3>& vertices, const std::vector<MeshFace>& faces) {
  std::string s = "cylinder p=" + vec(cyl.p) + " q=" + vec(cyl.q) + " r=" + fmt("%.17g", cyl.r) + "\n  " +
                  std::to_string(vertices.size()) + " vertices:";
  for (std::size_t i = 0; i < vertices.size(); ++i) s += "\n    v" + std::to_string(i) + " " + vec(vertices[i]);
  s += "\n  " + std::to_string(faces.size()) + " faces:";
  for (std::size_t i = 0; i < faces.size(); ++i)
    s += "\n    f" + std::to_string(i) + " " + std::to_string(faces[i][0]) + " " + std::to_string(faces[i][1]) + " " +
         std::to_string(faces[i][2]);
  return s;
}

}  // namespace geomcheck
