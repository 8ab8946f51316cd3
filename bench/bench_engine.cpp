// The certified convex engine (oracle::classify / oracle::penetration) on
// cylinder-cylinder, box(Obb)-cylinder and triangle-cylinder, with FCL as the
// peer where it can be asked, in one run.
//
//   bench_engine [--benchmark_* flags]          (e.g. --benchmark_min_time=0.2)
//   GEOMCHECK_BENCH_SEED=<n> bench_engine       (other inputs)
//
// Sets (generated and checked outside the timed loops from a fixed seed,
// printed; one benchmark iteration is one pass over a set):
//   random  kBatch pairs: shapes of size ~1 (cylinder length 0.5..1.5, radius
//           0.2..0.6; box half extents 0.2..0.6, axes the columns of a random
//           rotation; triangle vertices 0.7 from a centre) centred uniformly
//           in [-2, 2]^3, random orientations; exactly half of them certified
//           overlapping (or touching), shuffled.
//   near    kBatch near-touching pairs with certified |signed distance| <
//           1e-9 * scale. From a random pose, B is moved along the line of
//           the centres, v = unit(centre A - centre B), to where it touches
//           A, by bisection on classify's certified verdicts (B + t v is
//           separated below the contact t and overlapping above it, up to
//           t = |centre A - centre B| where the centres coincide) until the
//           bracket is below 5e-11 * scale; B is then placed at the middle
//           of the bracket plus off, off uniform in [-1e-10, 1e-10] * scale.
//           Kept only when classify decides the final pair and |signed
//           distance| <= 1e-9 * scale is certified: by classify's own
//           enclosure when tight enough, else by one more certified verdict
//           on B translated exactly (in rationals) by |w| <= 1e-9 * scale
//           towards A (separated pair: the moved pair must be overlapping or
//           touching) or away from A (overlapping pair: the moved pair must
//           be separated); the signed distance is 1-Lipschitz in B's
//           translation. (Translating B by the certified distance along the
//           certificates' direction, as first planned, does not work here:
//           classify's distance enclosure for a verdict is often as loose
//           as [0.09, 1.4] (GJK stops at the first separating plane unless
//           EngineOptions::rel_width asks for more), and a tight enclosure
//           costs a penetration or a converged 128-digit GJK per case.)
//   depth   kDepthBatch random poses as above (256; GEOMCHECK_BENCH_DEPTH_CASES
//           overrides), all certified overlapping. penetration(.., 1e-30)
//           took ~20 ms per call, but tens of seconds on some inputs in
//           earlier versions of the engine, so a pass starts no new case
//           after kDepthBudgetDefault seconds (10;
//           GEOMCHECK_BENCH_DEPTH_SECONDS overrides) and the run stays
//           short: the per-query figure is over the cases reached (printed),
//           and the case in progress always finishes. Widths (depth.hi - depth.lo) / scale and per-case
//           times are recorded during the timed pass, the timer paused.
//           FCL's depth benchmark runs on the cases the engine reached.
//
// Timed: classify(make_shape(a), make_shape(b)) (the conversion from doubles
// is part of every query), and penetration(make_shape(a), make_shape(b),
// 1e-30).
//
// Peer: FCL is measured for cylinder-cylinder only (its box and triangle
// pairs are timed by bench_collide_cylinder_obb / _triangle), through the adapter's
// converted-pair calls (FclCylinderCylinder and fcl_*_prepared in
// fcl_convert.hpp, GST_LIBCCD). The conversion is inside the timed loop, as
// make_shape is for the engine. Note (fcl_adapter.hpp): for cylinder/cylinder
// FCL runs libccd's GJK/MPR (no closed form), whose MPR has no iteration cap
// and is known to hang on elongated or far-from-origin scenes; the scenes
// here are of size ~1 near the origin.
#include <benchmark/benchmark.h>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

namespace oc = geomcheck::oracle;
using oc::Verdict;

constexpr std::size_t kBatch = 256;          // random and near sets
constexpr std::size_t kDepthBatchDefault = 256; // depth set (GEOMCHECK_BENCH_DEPTH_CASES)
constexpr double kDepthBudgetDefault = 10;      // s per depth pass (GEOMCHECK_BENCH_DEPTH_SECONDS)
constexpr double kBoxHalf = 2.0;       // centres in [-2, 2]^3
constexpr double kNearRel = 1e-9;      // near-touching: |signed distance| < 1e-9 * scale
constexpr double kOffsetRel = 1e-10;   // target signed distance in [-1e-10, 1e-10] * scale
constexpr double kDepthRel = 1e-30;    // penetration width asked for
constexpr std::size_t kMaxAttempts = 200 * kBatch;

// Targets.
constexpr double kTargetRandom = 20000;  // verdicts/s
constexpr double kTargetNear = 1000;     // verdicts/s
constexpr double kTargetDepth = 2000;    // depths/s

// ---- random shapes ------------------------------------------------------------

Cylinder random_cylinder(Rng& rng) {
  const Vec3 c = rng.in_box(kBoxHalf);
  const Vec3 u = rng.direction();
  const double len = rng.uniform(0.5, 1.5);
  Cylinder out;
  out.p = c - (0.5 * len) * u;
  out.q = c + (0.5 * len) * u;
  out.r = rng.uniform(0.2, 0.6);
  return out;
}

