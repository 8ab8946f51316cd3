// geomcheck — how often the certified engine leaves a pair Undecided, and how wide its
// enclosure of the signed distance is then, over the first N cases of the campaign's
// generator mix (the main job's seed) of every engine-backed collide query; the widest
// undecided cases written as case files.
//
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/undecided.
//   ./undecided 20000 [out_dir]   (writes out_dir/<query>-widest-K.case for the five widest)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/properties/generators.hpp"

using namespace geomcheck;

namespace {

template <QueryId Q>
void measure(int n, const std::string& out) {
  const std::uint64_t seed = 20261121;
  const auto gen = gen::targeted<Q>();
  rc::Random random = geomcheck::gen::sequence<Q>(seed);
  struct Row {
    double width;  // enclosure width / scale, log2
    int index;
    std::string mode, note;
    typename QueryTraits<Q>::Case c;
  };
  std::vector<Row> undecided;
  int tiny = 0;
  for (int i = 0; i < n; ++i) {
    const auto tc = gen(random.split(), 50).value();
    const auto& c = tc.first;
    if (!is_valid(c.a) || !is_valid(c.b)) continue;
    const oracle::ConvexShape a = oracle::make_shape(c.a), b = oracle::make_shape(c.b);
    // As the harness asks for the truth (properties/src/truth.cpp): no
    // certificates kept, the distance refined to 1e-20 * scale.
    oracle::EngineOptions opt;
    opt.certificates = false;
    opt.rel_width = 1e-20;
    const oracle::DistanceResult r = oracle::classify(a, b, opt);
    if (r.verdict != oracle::Verdict::Undecided) continue;
    const oracle::Q scale = oracle::pair_scale(a, b);
    const oracle::Q w = (r.distance.hi - r.distance.lo) / scale;
    const double lw = w == 0 ? -10000.0 : std::log2(oracle::to_double(w));
    if (w * oracle::Q(boost::multiprecision::mpz_int(1) << 200) <= 1) ++tiny;
    undecided.push_back({lw, i, tc.second, r.note, c});
  }
  std::sort(undecided.begin(), undecided.end(), [](const Row& x, const Row& y) { return x.width > y.width; });
  std::printf("%s: %d cases (seed %llu): %zu undecided (%.3f%%), %d of them within 2^-200 * scale; widest 2^%.1f * scale\n",
              info(Q).name, n, static_cast<unsigned long long>(seed), undecided.size(), 100.0 * undecided.size() / n, tiny,
              undecided.empty() ? 0.0 : undecided.front().width);
  for (std::size_t k = 0; k < undecided.size() && k < 5; ++k) {
    std::printf("  widest %zu: 2^%.1f * scale, case %d mode %s;%s\n", k, undecided[k].width, undecided[k].index,
                undecided[k].mode.c_str(), undecided[k].note.substr(0, 160).c_str());
    if (!out.empty()) {
      std::ofstream f(out + "/" + info(Q).name + "-widest-" + std::to_string(k) + ".case");
      f << write_case(from_case<Q>(undecided[k].c, "campaign seed=20261121 case=" + std::to_string(undecided[k].index) +
                                                        " mode=" + undecided[k].mode));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
  const std::string out = argc > 2 ? argv[2] : "";
  measure<QueryId::collide_cylinder_capsule>(n, out);
  measure<QueryId::collide_cylinder_obb>(n, out);
  measure<QueryId::collide_cylinder_triangle>(n, out);
  measure<QueryId::collide_cylinder_cylinder>(n, out);
}
