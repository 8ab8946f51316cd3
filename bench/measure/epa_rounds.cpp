// geomcheck — which rounds of the certified penetration depth (EPA in
// double-double, then 128, then 384 digits) the checks' requests reach, and
// what each bought: over the overlapping pairs among the first N cases of
// the campaign's generator mix (the main job's seed) of the cylinder/box,
// cylinder/triangle and cylinder/cylinder queries, oracle::penetration(a, b,
// 1e-20) as the checks ask it, tabulated by the rounds it ran (from its
// note) with the CPU time spent and how many reached the width.
//
// Built with -DGEOMCHECK_MEASURE=ON (the release preset):
//   build/release/bench/measure/epa_rounds 3000   (EPA_NOTES=1: the notes of
//   the pairs whose EPA stopped short)
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/properties/generators.hpp"

using namespace geomcheck;

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

struct Row {
  int pairs = 0, narrow = 0;
  double seconds = 0;
};

template <QueryId Q>
void run(int n) {
  const auto gen = gen::targeted<Q>();
  rc::Random random = geomcheck::gen::sequence<Q>(20261121);
  std::map<std::string, Row> rows;
  for (int i = 0; i < n; ++i) {
    const auto c = gen(random.split(), 50).value().first;
    if (!is_valid(c.a) || !is_valid(c.b)) continue;
    const oracle::ConvexShape a = oracle::make_shape(c.a), b = oracle::make_shape(c.b);
    oracle::EngineOptions o;
    o.certificates = false;
    if (oracle::classify(a, b, o).verdict != oracle::Verdict::Overlapping) continue;
    const double t0 = cpu_seconds();
    const oracle::PenetrationResult p = oracle::penetration(a, b, 1e-20);
    const double dt = cpu_seconds() - t0;
    const std::string& note = p.note;
    std::string key = note.find("epa106:") == std::string::npos ? "no double-double EPA" : "double-double";
    if (note.find("not converged") != std::string::npos) key += " not converged";
    if (note.find("step limit") != std::string::npos) key += " at its step limit";
    if (note.find("not certified") != std::string::npos) key += " not certified";
    if (note.find("epa128:") != std::string::npos) key += ", 128 digits";
    if (note.find("epa384:") != std::string::npos) key += ", 384 digits";
    if (!p.overlapping) key += ", no certificate";
    if (std::getenv("EPA_NOTES") && (note.find("not converged") != std::string::npos || note.find("step limit") != std::string::npos))
      std::printf("  #%d: %s\n", i, note.c_str());
    Row& r = rows[key];
    ++r.pairs;
    r.seconds += dt;
    if (p.overlapping && p.depth.hi - p.depth.lo <= oracle::pair_scale(a, b) * oracle::to_q(1e-20)) ++r.narrow;
  }
  std::printf("%s, overlapping pairs among the first %d cases:\n", info(Q).name, n);
  for (const auto& [k, r] : rows)
    std::printf("  %-56s %6d pairs  %6d to the width  %8.3f s  (%.2f ms a pair)\n", k.c_str(), r.pairs, r.narrow,
                r.seconds, 1e3 * r.seconds / r.pairs);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 3000;
  run<QueryId::collide_cylinder_obb>(n);
  run<QueryId::collide_cylinder_triangle>(n);
  run<QueryId::collide_cylinder_cylinder>(n);
}