Obb random_obb(Rng& rng) {
  // Uniform rotation from a uniform unit quaternion (rejection in the
  // 4-ball, squared norms above 1e-4).
  const std::array<double, 4> q = rng.unit_quaternion(std::nextafter(1e-4, 1.0));
  Obb b;
  b.c = rng.in_box(kBoxHalf);
  b.axes = rotation_columns(q);
  b.e = {rng.uniform(0.2, 0.6), rng.uniform(0.2, 0.6), rng.uniform(0.2, 0.6)};
  return b;
}

Triangle random_triangle(Rng& rng) {
  const Vec3 c = rng.in_box(kBoxHalf);
  return {c + 0.7 * rng.direction(), c + 0.7 * rng.direction(), c + 0.7 * rng.direction()};
}

Cylinder random_shape(Rng& rng, const Cylinder*) { return random_cylinder(rng); }
Obb random_shape(Rng& rng, const Obb*) { return random_obb(rng); }
Triangle random_shape(Rng& rng, const Triangle*) { return random_triangle(rng); }

Cylinder translate(Cylinder c, Vec3 t) { return {c.p + t, c.q + t, c.r}; }

// ---- printing (hex floats: the exact inputs) -------------------------------------

std::string hex(Vec3 v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", v.x, v.y, v.z);
  return buf;
}
std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}
std::string describe(const Cylinder& c) {
  return "Cylinder{p=" + hex(c.p) + ", q=" + hex(c.q) + ", r=" + hex(c.r) + "}";
}
std::string describe(const Obb& b) {
  return "Obb{c=" + hex(b.c) + ", axes={" + hex(b.axes[0]) + ", " + hex(b.axes[1]) + ", " + hex(b.axes[2]) +
         "}, e=" + hex(b.e) + "}";
}
std::string describe(const Triangle& t) {
  return "Triangle{a=" + hex(t.a) + ", b=" + hex(t.b) + ", c=" + hex(t.c) + "}";
}

const char* pair_name(const Cylinder*) { return "cylinder-cylinder"; }
const char* pair_name(const Obb*) { return "box-cylinder"; }
const char* pair_name(const Triangle*) { return "triangle-cylinder"; }
const char* pair_tag(const Cylinder*) { return "cylcyl"; }
const char* pair_tag(const Obb*) { return "boxcyl"; }
const char* pair_tag(const Triangle*) { return "tricyl"; }

// ---- sets -------------------------------------------------------------------------

template <class A>
struct Pair {
  A a;
  Cylinder b;
};

/// Seconds of one call, measured in the generation pass (CPU-bound, single thread).
template <class F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}


/// What the generation pass saw of a random or near set.
struct SetStats {
  std::size_t verdicts[4] = {0, 0, 0, 0};  // Separated, Touching, Overlapping, Undecided
  std::size_t attempts = 0, exceptions = 0, discarded = 0, by_filter = 0;
  std::vector<double> sec;                  // per kept case: one timed-equivalent query
  std::vector<double> sec_by[4];            // the same, by verdict
  double slowest_sec = 0;
  std::string slowest_input, slowest_note;
  std::string first_exception;              // message and input
  std::vector<std::string> undecided;       // inputs (hex) of Undecided verdicts, first few
  // near set
  double worst_near_rel = 0;                // max certified |signed distance| / scale
  std::size_t near_by_push = 0;             // bound from an exact push (classify's interval looser)
  std::size_t near_calls = 0;               // classify calls of the bisections
  // FCL (cylinder-cylinder only)
  bool fcl = false;
  std::size_t fcl_agree = 0, fcl_exceptions = 0, fcl_says_overlap = 0;
  std::vector<std::string> fcl_disagree;    // first few inputs where FCL's verdict differs
};

/// What the timed pass of penetration saw of one depth case.
struct DepthObs {
  bool seen = false;
  double sec = 0, rel_width = 0, depth_mid = 0, scale = 0;
  bool overlapping = false, reached = false, fallback = false;
  std::string note;
};

template <class A>
struct Set {
  std::vector<Pair<A>> pairs;
  SetStats st;
  std::vector<DepthObs> obs;  // depth set only
};

template <class A>
struct Sets {
  Set<A> random, near, depth;
};

template <class A>
std::string describe(const Pair<A>& pr) {
  return "A = " + describe(pr.a) + ", B = " + describe(pr.b);
}

void note_time(SetStats& st, double sec, Verdict v, const std::string& input, const std::string& note) {
  st.sec.push_back(sec);
  st.sec_by[static_cast<int>(v)].push_back(sec);
  if (sec > st.slowest_sec) {
    st.slowest_sec = sec;
    st.slowest_input = input;
    st.slowest_note = note;
  }
}

bool overlapping(Verdict v) { return v == Verdict::Overlapping || v == Verdict::Touching; }

double rel(const oc::Q& x, const oc::Q& scale) { return oc::to_double(x / scale); }
oc::Q q_abs(const oc::Q& x) { return x < 0 ? oc::Q(-x) : x; }

bool unit(Vec3& v) {
  const double l = length(v);
  if (!(l > 0) || !std::isfinite(l)) return false;
  v = (1 / l) * v;
  return true;
}

