// geomcheck — certified convex engine: penetration depth (EPA with a
// certified inner polytope) and time of impact (conservative advancement,
// then separation/overlap certificates at both ends of the interval).
#include <map>
#include <sstream>

#include "engine_search.hpp"

namespace geomcheck::oracle {

using namespace search;

namespace {

template <class T>
struct Face {
  int v[3];
  V3<T> n;  // unit outward normal
  T d;      // distance of the plane from the origin
  bool alive = true;
};

template <class T>
struct Epa {
  std::vector<Vert<T>> verts;
  std::vector<Face<T>> faces;
  int iterations = 0;
  bool ok = true;
  int start_of[4] = {0, 1, 2, 3};  // which certificate point each start vertex is
};

template <class T>
bool make_face(Epa<T>& e, int a, int b, int c, Face<T>& f) {
  using std::sqrt;
  const V3<T>& A = e.verts[a].w;
  V3<T> n = cross(e.verts[b].w - A, e.verts[c].w - A);
  const T nn = dot(n, n);
  if (!(nn > 0)) return false;
  n = (T(1) / sqrt(nn)) * n;
  f = Face<T>{{a, b, c}, n, dot(n, A), true};
  return true;
}

/// EPA from a tetrahedron holding the origin; stops when the gap between the
/// closest face and the support along its normal is below `tol`.
template <class T>
Epa<T> epa(const ShapeT<T>& A, const ShapeT<T>& B, const std::array<Vert<T>, 4>& tet, const T& tol, int max_iter) {
  Epa<T> e;
  e.verts.assign(tet.begin(), tet.end());
  // Orient the tetrahedron: (0,1,2) must face away from vertex 3.
  {
    const V3<T> n = cross(e.verts[1].w - e.verts[0].w, e.verts[2].w - e.verts[0].w);
    if (dot(n, e.verts[3].w - e.verts[0].w) > 0) {
      std::swap(e.verts[1], e.verts[2]);
      std::swap(e.start_of[1], e.start_of[2]);
    }
  }
  const int init[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  for (const auto& t : init) {
    Face<T> f;
    if (!make_face(e, t[0], t[1], t[2], f)) { e.ok = false; return e; }
    e.faces.push_back(f);
  }
  for (int it = 0; it < max_iter; ++it) {
    e.iterations = it + 1;
    int best = -1;
    for (std::size_t i = 0; i < e.faces.size(); ++i)
      if (e.faces[i].alive && (best < 0 || e.faces[i].d < e.faces[best].d)) best = static_cast<int>(i);
    if (best < 0) { e.ok = false; return e; }
    const Face<T> fb = e.faces[best];
    const Vert<T> v = support_vert(A, B, fb.n);
    const T dist = dot(v.w, fb.n);
    if (dist - fb.d <= tol) return e;
    const int vi = static_cast<int>(e.verts.size());
    e.verts.push_back(v);
    // Remove the faces that see the new point; keep the horizon.
    std::map<std::pair<int, int>, int> edges;
    for (auto& f : e.faces) {
      if (!f.alive) continue;
      if (dot(f.n, v.w - e.verts[f.v[0]].w) > 0) {
        f.alive = false;
        for (int k = 0; k < 3; ++k) {
          const int a = f.v[k], b = f.v[(k + 1) % 3];
          auto rev = edges.find({b, a});
          if (rev != edges.end()) edges.erase(rev);
          else edges[{a, b}] = 1;
        }
      }
    }
    if (edges.empty()) { e.ok = false; return e; }
    for (const auto& [ed, one] : edges) {
      Face<T> f;
      if (!make_face(e, ed.first, ed.second, vi, f)) { e.ok = false; return e; }
      e.faces.push_back(f);
    }
    // Compact occasionally.
    if (e.faces.size() > 4 * e.verts.size() + 64) {
      std::vector<Face<T>> keep;
      for (const auto& f : e.faces)
        if (f.alive) keep.push_back(f);
      e.faces.swap(keep);
    }
  }
  return e;
}

/// Certified depth interval from an EPA polytope.
/// Lower bound: the faces form a closed surface, every face has the origin
/// strictly on its inner side (exact sign), so every ray from the origin
/// meets the surface, the surface lies in A - B (its vertices are points
/// a_i - b_i built inside), and the depth is at least the smallest face
/// distance. Upper bound: the support of A - B along the closest face normal.
template <class T>
bool certify_epa(const ConvexShape& A, const ConvexShape& B, const Epa<T>& e, const OverlapCertificate& start,
                 PenetrationResult& out) {
  // The first four vertices are the overlap certificate's exact points.
  std::vector<QVec> W(e.verts.size());
  for (std::size_t i = 0; i < e.verts.size(); ++i)
    W[i] = i < 4 ? start.a[e.start_of[i]] - start.b[e.start_of[i]]
                 : sup_point_q(A, e.verts[i].a) - sup_point_q(B, e.verts[i].b);
  std::vector<const Face<T>*> faces;
  std::map<std::pair<int, int>, int> edge_count;
  for (const auto& f : e.faces) {
    if (!f.alive) continue;
    faces.push_back(&f);
    for (int k = 0; k < 3; ++k) ++edge_count[{f.v[k], f.v[(k + 1) % 3]}];
  }
  // Closed, consistently oriented surface: each directed edge once, and its
  // reverse once.
  for (const auto& [ed, n] : edge_count) {
    if (n != 1) return false;
    auto rev = edge_count.find({ed.second, ed.first});
    if (rev == edge_count.end() || rev->second != 1) return false;
  }
  // Closest face first: its exact lower bound is the candidate.
  std::sort(faces.begin(), faces.end(), [](const Face<T>* a, const Face<T>* b) { return a->d < b->d; });
  Q lo;
  bool have_lo = false;
  for (const Face<T>* f : faces) {
    const QVec &a = W[f->v[0]], &b = W[f->v[1]], &c = W[f->v[2]];
    const Q vol = dot(a, cross(b, c));  // origin strictly inside: > 0
    if (!(vol > 0)) return false;
    const QVec n = cross(b - a, c - a);
    const Q nn = dot(n, n);
    // dist = vol / |n| >= lo  <=>  vol^2 >= lo^2 |n|^2 (vol > 0).
    if (have_lo && vol * vol >= lo * lo * nn) continue;
    const Q d = vol / sqrt_interval(nn).hi;
    if (!have_lo || d < lo) lo = d;
    have_lo = true;
  }
  if (!have_lo) return false;
  // Upper bound along the closest face normal (rationalised).
  const QVec n = exact_q(faces.front()->n);
  const QInterval h = (support_value(A, n) + support_value(B, Q(-1) * n)) / sqrt_interval(dot(n, n));
  out.overlapping = lo > 0;
  out.depth = {lo, h.hi};
  out.direction = n;
  out.faces = static_cast<int>(faces.size());
  return out.overlapping;
}

}  // namespace

PenetrationResult penetration(const ConvexShape& a, const ConvexShape& b, double rel_width) {
  PenetrationResult out;
  std::ostringstream note;
  const Q scale = pair_scale(a, b);
  EngineOptions opt;
  opt.filter = false;
  const DistanceResult c = classify(a, b, opt);
  if (c.verdict != Verdict::Overlapping || !c.overlap) {
    out.note = std::string("not certified overlapping: ") + to_string(c.verdict);
    return out;
  }
  const ShapeT<HP128> A = convert<HP128>(a), B = convert<HP128>(b);
  // The starting tetrahedron: the certificate's points (exact, inside).
  std::array<Vert<HP128>, 4> tet;
  for (int i = 0; i < 4; ++i) {
    Sup<HP128> sa, sb;
    sa.i = sb.i = -2;  // a fixed point, not a support point
    sa.p = from_q<HP128>(c.overlap->a[i]);
    sb.p = from_q<HP128>(c.overlap->b[i]);
    tet[i] = make_vert(sa, sb);
  }
  const HP128 tol = from_q<HP128>(scale) * HP128(rel_width) / 4;
  const Epa<HP128> e = epa(A, B, tet, tol, 400);
  note << "epa128:" << e.iterations;
  if (!e.ok || !certify_epa(a, b, e, *c.overlap, out)) {
    // Fall back to the certificate's tetrahedron bounds.
    out.overlapping = true;
    out.depth = {Q(-c.distance.hi), Q(-c.distance.lo)};
    note << " (polytope not certified; tetrahedron bounds)";
  }
  out.note = note.str();
  return out;
}

const char* to_string(ImpactResult::Kind k) {
  switch (k) {
    case ImpactResult::Kind::NoHit: return "no hit";
    case ImpactResult::Kind::Hit: return "hit";
    case ImpactResult::Kind::StartsInside: return "starts inside";
    case ImpactResult::Kind::Undecided: return "undecided";
  }
  return "?";
}

ImpactResult time_of_impact(const ConvexShape& moving, const QVec& delta, const ConvexShape& b) {
  ImpactResult out;
  std::ostringstream note;
  const DistanceResult start = classify(moving, b);
  if (start.verdict == Verdict::Overlapping || start.verdict == Verdict::Touching) {
    out.kind = ImpactResult::Kind::StartsInside;
    out.t = point(Q(0));
    out.note = "start overlaps";
    return out;
  }
  if (start.verdict == Verdict::Undecided) {
    out.note = "start undecided";
    return out;
  }
  const DistanceResult whole = classify(swept(moving, delta), b);
  if (whole.verdict == Verdict::Separated) {
    out.kind = ImpactResult::Kind::NoHit;
    out.t = point(Q(1));
    out.note = "swept shape separated";
    return out;
  }
  // Conservative advancement in 128 digits: the distance is convex in t, so
  // the step d / (approach speed) never passes the first contact.
  const Q scale = pair_scale(moving, b);
  const ShapeT<HP128> B = convert<HP128>(b);
  const V3<HP128> dlt = from_q<HP128>(delta);
  const HP128 sc = from_q<HP128>(scale);
  const HP128 contact = ldexp(sc, -110);
  HP128 t = 0;
  bool reached = false;
  int steps = 0;
  for (; steps < 200; ++steps) {
    const ConvexShape at = translated(moving, exact_q(t) * delta);
    const ShapeT<HP128> A = convert<HP128>(at);
    // A loose GJK (2^-24) is enough: the step uses its lower bound of the
    // distance, so each step gains about 24 bits and none overshoots.
    const GjkOut<HP128> g = gjk(A, B, contact * contact, 400, false, 24);
    if (g.status == GjkStatus::Inside || g.status == GjkStatus::Contact) { reached = true; break; }
    using std::sqrt;
    const V3<HP128> v = g.simplex.closest;
    const HP128 vn = sqrt(dot(v, v));
    const HP128 d = g.vw / sqrt(g.vv);  // lower bound of the distance
    const HP128 speed = -dot(dlt, v) / vn;
    if (!(speed > 0)) break;
    if (d <= contact) { reached = true; break; }
    const HP128 step = d / speed;
    t += step;
    if (t > 1) break;
  }
  note << "advancement:" << steps;
  if (!reached && t <= 1) reached = true;  // stalled: try to certify around t
  if (t > 1) t = 1;
  // Certify [t_lo, t_hi] around t, widening on failure.
  const Q tq = exact_q(t);
  for (int k : {64, 48, 32, 16}) {
    const Q eps = Q(1) / Q(mp::mpz_int(1) << k);
    const Q tlo = tq - eps > 0 ? Q(tq - eps) : Q(0);
    const Q thi = tq + eps < 1 ? Q(tq + eps) : Q(1);
    const DistanceResult lo = tlo == 0 ? start : classify(swept(moving, tlo * delta), b);
    if (lo.verdict != Verdict::Separated) continue;
    const DistanceResult hi = classify(translated(moving, thi * delta), b);
    if (hi.verdict != Verdict::Overlapping && hi.verdict != Verdict::Touching) continue;
    out.kind = ImpactResult::Kind::Hit;
    out.t = {tlo, thi};
    note << " certified at 2^-" << k;
    out.note = note.str();
    return out;
  }
  note << " no certificate around t = " << to_double(tq);
  out.note = note.str();
  return out;
}

}  // namespace geomcheck::oracle
