// geomcheck — certified convex engine: penetration depth (EPA with a
// certified inner polytope) and time of impact (conservative advancement,
// then separation/overlap certificates at both ends of the interval).
#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <optional>
#include <stdexcept>
#include <string>
#include <sstream>

#include "engine_interval.hpp"
#include "engine_search.hpp"

namespace geomcheck::oracle {

using namespace search;

namespace {

template <class T>
struct Face {
  int v[3];
  V3<T> n;  // outward normal (b - a) x (c - a), not normalised: no square root
  T nn;     // |n|^2
  T num;    // n . a = distance * |n|
  T d2;     // signed squared distance of the plane, num |num| / nn (for ordering)
  double dd;  // the distance and the unit normal, rounded, for the scans
  V3<double> nd;
  bool alive = true;
};

/// The face on the left of each directed edge (a, b) of the polytope, keyed
/// by (a, b) packed in 64 bits; only looked up, never iterated, so the
/// container's order cannot reach an answer.
struct EdgeMap {
  std::unordered_map<std::uint64_t, int> m;
  static std::uint64_t key(const std::pair<int, int>& e) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(e.first)) << 32) | static_cast<std::uint32_t>(e.second);
  }
  int& operator[](const std::pair<int, int>& e) { return m[key(e)]; }
  /// The face id, or -1.
  int find(const std::pair<int, int>& e) const {
    const auto it = m.find(key(e));
    return it == m.end() ? -1 : it->second;
  }
  void erase(const std::pair<int, int>& e) { m.erase(key(e)); }
  void clear() { m.clear(); }
};

template <class T>
struct Epa {
  std::vector<Vert<T>> verts;
  std::vector<V3<double>> wd;  // vertices rounded
  std::vector<Face<T>> faces;
  int iterations = 0;
  bool ok = true;
  bool converged = false;
  double gap = NAN;  // the last step's gap (support minus face distance) over the scale
};

inline double to_d(double x) { return x; }
template <class T> double to_d(const T& x) { return static_cast<double>(x); }
template <class T> V3<double> to_d(const V3<T>& v) { return {to_d(v.x), to_d(v.y), to_d(v.z)}; }

template <class T>
bool make_face(Epa<T>& e, int a, int b, int c, Face<T>& f) {
  const V3<T>& A = e.verts[a].w;
  const V3<T> n = cross(e.verts[b].w - A, e.verts[c].w - A);
  const T nn = dot(n, n);
  if (!(nn > 0)) return false;
  const T num = dot(n, A);
  const double inv = 1 / std::sqrt(to_d(nn));
  const V3<double> nd = to_d(n);
  f = Face<T>{{a, b, c}, n, nn, num, num * abs(num) / nn, to_d(num) * inv, {nd.x * inv, nd.y * inv, nd.z * inv}, true};
  return true;
}

/// Adds vertex `v` to the polytope: the faces that see it, grown from
/// `start` across edges (so that they form one patch), are replaced by a fan
/// from their boundary to the new vertex.
template <class T>
bool insert_point(Epa<T>& e, EdgeMap& edge_face, const Vert<T>& v, int start,
                  double margin) {
  const int vi = static_cast<int>(e.verts.size());
  e.verts.push_back(v);
  const V3<double> vd = to_d(v.w);
  e.wd.push_back(vd);
  auto visible = [&](const Face<T>& f) {
    const double sd = dot(f.nd, vd - e.wd[f.v[0]]);
    if (sd > margin) return true;
    if (sd < -margin) return false;
    return dot(f.n, v.w - e.verts[f.v[0]].w) > 0;
  };
  std::vector<int> stack{start};
  std::vector<std::pair<int, int>> horizon;
  e.faces[start].alive = false;
  std::vector<int> dead{start};
  while (!stack.empty()) {
    const int fi = stack.back();
    stack.pop_back();
    const Face<T> f = e.faces[fi];
    for (int k = 0; k < 3; ++k) {
      const int a = f.v[k], b = f.v[(k + 1) % 3];
      const int g = edge_face.find({b, a});
      if (g < 0) return false;
      if (!e.faces[g].alive) continue;  // already removed
      if (visible(e.faces[g])) {
        e.faces[g].alive = false;
        dead.push_back(g);
        stack.push_back(g);
      } else {
        horizon.push_back({a, b});
      }
    }
  }
  // An edge between two removed faces is not on the horizon: drop the ones
  // whose neighbour was removed after the edge was recorded.
  std::vector<std::pair<int, int>> rim;
  for (const auto& ed : horizon) {
    const int g = edge_face.find({ed.second, ed.first});
    if (g >= 0 && e.faces[g].alive) rim.push_back(ed);
  }
  for (int fi : dead)
    for (int k = 0; k < 3; ++k) edge_face.erase({e.faces[fi].v[k], e.faces[fi].v[(k + 1) % 3]});
  if (rim.size() < 3) return false;
  for (const auto& ed : rim) {
    Face<T> f;
    if (!make_face(e, ed.first, ed.second, vi, f)) return false;
    const int id = static_cast<int>(e.faces.size());
    e.faces.push_back(f);
    edge_face[{ed.first, ed.second}] = id;
    edge_face[{ed.second, vi}] = id;
    edge_face[{vi, ed.first}] = id;
  }
  return true;
}