template <class A>
void count_verdict(SetStats& st, const Pair<A>& pr, const oc::DistanceResult& r) {
  ++st.verdicts[static_cast<int>(r.verdict)];
  st.by_filter += r.by_filter;
  if (r.verdict == Verdict::Undecided && st.undecided.size() < 5)
    st.undecided.push_back(describe(pr) + "  [" + r.note + "]");
}

/// Fills a set that fell short (attempt limit) up to n by repeating its cases.
template <class A>
void fill(Set<A>& s, std::size_t n, const char* what) {
  if (s.pairs.empty() || s.pairs.size() >= n) return;
  std::printf("WARNING: %s: only %zu cases after %zu attempts; repeated up to %zu\n", what, s.pairs.size(),
              s.st.attempts, n);
  for (std::size_t i = 0; s.pairs.size() < n; ++i) s.pairs.push_back(s.pairs[i]);
}

template <class A>
Pair<A> random_pair(Rng& rng) {
  A a = random_shape(rng, static_cast<const A*>(nullptr));
  return {a, random_cylinder(rng)};
}

// random: exactly half certified overlapping (or touching).
template <class A>
Set<A> make_random(Rng& rng) {
  Set<A> s;
  std::size_t n_over = 0, n_sep = 0;
  while (s.pairs.size() < kBatch && s.st.attempts < kMaxAttempts) {
    ++s.st.attempts;
    const Pair<A> pr = random_pair<A>(rng);
    oc::DistanceResult r;
    double sec = 0;
    try {
      sec = seconds([&] { r = oc::classify(oc::make_shape(pr.a), oc::make_shape(pr.b)); });
    } catch (const std::exception& e) {
      if (s.st.exceptions++ == 0) s.st.first_exception = std::string(e.what()) + " on " + describe(pr);
      continue;
    }
    const bool over = overlapping(r.verdict);
    if (over ? n_over >= kBatch / 2 : n_sep >= kBatch / 2) continue;
    (over ? n_over : n_sep)++;
    count_verdict(s.st, pr, r);
    note_time(s.st, sec, r.verdict, describe(pr), r.note);
    s.pairs.push_back(pr);
  }
  fill(s, kBatch, "random set");
  shuffle(s.pairs, rng);
  return s;
}

Vec3 centre(const Cylinder& c) { return 0.5 * c.p + 0.5 * c.q; }
Vec3 centre(const Obb& b) { return b.c; }
Vec3 centre(const Triangle& t) { return (1.0 / 3) * (t.a + t.b + t.c); }

/// Certifies |signed distance| <= 1e-9 * scale for a near-touching
/// candidate. classify as timed (filter on) gives the verdict; its distance
/// enclosure is used when it is tight enough. Otherwise B is translated
/// EXACTLY (in rationals, oracle::translated) by a vector w with
/// |w| <= 1e-9 * scale: towards A (along `towards`) for a separated pair,
/// which must then be certified overlapping or touching, and away from A for
/// an overlapping pair, which must then be certified separated. The signed
/// distance is 1-Lipschitz in the translation of B, so in both cases
/// |signed distance| <= |w|.
template <class A>
bool near_ok(const Pair<A>& pr, Vec3 towards, SetStats& st, bool keep_stats) {
  oc::DistanceResult r;
  const double sec = seconds([&] { r = oc::classify(oc::make_shape(pr.a), oc::make_shape(pr.b)); });
  if (r.verdict == Verdict::Undecided) {
    if (keep_stats) count_verdict(st, pr, r);
    return false;
  }
  const oc::ConvexShape a = oc::make_shape(pr.a), b = oc::make_shape(pr.b);
  const oc::Q scale = oc::pair_scale(a, b);
  const oc::Q eps = oc::to_q(kNearRel) * scale;
  oc::QInterval e = r.distance;
  bool pushed = false;
  if (!(e.lo >= -eps && e.hi <= eps) && r.verdict != Verdict::Touching) {
    const bool sep = r.verdict == Verdict::Separated;
    for (double f : {0.25, 0.9}) {
      const oc::QVec w = oc::to_q((sep ? 1.0 : -1.0) * f * kNearRel * oc::to_double(scale) * towards);
      const oc::Q ww = oc::dot(w, w);
      if (!(ww <= eps * eps)) continue;
      const Verdict v = oc::classify(a, oc::translated(b, w)).verdict;
      if (sep ? !overlapping(v) : v != Verdict::Separated) continue;
      const oc::Q bound = oc::sqrt_interval(ww).hi;
      e = sep ? oc::QInterval{r.distance.lo, bound} : oc::QInterval{oc::Q(-bound), oc::Q(0)};
      pushed = true;
      break;
    }
  }
  if (!(e.lo >= -eps && e.hi <= eps)) return false;
  if (keep_stats) {
    count_verdict(st, pr, r);
    st.near_by_push += pushed;
    st.worst_near_rel = std::max(st.worst_near_rel, rel(std::max(q_abs(e.lo), q_abs(e.hi)), scale));
    note_time(st, sec, r.verdict, describe(pr), r.note);
  }
  return true;
}

