// geomcheck — the tail of depth / certified penetration depth of a consistent contact
// (a query whose depth is the overlap along its normal, an upper bound) over the first N
// cases of the campaign's generator mix (the main job's seed), with the worst cases by mode
// and as case files.
//
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/depth_tail.
//   ./depth_tail 20000 [out_dir]   (writes out_dir/worst-K.case for the ten worst)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/generators.hpp"

using namespace geomcheck;

int main(int argc, char** argv) {
  constexpr QueryId Q = QueryId::collide_cylinder_cylinder;
  const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
  const std::string out = argc > 2 ? argv[2] : "";
  const std::uint64_t seed = 20261121;
  const auto gen = gen::targeted<Q>();
  rc::Random random = geomcheck::gen::sequence<Q>(seed);
  struct Row {
    double ratio;
    int index;
    std::string mode;
    QueryTraits<Q>::Case c;
  };
  std::vector<Row> rows;
  std::map<std::string, std::pair<int, int>> by_mode;  // ratio > 1.5, measured
  for (int i = 0; i < n; ++i) {
    const auto tc = gen(random.split(), 50).value();
    const Evaluation e = evaluate(tc.first);
    if (!(e.depth_ratio == e.depth_ratio)) continue;
    rows.push_back({e.depth_ratio, i, tc.second, tc.first});
    auto& m = by_mode[tc.second];
    ++m.second;
    if (e.depth_ratio > 1.5) ++m.first;
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.ratio > b.ratio; });
  std::vector<double> r;
  for (const Row& w : rows) r.push_back(w.ratio);
  std::sort(r.begin(), r.end());
  auto pct = [&](double p) { return r.empty() ? 0.0 : r[std::min(r.size() - 1, static_cast<std::size_t>(p * r.size()))]; };
  std::printf("%s: %d cases (seed %llu), %zu with a measured ratio: p50 %.4f p90 %.4f p99 %.4f max %.4g\n", info(Q).name,
              n, static_cast<unsigned long long>(seed), r.size(), pct(0.5), pct(0.9), pct(0.99), r.empty() ? 0.0 : r.back());
  for (const auto& [mode, m] : by_mode)
    if (m.first) std::printf("  mode %-28s ratio > 1.5: %d of %d\n", mode.c_str(), m.first, m.second);
  for (std::size_t k = 0; k < rows.size() && k < 10; ++k) {
    std::printf("  worst %zu: ratio %.4g case %d mode %s\n", k, rows[k].ratio, rows[k].index, rows[k].mode.c_str());
    if (!out.empty()) {
      std::ofstream f(out + "/worst-" + std::to_string(k) + ".case");
      f << write_case(from_case<Q>(rows[k].c, "campaign seed=20261121 case=" + std::to_string(rows[k].index) + " mode=" + rows[k].mode));
    }
  }
}