/// EPA from a tetrahedron holding the origin; stops when the gap between the
/// closest face and the support along its normal is below `tol`. The scans
/// run on rounded copies; only close calls are settled in T.
template <class T>
Epa<T> epa(const ShapeT<T>& A, const ShapeT<T>& B, std::array<Vert<T>, 4> tet, const T& tol, double scale,
           int max_iter, EdgeMap& edge_face) {
  Epa<T> e;
  {
    const V3<T> n = cross(tet[1].w - tet[0].w, tet[2].w - tet[0].w);
    if (dot(n, tet[3].w - tet[0].w) > 0) std::swap(tet[1], tet[2]);
  }
  e.verts.assign(tet.begin(), tet.end());
  for (const auto& v : e.verts) e.wd.push_back(to_d(v.w));
  edge_face.clear();
  const int init[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  for (const auto& t : init) {
    Face<T> f;
    if (!make_face(e, t[0], t[1], t[2], f)) { e.ok = false; return e; }
    const int id = static_cast<int>(e.faces.size());
    e.faces.push_back(f);
    for (int k = 0; k < 3; ++k) edge_face[{t[k], t[(k + 1) % 3]}] = id;
  }
  const double margin = scale * 1e-9;
  for (int it = 0; it < max_iter; ++it) {
    e.iterations = it + 1;
    int best = -1;
    for (std::size_t i = 0; i < e.faces.size(); ++i)
      if (e.faces[i].alive && (best < 0 || e.faces[i].dd < e.faces[best].dd)) best = static_cast<int>(i);
    if (best < 0) { e.ok = false; return e; }
    // Settle ties in T among faces within rounding of the best.
    for (std::size_t i = 0; i < e.faces.size(); ++i)
      if (e.faces[i].alive && e.faces[i].dd <= e.faces[best].dd + 1e-12 * scale && e.faces[i].d2 < e.faces[best].d2)
        best = static_cast<int>(i);
    const Face<T> fb = e.faces[best];
    const Vert<T> v = support_vert(A, B, fb.n);
    // Converged when (support - plane distance) <= tol, i.e. gap <= tol |n|.
    const T gap = dot(v.w, fb.n) - fb.num;
    e.gap = to_d(gap) / std::sqrt(to_d(fb.nn)) / scale;
    if (gap <= 0 || gap * gap <= tol * tol * fb.nn) { e.converged = true; return e; }
    if (!insert_point(e, edge_face, v, best, margin)) { e.ok = false; return e; }
  }
  return e;
}

using Z = mp::mpz_int;
struct ZVec {
  Z x, y, z;
};
Z zdot(const ZVec& a, const ZVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ZVec zcross(const ZVec& a, const ZVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
ZVec zscale(const Z& s, const ZVec& a) { return {s * a.x, s * a.y, s * a.z}; }
ZVec zadd(const ZVec& a, const ZVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

/// A rational point as integer numerators over one positive denominator.
struct ZPoint {
  ZVec n;
  Z den;
};
ZPoint to_z(const QVec& p) {
  Z den = mp::denominator(p.x);
  den = mp::lcm(den, Z(mp::denominator(p.y)));
  den = mp::lcm(den, Z(mp::denominator(p.z)));
  auto num = [&](const Q& c) { return Z(mp::numerator(c) * (den / mp::denominator(c))); };
  return {{num(p.x), num(p.y), num(p.z)}, den};
}

/// One-ulp-wide double enclosure of a rational (mpq_get_d truncates towards
/// zero); false when it does not fit a finite double.
bool enclose(const Q& q, Iv& out) {
  const double d = mpq_get_d(q.backend().data());
  if (!std::isfinite(d)) return false;
  const int s = q.sign();
  out = s > 0 ? Iv{d, up(d)} : (s < 0 ? Iv{dn(d), d} : Iv{0, 0});
  return true;
}

/// Smallest face distance of a surface around the origin, certified, or
/// nothing when the surface is not closed and consistently oriented or a face
/// does not have the origin strictly on its inner side. Faces are visited in
/// the given order: the first one's exact distance (bracketed) is the
/// candidate bound; every other face is first checked in interval arithmetic
/// on double enclosures of the points (its orientation determinant certainly
/// positive and its distance certainly at least the bound), and only where
/// that cannot decide, with integers: a point is N / den; a face's distance
/// is det(N_a, N_b, N_c) / |M|, M = den_a (N_b x N_c) + den_c (N_a x N_b) +
/// den_b (N_c x N_a).
std::optional<Q> surface_lower_bound(const std::vector<QVec>& points, const std::vector<std::array<int, 3>>& faces,
                                     std::string& why) {
  // Closed and consistently oriented: every directed edge once, and its
  // reverse once.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(faces.size() * 3);
  for (const auto& f : faces) {
    for (int k = 0; k < 3; ++k) {
      if (f[k] < 0 || f[k] >= static_cast<int>(points.size())) { why = "vertex index out of range"; return {}; }
      edges.emplace_back(f[k], f[(k + 1) % 3]);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (i + 1 < edges.size() && edges[i + 1] == edges[i]) { why = "edge used twice"; return {}; }
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(edges[i].second, edges[i].first))) {
      why = "open surface";
      return {};
    }
  }
  std::vector<std::optional<ZPoint>> W(points.size());
  auto zpoint = [&](int i) -> const ZPoint& {
    if (!W[i]) W[i] = to_z(points[i]);
    return *W[i];
  };
  std::vector<IV3> box(points.size());
  std::vector<char> boxed(points.size(), 0);  // 1 enclosed, 2 not representable
  auto enclosed = [&](int i) {
    if (!boxed[i]) boxed[i] = enclose(points[i].x, box[i].x) && enclose(points[i].y, box[i].y) &&
                                      enclose(points[i].z, box[i].z) ? 1 : 2;
    return boxed[i] == 1;
  };
  Z lo_num, lo_den;  // lo = lo_num / lo_den, lo_den > 0
  bool have_lo = false;
  double lo_up = 0;  // a double at least lo
  for (const auto& f : faces) {
    if (have_lo && std::isfinite(lo_up) && enclosed(f[0]) && enclosed(f[1]) && enclosed(f[2])) {
      const IV3 &a = box[f[0]], &b = box[f[1]], &c = box[f[2]];
      // det(a, b, c) = a . (b x c) = n . a with n = (b - a) x (c - a); the
      // face's distance is det / |n|.
      const Iv det = dot(a, cross(b, c));
      const IV3 n = cross(b - a, c - a);
      const Iv nn = dot(n, n);
      // det / |n| >= lo  <=  det.lo > 0 and det.lo^2 >= lo_up^2 nn.hi.
      if (det.lo > 0 && nn.hi < INFINITY) {
        const Iv l2 = Iv::exact(det.lo) * Iv::exact(det.lo);
        const Iv r2 = Iv::exact(lo_up) * Iv::exact(lo_up) * Iv::exact(nn.hi);
        if (l2.lo >= r2.hi) continue;
      }
    }
    const ZPoint &a = zpoint(f[0]), &b = zpoint(f[1]), &c = zpoint(f[2]);
    const Z det = zdot(a.n, zcross(b.n, c.n));
    if (det <= 0) { why = "face through or behind the origin"; return {}; }
    const ZVec M = zadd(zadd(zscale(a.den, zcross(b.n, c.n)), zscale(c.den, zcross(a.n, b.n))), zscale(b.den, zcross(c.n, a.n)));
    const Z mm = zdot(M, M);
    // dist >= lo  <=>  det * lo_den >= lo_num * |M|  <=>  (det lo_den)^2 >= lo_num^2 |M|^2.
    if (have_lo) {
      const Z l = det * lo_den;
      if (l * l >= lo_num * lo_num * mm) continue;
    }
    const Q d = Q(det) / sqrt_interval(Q(mm)).hi;
    lo_num = mp::numerator(d);
    lo_den = mp::denominator(d);
    have_lo = true;
    lo_up = to_double_up(d);
  }
  if (!have_lo) { why = "no face"; return {}; }
  return Q(lo_num) / Q(lo_den);
}

/// Certified depth interval from an EPA polytope.
/// Lower bound: the faces form a closed, consistently oriented surface and
/// every face has the origin strictly on its inner side (exact signs), so
/// every ray from the origin meets the surface; the surface lies in A - B
/// (its vertices are points a_i - b_i built inside A and B), hence so does
/// the union of the segments from the origin to it, and the depth is at
/// least the smallest face distance. Upper bound: the support of A - B along
/// the closest face normal.
template <class T>
bool certify_epa(const ConvexShape& A, const ConvexShape& B, const Epa<T>& e, PenetrationResult& out) {
  std::vector<const Face<T>*> faces;
  for (const auto& f : e.faces)
    if (f.alive) faces.push_back(&f);
  // Closest face first (its bound is the candidate for all others).
  std::sort(faces.begin(), faces.end(), [](const Face<T>* a, const Face<T>* b) { return a->d2 < b->d2; });
  DepthCertificate cert;
  std::vector<int> index(e.verts.size(), -1);
  std::vector<QVec> W;
  for (const Face<T>* f : faces) {
    std::array<int, 3> g;
    for (int k = 0; k < 3; ++k) {
      int& id = index[f->v[k]];
      if (id < 0) {
        id = static_cast<int>(cert.a.size());
        cert.a.push_back(sup_point_q(A, e.verts[f->v[k]].a));
        cert.b.push_back(sup_point_q(B, e.verts[f->v[k]].b));
        W.push_back(cert.a.back() - cert.b.back());
      }
      g[k] = id;
    }
    cert.faces.push_back(g);
  }
  const std::optional<Q> lo = surface_lower_bound(W, cert.faces, out.note);
  if (!lo) return false;
  const QVec n = exact_q(faces.front()->n);
  const QInterval h = (support_value(A, n) + support_value(B, Q(-1) * n)) / sqrt_interval(dot(n, n));
  out.overlapping = *lo > 0;
  out.depth = {*lo, h.hi};
  out.direction = n;
  out.faces = static_cast<int>(faces.size());
  out.certificate = std::move(cert);
  return out.overlapping;
}

}  // namespace

bool check_depth(const ConvexShape& a, const ConvexShape& b, const DepthCertificate& c, const Q& lo) {
  if (c.a.size() != c.b.size()) return false;
  std::vector<QVec> W;
  for (std::size_t i = 0; i < c.a.size(); ++i) {
    if (!contains(a, c.a[i]) || !contains(b, c.b[i])) return false;
    W.push_back(c.a[i] - c.b[i]);
  }
  std::string why;
  const std::optional<Q> bound = surface_lower_bound(W, c.faces, why);
  return bound && *bound >= lo;
}

namespace {

/// A tetrahedron of Minkowski vertices around the origin, searched in T
/// (GJK, else the portal method, else the tetrahedral probes);
/// `contact_shift`: GJK stops within 2^-contact_shift * scale of the origin.
template <class T>
bool tet_around_origin(const ShapeT<T>& A, const ShapeT<T>& B, const T& sc, int contact_shift, int iter,
                       std::array<Vert<T>, 4>& tet) {
  const T contact = ldexp(sc, -contact_shift);
  const GjkOut<T> g = gjk(A, B, contact * contact, iter);
  if (g.status == GjkStatus::Inside) {
    tet = {g.simplex.v[0], g.simplex.v[1], g.simplex.v[2], g.simplex.v[3]};
    return true;
  }
  if (g.status != GjkStatus::Contact) return false;
  const MprOut<T> m = mpr(A, B, iter);
  std::vector<Vert<T>> cand(g.simplex.v.begin(), g.simplex.v.end());
  if (m.status == MprStatus::Hit) cand.insert(cand.end(), m.tet.begin(), m.tet.end());
  return enclosing_tet(A, B, cand, tet);
}

}  // namespace

namespace {
PenetrationResult penetration_impl(const ConvexShape& a, const ConvexShape& b, double rel_width, bool double_double) {
  PenetrationResult out;
  std::ostringstream note;
  const Q scale = pair_scale(a, b);
  if (double_double && dd::in_range(to_double(scale))) {
    // First in double-double: taken when EPA converges to the width and its
    // polytope is certified; else the software floats below, from scratch.
    const ShapeT<DD> A = convert<DD>(a), B = convert<DD>(b);
    const DD sc = from_q<DD>(scale);
    std::array<Vert<DD>, 4> tet;
    if (tet_around_origin(A, B, sc, 98, 400, tet)) {
      EdgeMap edge_face;
      const Epa<DD> e = epa(A, B, tet, sc * DD(rel_width) / 4, static_cast<double>(sc), 600, edge_face);
      note << "epa106:" << e.iterations;
      PenetrationResult r;
      if (e.ok && e.converged && certify_epa(a, b, e, r)) {
        r.note = note.str();
        note_stage(Stage::DoubleDouble);
        return r;
      }
      // Stopped by its step limit with the gap far above double-double's
      // rounding (2^-80 * scale): the optimum is a curve or a surface (two
      // coaxial cylinders: a circle of equally deep directions), which a
      // polytope approaches by a few bits per hundred steps whatever the
      // precision; the software floats' rounds would crawl the same way
      // (bench/measure/epa_rounds). Its certified polytope is the answer.
      if (e.ok && !e.converged && e.gap > 0x1p-80 && certify_epa(a, b, e, r)) {
        note << " (step limit, gap 2^" << std::ilogb(e.gap) << " scale)";
        r.note = note.str();
        note_stage(Stage::DoubleDouble);
        return r;
      }
      note << (e.ok && e.converged ? " (not certified) " : " (not converged, gap 2^" + std::to_string(std::ilogb(e.gap)) + " scale) ");
    }
  }
  const ShapeT<HP128> A = convert<HP128>(a), B = convert<HP128>(b);
  const HP128 sc = from_q<HP128>(scale);
  // A tetrahedron around the origin, searched in 128 digits.
  std::array<Vert<HP128>, 4> tet;
  if (!tet_around_origin(A, B, sc, 120, 400, tet)) {
    note << "no tetrahedron around the origin (not overlapping, or touching)";
    out.note = note.str();
    return out;
  }
  const HP128 tol = sc * HP128(rel_width) / 4;
  EdgeMap edge_face;
  Epa<HP128> e = epa(A, B, tet, tol, static_cast<double>(sc), 200, edge_face);
  note << "epa128:" << e.iterations << (e.converged ? "" : " (not converged, gap 2^" + std::to_string(std::ilogb(e.gap)) + " scale)");
  bool done = false;
  if (e.ok && !e.converged) {
    // Not converged in 128 digits: near a smooth optimum the faces get
    // small enough that their normals lose the digits a width of 1e-30 needs.
    // EPA again in 384 digits.
    const ShapeT<HP384> A3 = convert<HP384>(a), B3 = convert<HP384>(b);
    std::array<Vert<HP384>, 4> tet3;
    bool have3 = false;
    const HP384 sc3 = from_q<HP384>(scale);
    const HP384 contact3 = ldexp(sc3, -370);
    const GjkOut<HP384> g3 = gjk(A3, B3, contact3 * contact3, 800);
    if (g3.status == GjkStatus::Inside) {
      tet3 = {g3.simplex.v[0], g3.simplex.v[1], g3.simplex.v[2], g3.simplex.v[3]};
      have3 = true;
    } else {
      std::vector<Vert<HP384>> cand(g3.simplex.v.begin(), g3.simplex.v.end());
      have3 = enclosing_tet(A3, B3, cand, tet3);
    }
    if (have3) {
      EdgeMap ef3;
      Epa<HP384> e3 = epa(A3, B3, tet3, sc3 * HP384(rel_width) / 4, static_cast<double>(sc), 600, ef3);
      note << " epa384:" << e3.iterations;
      PenetrationResult r3;
      if (e3.ok && certify_epa(a, b, e3, r3)) {
        out = r3;
        done = true;
        note_stage(Stage::Soft384);
      } else {
        note << " (384: " << (e3.ok ? r3.note : std::string("search failed")) << ")";
      }
    }
  }
  if (!done && (!e.ok || !certify_epa(a, b, e, out))) {
    note << " polytope not certified: " << (e.ok ? out.note : std::string("search failed"));
    out = PenetrationResult{};
    note_stage(Stage::Undecided);
  } else if (!done) {
    note_stage(Stage::Soft128);
  }
  out.note = note.str();
  return out;
}

}  // namespace

PenetrationResult penetration(const ConvexShape& a, const ConvexShape& b, double rel_width, bool double_double) {
  try {
    return penetration_impl(a, b, rel_width, double_double);
  } catch (const std::invalid_argument&) {
    // A search that proposed a non-finite value: nothing certified.
    PenetrationResult out;
    out.note = "a non-finite proposal";
    note_stage(Stage::Undecided);
    return out;
  }
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

namespace {

/// Conservative advancement of `moving` along delta towards b in T, from
/// t = 0: the candidate t (in [0, 1]) around which the caller certifies.
/// `contact_shift`: contact within 2^-contact_shift * scale.
template <class T>
Q advance(const ConvexShape& moving, const QVec& delta, const ConvexShape& b, const Q& scale, int contact_shift,
          int& steps) {
  const ShapeT<T> B = convert<T>(b);
  const V3<T> dlt = from_q<T>(delta);
  const T sc = from_q<T>(scale);
  const T contact = ldexp(sc, -contact_shift);
  T t = 0;
  for (steps = 0; steps < 200; ++steps) {
    const ConvexShape at = translated(moving, exact_q(t) * delta);
    const ShapeT<T> A = convert<T>(at);
    // A loose GJK (2^-24) is enough: the step uses its lower bound of the
    // distance, so each step gains about 24 bits and none overshoots.
    const GjkOut<T> g = gjk(A, B, contact * contact, 400, false, 24);
    if (g.status == GjkStatus::Inside || g.status == GjkStatus::Contact) break;
    using std::sqrt;
    const V3<T> v = g.simplex.closest;
    const T vn = sqrt(dot(v, v));
    const T d = g.vw / sqrt(g.vv);  // lower bound of the distance
    const T speed = -dot(dlt, v) / vn;
    if (!(speed > 0)) break;
    if (d <= contact) break;
    const T step = d / speed;
    t += step;
    if (t > 1) break;
  }
  // Reached, stalled or past 1: the caller certifies around t either way.
  if (t > 1) t = 1;
  return exact_q(t);
}

}  // namespace

ImpactResult time_of_impact(const ConvexShape& moving, const QVec& delta, const ConvexShape& b, bool double_double) {
  ImpactResult out;
  std::ostringstream note;
  EngineOptions opt;
  opt.double_double = double_double;
  opt.narrow_undecided = false;  // only the verdicts are read below
  const DistanceResult start = classify(moving, b, opt);
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
  const DistanceResult whole = classify(swept(moving, delta), b, opt);
  if (whole.verdict == Verdict::Separated) {
    out.kind = ImpactResult::Kind::NoHit;
    out.t = point(Q(1));
    out.note = "swept shape separated";
    return out;
  }
  // Conservative advancement: the distance is convex in t, so the step
  // d / (approach speed) never passes the first contact. In double-double
  // where the scale allows, else in 128 digits.
  const Q scale = pair_scale(moving, b);
  int steps = 0;
  const Q tq = double_double && dd::in_range(to_double(scale))
                   ? advance<DD>(moving, delta, b, scale, 88, steps)
                   : advance<HP128>(moving, delta, b, scale, 110, steps);
  note << "advancement:" << steps;
  // Certify [t_lo, t_hi] around t, widening on failure.
  for (int k : {64, 48, 32, 16}) {
    const Q eps = Q(1) / Q(mp::mpz_int(1) << k);
    const Q tlo = tq - eps > 0 ? Q(tq - eps) : Q(0);
    const Q thi = tq + eps < 1 ? Q(tq + eps) : Q(1);
    const DistanceResult lo = tlo == 0 ? start : classify(swept(moving, tlo * delta), b, opt);
    if (lo.verdict != Verdict::Separated) continue;
    const DistanceResult hi = classify(translated(moving, thi * delta), b, opt);
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