/// Moves B along the line of the centres, v = unit(centre A - centre B), to
/// where it touches A, by bisection on certified verdicts: B + t v is
/// separated for small t and overlapping at t = |centre A - centre B| (the
/// centres coincide), and the t where it overlaps form an interval (A - B is
/// convex). Stops when the bracket [t_sep, t_over] is below 5e-11 * scale,
/// then places B at its middle plus off_rel * scale. Counts classify calls.
template <class A>
bool place_near(Pair<A>& pr, double off_rel, Vec3& v, std::size_t& calls) {
  const oc::ConvexShape a = oc::make_shape(pr.a);
  v = centre(pr.a) - centre(pr.b);
  const double dist = length(v);
  if (!unit(v)) return false;
  const double scale = oc::to_double(oc::pair_scale(a, oc::make_shape(pr.b)));
  auto verdict_at = [&](double t) {
    ++calls;
    return oc::classify(a, oc::make_shape(translate(pr.b, t * v))).verdict;
  };
  double t_sep = 0, t_over = dist;
  const Verdict v0 = verdict_at(0);
  if (v0 == Verdict::Undecided) return false;
  if (v0 == Verdict::Separated) {
    if (!overlapping(verdict_at(t_over))) return false;
  } else {
    t_over = 0;
    double step = 0.5;
    for (t_sep = -step; verdict_at(t_sep) != Verdict::Separated; t_sep -= step, step *= 2)
      if (t_sep < -64) return false;
  }
  while (t_over - t_sep > 0.5 * kOffsetRel * scale) {
    const double mid = 0.5 * t_sep + 0.5 * t_over;
    const Verdict m = verdict_at(mid);
    if (m == Verdict::Undecided) return false;
    (m == Verdict::Separated ? t_sep : t_over) = mid;
  }
  pr.b = translate(pr.b, (0.5 * t_sep + 0.5 * t_over + off_rel * scale) * v);
  return true;
}

// near: |signed distance| < 1e-9 * scale, certified.
template <class A>
Set<A> make_near(Rng& rng) {
  Set<A> s;
  while (s.pairs.size() < kBatch && s.st.attempts < kMaxAttempts) {
    ++s.st.attempts;
    Pair<A> pr = random_pair<A>(rng);
    const double off_rel = rng.uniform(-kOffsetRel, kOffsetRel);
    Vec3 v;
    bool ok = false;
    try {
      ok = place_near(pr, off_rel, v, s.st.near_calls) && near_ok(pr, v, s.st, false);
    } catch (const std::exception& e) {
      if (s.st.exceptions++ == 0) s.st.first_exception = std::string(e.what()) + " on " + describe(pr);
      continue;
    }
    if (!ok) {
      ++s.st.discarded;
      continue;
    }
    near_ok(pr, v, s.st, true);  // the statistics of the kept case (same answers)
    s.pairs.push_back(pr);
  }
  fill(s, kBatch, "near set");
  return s;
}

// depth: certified overlapping random poses (penetration is observed in the
// timed pass).
template <class A>
Set<A> make_depth(Rng& rng, std::size_t n) {
  Set<A> s;
  while (s.pairs.size() < n && s.st.attempts < kMaxAttempts) {
    ++s.st.attempts;
    const Pair<A> pr = random_pair<A>(rng);
    try {
      const oc::DistanceResult r = oc::classify(oc::make_shape(pr.a), oc::make_shape(pr.b));
      if (r.verdict != Verdict::Overlapping) continue;
    } catch (const std::exception& e) {
      if (s.st.exceptions++ == 0) s.st.first_exception = std::string(e.what()) + " on " + describe(pr);
      continue;
    }
    s.pairs.push_back(pr);
  }
  fill(s, n, "depth set");
  s.obs.resize(s.pairs.size());
  return s;
}

// ---- FCL (cylinder-cylinder) -------------------------------------------------------

using FclPair = peers::FclCylinderCylinder;
FclPair fcl_pair(const Pair<Cylinder>& p) { return FclPair(p.a, p.b); }

// The adapter's calls on converted pairs (peers/fcl/fcl_convert.hpp).
bool fcl_collide(const FclPair& p) { return peers::fcl_overlap_prepared(p); }
/// FCL's penetration depth (collide with contact); -1 when FCL sees no contact.
double fcl_depth(const FclPair& p) {
  const peers::PeerContact c = peers::fcl_collide_prepared(p);
  return c.hit ? c.depth : -1.0;
}
/// FCL's distance (> 0 separated; negative when FCL sees contact).
double fcl_distance(const FclPair& p) { return peers::fcl_distance_prepared(p).distance; }

/// FCL's verdicts on a random or near cylinder set against the certified
/// ones (untimed; also runs every FCL query once before timing).
void fcl_check(Set<Cylinder>& s) {
  s.st.fcl = true;
  for (const Pair<Cylinder>& pr : s.pairs) {
    try {
      const FclPair fp = fcl_pair(pr);
      const bool f = fcl_collide(fp);
      const double d = fcl_distance(fp);
      s.st.fcl_says_overlap += f;
      const oc::DistanceResult r = oc::classify(oc::make_shape(pr.a), oc::make_shape(pr.b));
      const bool agree = f == overlapping(r.verdict);
      s.st.fcl_agree += agree;
      if (!agree && s.st.fcl_disagree.size() < 3) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "certified %s, distance in [%.3g, %.3g]; FCL collide %d, distance %.3g: ",
                      oc::to_string(r.verdict), oc::to_double(r.distance.lo), oc::to_double(r.distance.hi), f, d);
        s.st.fcl_disagree.push_back(buf + describe(pr));
      }
    } catch (const std::exception&) {
      ++s.st.fcl_exceptions;
    }
  }
}

