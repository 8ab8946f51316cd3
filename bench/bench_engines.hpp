// geomcheck benchmarks — the other engines (ODE, Bullet, MuJoCo, where this
// build has them) on a pair benchmark's batch, through their peer subjects:
// each call is what the campaign asks, the adapter's validation and the
// building of the engine's shapes from geomcheck's included (an engine
// takes its own shape objects; these are its answer as a user of geomcheck's
// shapes gets it). bench/CMakeLists.txt links each peer that is built and
// defines GEOMCHECK_BENCH_<ENGINE>.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "geomcheck/registry.hpp"
#include "geomcheck/results.hpp"
#if GEOMCHECK_BENCH_ODE
#include "geomcheck/peers/ode.hpp"
#endif
#if GEOMCHECK_BENCH_BULLET
#include "geomcheck/peers/bullet.hpp"
#endif
#if GEOMCHECK_BENCH_MUJOCO
#include "geomcheck/peers/mujoco.hpp"
#endif

namespace geomcheck::bench {

/// Another engine's overlap and collide over the pair's shapes, and its
/// name in the benchmarks' names (BM_<key>_collide_<set>).
template <class A, class B>
struct OtherEngine {
  std::string key;
  std::function<bool(const A&, const B&)> overlap;
  std::function<Contact(const A&, const B&)> collide;
};

namespace engines_detail {
template <QueryId Q, class Peer>
void add_engine(std::vector<OtherEngine<typename QueryTraits<Q>::ShapeA, typename QueryTraits<Q>::ShapeB>>& out,
                const char* key, const Peer& peer) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  if (!peer.subject) return;
  const auto* s = peer.subject;
  out.push_back({key, [s](const A& a, const B& b) { return s->overlap(a, b); },
                 [s](const A& a, const B& b) { return s->collide(a, b); }});
}
}  // namespace engines_detail

/// The engines of this build that express collide query Q.
template <QueryId Q>
std::vector<OtherEngine<typename QueryTraits<Q>::ShapeA, typename QueryTraits<Q>::ShapeB>> other_engines() {
  std::vector<OtherEngine<typename QueryTraits<Q>::ShapeA, typename QueryTraits<Q>::ShapeB>> out;
#if GEOMCHECK_BENCH_ODE
  engines_detail::add_engine<Q>(out, "ode", peers::peer_ode<Q>());
#endif
#if GEOMCHECK_BENCH_BULLET
  engines_detail::add_engine<Q>(out, "bullet", peers::peer_bullet<Q>());
#endif
#if GEOMCHECK_BENCH_MUJOCO
  engines_detail::add_engine<Q>(out, "mujoco", peers::peer_mujoco<Q>());
#endif
  return out;
}

}  // namespace geomcheck::bench