// ---- timed loops ---------------------------------------------------------------------

/// `certificates` false: the verdict is still certified (by the interval
/// filter or the rational rounds), only the rational certificate objects are
/// not built when the filter decided (EngineOptions::certificates).
template <class A>
void bm_classify(benchmark::State& state, const std::vector<Pair<A>>* pairs, bool certificates) {
  oc::EngineOptions opt;
  opt.certificates = certificates;
  for (auto _ : state) {
    for (const Pair<A>& pr : *pairs) {
      const oc::DistanceResult r = oc::classify(oc::make_shape(pr.a), oc::make_shape(pr.b), opt);
      benchmark::DoNotOptimize(r.verdict);
    }
  }
  set_per_query(state, pairs->size());
}

/// Per-query figures for a benchmark that ran `done` queries in all.
void finish(benchmark::State& state, CaptureReporter* rep, const std::string& name, std::size_t done) {
  state.SetItemsProcessed(static_cast<std::int64_t>(done));
  state.counters["per_query"] =
      benchmark::Counter(static_cast<double>(done), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  rep->set_batch(name, static_cast<double>(done) / static_cast<double>(std::max<benchmark::IterationCount>(
                                                      state.iterations(), 1)));
}

/// penetration(.., 1e-30) over the depth set, in order; a pass starts no new
/// case once `budget` seconds have gone (the run must stay short, and one
/// case can take tens of seconds). The first time a case is seen, its
/// width and time are recorded with the timer paused.
template <class A>
void bm_penetration(benchmark::State& state, Set<A>* set, CaptureReporter* rep, std::string name, double budget) {
  std::size_t done = 0;
  for (auto _ : state) {
    const auto pass = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < set->pairs.size(); ++i) {
      if (i > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - pass).count() > budget) break;
      const Pair<A>& pr = set->pairs[i];
      const auto t0 = std::chrono::steady_clock::now();
      const oc::PenetrationResult p = oc::penetration(oc::make_shape(pr.a), oc::make_shape(pr.b), kDepthRel);
      const auto t1 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(p.overlapping);
      ++done;
      DepthObs& o = set->obs[i];
      if (o.seen) continue;
      state.PauseTiming();
      o.seen = true;
      o.sec = std::chrono::duration<double>(t1 - t0).count();
      o.overlapping = p.overlapping;
      o.note = p.note;
      const oc::Q scale = oc::pair_scale(oc::make_shape(pr.a), oc::make_shape(pr.b));
      o.scale = oc::to_double(scale);
      if (p.overlapping) {
        const oc::Q width = p.depth.hi - p.depth.lo;
        o.rel_width = rel(width, scale);
        o.reached = width <= oc::to_q(kDepthRel) * scale;
        o.depth_mid = p.depth.mid();
      }
      o.fallback = p.note.find("not certified") != std::string::npos;
      state.ResumeTiming();
    }
  }
  finish(state, rep, name, done);
}

/// FCL's depth on the depth cases the engine's benchmark reached (all of
/// them when it did not run).
void bm_fcl_depth(benchmark::State& state, const Set<Cylinder>* set, CaptureReporter* rep, std::string name) {
  std::vector<const Pair<Cylinder>*> cases;
  for (std::size_t i = 0; i < set->pairs.size(); ++i)
    if (set->obs[i].seen) cases.push_back(&set->pairs[i]);
  if (cases.empty())
    for (const auto& pr : set->pairs) cases.push_back(&pr);
  for (auto _ : state) {
    for (const Pair<Cylinder>* pr : cases) {
      const FclPair fp = fcl_pair(*pr);  // conversion from doubles, as make_shape for the engine
      benchmark::DoNotOptimize(fcl_depth(fp));
    }
  }
  finish(state, rep, name, cases.size() * static_cast<std::size_t>(state.iterations()));
}

template <class F>
void bm_fcl(benchmark::State& state, const std::vector<Pair<Cylinder>>* pairs, F query) {
  for (auto _ : state) {
    for (const Pair<Cylinder>& pr : *pairs) {
      const FclPair fp = fcl_pair(pr);  // conversion from doubles, as make_shape for the engine
      benchmark::DoNotOptimize(query(fp));
    }
  }
  set_per_query(state, pairs->size());
}

std::string bm_name(const char* what, const char* tag, const char* set) {
  return std::string("BM_") + what + "_" + tag + "_" + set;
}

template <class A>
void register_engine(Sets<A>& s, CaptureReporter& rep, double budget) {
  const A* k = nullptr;
  benchmark::RegisterBenchmark(bm_name("classify", pair_tag(k), "random").c_str(), bm_classify<A>, &s.random.pairs, true);
  benchmark::RegisterBenchmark(bm_name("classify", pair_tag(k), "near").c_str(), bm_classify<A>, &s.near.pairs, true);
  benchmark::RegisterBenchmark(bm_name("verdict", pair_tag(k), "random").c_str(), bm_classify<A>, &s.random.pairs, false);
  benchmark::RegisterBenchmark(bm_name("verdict", pair_tag(k), "near").c_str(), bm_classify<A>, &s.near.pairs, false);
  const std::string pen = bm_name("penetration", pair_tag(k), "depth");
  benchmark::RegisterBenchmark(pen.c_str(), bm_penetration<A>, &s.depth, &rep, pen, budget);
}

void register_fcl(const Sets<Cylinder>& s, CaptureReporter& rep) {
  using Q1 = bool (*)(const FclPair&);
  using Q2 = double (*)(const FclPair&);
  benchmark::RegisterBenchmark("BM_fcl_collide_cylcyl_random", bm_fcl<Q1>, &s.random.pairs, &fcl_collide);
  benchmark::RegisterBenchmark("BM_fcl_distance_cylcyl_random", bm_fcl<Q2>, &s.random.pairs, &fcl_distance);
  benchmark::RegisterBenchmark("BM_fcl_collide_cylcyl_near", bm_fcl<Q1>, &s.near.pairs, &fcl_collide);
  benchmark::RegisterBenchmark("BM_fcl_distance_cylcyl_near", bm_fcl<Q2>, &s.near.pairs, &fcl_distance);
  benchmark::RegisterBenchmark("BM_fcl_contact_cylcyl_depth", bm_fcl_depth, &s.depth, &rep,
                               std::string("BM_fcl_contact_cylcyl_depth"));
}

// ---- reports ---------------------------------------------------------------------------

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void print_set(const char* pair, const char* set, const SetStats& st) {
  const double med = median(st.sec);
  std::size_t slow = 0;
  for (double t : st.sec) slow += t > 10 * med;
  std::printf("%s %s: %zu cases (%zu attempts", pair, set, st.sec.size(), st.attempts);
  if (st.discarded) std::printf(", %zu discarded", st.discarded);
  std::printf(", %zu exceptions): separated %zu, touching %zu, overlapping %zu, undecided %zu; by filter %zu\n",
              st.exceptions, st.verdicts[0], st.verdicts[1], st.verdicts[2], st.verdicts[3], st.by_filter);
  std::printf("  classify (generation pass): median %.1f us (separated %.1f us, overlapping %.1f us), max %.1f us; "
              "%zu above 10x the median\n",
              med * 1e6, median(st.sec_by[0]) * 1e6, median(st.sec_by[2]) * 1e6, st.slowest_sec * 1e6, slow);
  if (!st.slowest_input.empty())
    std::printf("  slowest: %s  [%s]\n", st.slowest_input.c_str(), st.slowest_note.c_str());
  if (std::string(set) == "near") {
    std::printf("  max certified |signed distance| / scale = %.3g (limit %.0e); bound from an exact push (classify's "
                "interval looser) %zu; bisection: %zu classify calls\n",
                st.worst_near_rel, kNearRel, st.near_by_push, st.near_calls);
  }
  if (!st.first_exception.empty()) std::printf("  first exception: %s\n", st.first_exception.c_str());
  for (const std::string& u : st.undecided) std::printf("  UNDECIDED: %s\n", u.c_str());
  if (st.fcl) {
    std::printf("  FCL: collide says overlapping on %zu; agrees with the certified verdict on %zu/%zu; "
                "exceptions %zu\n",
                st.fcl_says_overlap, st.fcl_agree, st.sec.size(), st.fcl_exceptions);
    for (const std::string& d : st.fcl_disagree) std::printf("  FCL differs: %s\n", d.c_str());
  }
}

/// Generates (and prints as it goes) the three sets of a pair kind; FCL's
/// verdicts are checked for cylinder-cylinder.
template <class A>
void generate(Sets<A>& s, std::uint64_t seed, std::uint64_t stream, std::size_t n_depth) {
  const A* k = nullptr;
  auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  auto t = std::chrono::steady_clock::now();
  Rng r1(seed ^ (0x1111 * stream)), r2(seed ^ (0x1111 * (stream + 1))), r3(seed ^ (0x1111 * (stream + 2)));
  // The random or near set just made (since t): FCL's check, the printout.
  auto made = [&](Set<A>& set, const char* name) {
    if constexpr (std::is_same_v<A, Cylinder>) fcl_check(set);
    print_set(pair_name(k), name, set.st);
    std::printf("  (generated in %.1f s)\n", since(t));
    std::fflush(stdout);
    t = std::chrono::steady_clock::now();
  };
  s.random = make_random<A>(r1);
  made(s.random, "random");
  s.near = make_near<A>(r2);
  made(s.near, "near");
  s.depth = make_depth<A>(r3, n_depth);
  std::printf("%s depth: %zu certified overlapping cases (%zu attempts, %zu exceptions; generated in %.1f s)\n",
              pair_name(k), s.depth.pairs.size(), s.depth.st.attempts, s.depth.st.exceptions, since(t));
  if (!s.depth.st.first_exception.empty())
    std::printf("  first exception: %s\n", s.depth.st.first_exception.c_str());
  std::fflush(stdout);
}

struct DepthSummary {
  std::size_t seen = 0, reached = 0, not_overlapping = 0, fallback = 0;
  double worst = 0;
};

template <class A>
DepthSummary print_depth(const Set<A>& s, bool fcl) {
  const A* k = nullptr;
  DepthSummary d;
  std::vector<double> sec;
  std::size_t worst_i = 0, slow_i = 0;
  for (std::size_t i = 0; i < s.obs.size(); ++i) {
    const DepthObs& o = s.obs[i];
    if (!o.seen) continue;
    ++d.seen;
    sec.push_back(o.sec);
    d.reached += o.reached;
    d.fallback += o.fallback;
    if (!o.overlapping) ++d.not_overlapping;
    const double w = o.overlapping ? o.rel_width : INFINITY;
    if (w >= d.worst) d.worst = w, worst_i = i;
    if (o.sec > s.obs[slow_i].sec) slow_i = i;
  }
  std::printf("%s depth: ", pair_name(k));
  if (d.seen == 0) {
    std::printf("penetration benchmark did not run\n");
    return d;
  }
  std::printf("%zu of %zu cases timed (budget); width (hi - lo) / scale worst %.3g, %zu/%zu <= %.0e; "
              "penetration not certified overlapping %zu (\"polytope not certified\" %zu)\n",
              d.seen, s.obs.size(), d.worst, d.reached, d.seen, kDepthRel, d.not_overlapping, d.fallback);
  std::printf("  penetration: median %.1f ms, max %.1f ms\n", median(sec) * 1e3, s.obs[slow_i].sec * 1e3);
  std::printf("  worst width: %s  [%s]\n", describe(s.pairs[worst_i]).c_str(), s.obs[worst_i].note.c_str());
  std::printf("  slowest:     %s  [%s]\n", describe(s.pairs[slow_i]).c_str(), s.obs[slow_i].note.c_str());
  std::size_t listed = 0;
  for (std::size_t i = 0; i < s.obs.size(); ++i)
    if (s.obs[i].seen && (s.obs[i].fallback || !s.obs[i].reached) && i != worst_i)
      if (++listed <= 5)
        std::printf("  %s %.3g in %.1f ms: %s  [%s]\n", s.obs[i].overlapping ? "width" : "NO DEPTH, width",
                    s.obs[i].overlapping ? s.obs[i].rel_width : INFINITY, s.obs[i].sec * 1e3,
                    describe(s.pairs[i]).c_str(), s.obs[i].note.c_str());
  if constexpr (std::is_same_v<A, Cylinder>) {
    if (fcl) {
      std::size_t says = 0, exc = 0, cmp = 0;
      double lo = INFINITY, hi = -INFINITY;
      std::vector<double> err;
      for (std::size_t i = 0; i < s.obs.size(); ++i) {
        try {
          const double fd = fcl_depth(fcl_pair(s.pairs[i]));
          says += fd >= 0;
          if (s.obs[i].seen && s.obs[i].reached && fd >= 0) {
            const double e = (fd - s.obs[i].depth_mid) / s.obs[i].scale;
            lo = std::min(lo, e), hi = std::max(hi, e);
            err.push_back(std::fabs(e));
            ++cmp;
          }
        } catch (const std::exception&) {
          ++exc;
        }
      }
      std::printf("  FCL: contact on %zu/%zu, exceptions %zu; (FCL depth - certified depth) / scale over the %zu "
                  "cases whose width reached 1e-30: min %.3g, max %.3g, median |.| %.3g\n",
                  says, s.obs.size(), exc, cmp, lo, hi, median(err));
    }
  }
  return d;
}

struct Row {
  const char* pair;
  const char* tag;
  DepthSummary depth;
  bool fcl;
};

void print_targets(const CaptureReporter& rep, const std::vector<Row>& rows) {
  std::printf("\n%-18s %-7s %22s  %-20s %-8s %12s %11s\n", "pair", "set", "engine /s", "target", "result",
              "FCL /s", "engine/FCL");
  auto rate = [&](const std::string& name) {
    const double ns = rep.ns_per_query(name);
    return ns > 0 ? 1e9 / ns : -1.0;
  };
  auto line = [&](const Row& r, const char* set, const std::string& eng, const std::string& fcl, double target,
                  const char* target_text) {
    const double e = rate(eng);
    std::printf("%-18s %-7s ", r.pair, set);
    if (e < 0) std::printf("%22s  ", "not run");
    else std::printf("%22.1f  ", e);
    std::printf("%-20s %-8s ", target_text, e < 0 ? "-" : (e >= target ? "met" : "NOT met"));
    const double f = r.fcl ? rate(fcl) : -1.0;
    if (!r.fcl) std::printf("%12s %11s\n", "no peer", "-");
    else if (f < 0 || e < 0) std::printf("%12s %11s\n", f < 0 ? "not run" : "", "-");
    else std::printf("%12.1f %10.1fx\n", f, f / e);
  };
  for (const Row& r : rows) {
    line(r, "random", bm_name("classify", r.tag, "random"), bm_name("fcl_collide", r.tag, "random"), kTargetRandom,
         ">= 20000 verdicts/s");
    line(r, "near", bm_name("classify", r.tag, "near"), bm_name("fcl_collide", r.tag, "near"), kTargetNear,
         ">= 1000 verdicts/s");
    line(r, "random*", bm_name("verdict", r.tag, "random"), bm_name("fcl_collide", r.tag, "random"), kTargetRandom,
         ">= 20000 verdicts/s");
    line(r, "near*", bm_name("verdict", r.tag, "near"), bm_name("fcl_collide", r.tag, "near"), kTargetNear,
         ">= 1000 verdicts/s");
    line(r, "depth", bm_name("penetration", r.tag, "depth"), bm_name("fcl_contact", r.tag, "depth"), kTargetDepth,
         ">= 2000 depths/s");
    char buf[64];
    if (r.depth.seen == 0) std::snprintf(buf, sizeof buf, "not run");
    else std::snprintf(buf, sizeof buf, "%zu/%zu, worst %.2g", r.depth.reached, r.depth.seen, r.depth.worst);
    const bool all = r.depth.seen > 0 && r.depth.reached == r.depth.seen;
    std::printf("%-18s %-7s %22s  %-20s %-8s\n", r.pair, "width", buf, "<= 1e-30 * scale",
                r.depth.seen == 0 ? "-" : (all ? "met" : "NOT met"));
  }
  std::printf("engine /s: CPU-time rate of classify (random, near) or penetration(.., 1e-30) (depth), make_shape "
              "included;\nrandom*, near*: the same verdicts, certified the same way, without building the rational "
              "certificate\nobjects when the interval filter decided (EngineOptions::certificates = false);\nengine/FCL: engine time / FCL time per query (fcl::collide; with contact for depths; "
              "conversion included);\nwidth: cases whose certified depth width reached 1e-30 * scale, and the worst "
              "width / scale. FCL: cylinder-cylinder only\n(the FCL adapter has no box or triangle conversion).\n");
}

double depth_budget_from_env() {
  if (const char* s = std::getenv("GEOMCHECK_BENCH_DEPTH_SECONDS")) {
    const double v = std::strtod(s, nullptr);
    if (v > 0) return v;
  }
  return kDepthBudgetDefault;
}

std::size_t depth_cases_from_env() {
  if (const char* s = std::getenv("GEOMCHECK_BENCH_DEPTH_CASES")) {
    const unsigned long long n = std::strtoull(s, nullptr, 0);
    if (n > 0) return static_cast<std::size_t>(n);
  }
  return kDepthBatchDefault;
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck;
  using namespace geomcheck::bench;
  const std::uint64_t seed = seed_from_env();
  const std::size_t n_depth = depth_cases_from_env();
  const double depth_budget = depth_budget_from_env();
  std::printf("engine benchmark: %s; %zu pairs per random/near set, up to %zu per depth set "
              "(GEOMCHECK_BENCH_DEPTH_CASES overrides), a depth pass starting no new case after %g s "
              "(GEOMCHECK_BENCH_DEPTH_SECONDS overrides)\n",
              seed_text(seed).c_str(), kBatch, n_depth, depth_budget);
  std::printf("shapes of size ~1 centred in [-%g, %g]^3; near: certified |d| < %.0e * scale (target offset within "
              "+-%.0e * scale); depth: penetration(.., %.0e)\n",
              kBoxHalf, kBoxHalf, kNearRel, kOffsetRel, kDepthRel);
  std::printf("FCL peer: cylinder-cylinder only (the FCL adapter has no box or triangle conversion): FclCylinder + "
              "fcl::collide / fcl::distance, GST_LIBCCD\n\n");
  std::fflush(stdout);

  const auto t0 = std::chrono::steady_clock::now();
  static Sets<Cylinder> cyl;
  static Sets<Obb> box;
  static Sets<Triangle> tri;
  // One generator per pair kind and set: a set does not depend on the others.
  generate(cyl, seed, 0, n_depth);
  generate(box, seed, 3, n_depth);
  generate(tri, seed, 6, n_depth);
  std::printf("(inputs generated and checked in %.1f s)\n\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  std::fflush(stdout);

  CaptureReporter reporter(kBatch);
  register_engine(cyl, reporter, depth_budget);
  register_engine(box, reporter, depth_budget);
  register_engine(tri, reporter, depth_budget);
  register_fcl(cyl, reporter);
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  std::printf("\n");
  const DepthSummary dc = print_depth(cyl.depth, true);
  const DepthSummary db = print_depth(box.depth, false);
  const DepthSummary dt = print_depth(tri.depth, false);
  print_summary(reporter, {
                              {"classify cylcyl random engine/FCL collide",
                               {"BM_classify_cylcyl_random", "BM_fcl_collide_cylcyl_random"}},
                              {"classify cylcyl random engine/FCL distance",
                               {"BM_classify_cylcyl_random", "BM_fcl_distance_cylcyl_random"}},
                              {"classify cylcyl near engine/FCL collide",
                               {"BM_classify_cylcyl_near", "BM_fcl_collide_cylcyl_near"}},
                              {"classify cylcyl near engine/FCL distance",
                               {"BM_classify_cylcyl_near", "BM_fcl_distance_cylcyl_near"}},
                              {"penetration cylcyl engine/FCL contact",
                               {"BM_penetration_cylcyl_depth", "BM_fcl_contact_cylcyl_depth"}},
                          });
  print_targets(reporter, {{"cylinder-cylinder", "cylcyl", dc, true},
                           {"box-cylinder", "boxcyl", db, false},
                           {"triangle-cylinder", "tricyl", dt, false}});
  return 0;
}
