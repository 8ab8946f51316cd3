// geomcheck — teeth: the suite must catch each known-wrong variant within
// the CI budget (the fixed seed and max_success of ctest), with a shrunk
// counterexample saved as a case file.
#include <gtest/gtest.h>

#include <cctype>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "geomcheck/properties/spec.hpp"
#include "support.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {
namespace {

template <QueryId Q>
void expect_caught(const typename Spec<Q>::Impl& wrong) {
  const std::string name = std::string(info(Q).name) + ".teeth." + wrong.name;
  const PropertyRun r = run_property<Q>(
      name, Spec<Q>::targeted(), [&](const auto& c) { return check_all(c, wrong); },
      [&](const auto& c) { return Spec<Q>::hit(c, wrong); });
  ASSERT_FALSE(r.passed) << "the suite did not catch the known-wrong variant '" << wrong.name << "' in "
                         << r.cases << " cases";
  ASSERT_FALSE(r.case_file.empty()) << "no shrunk counterexample was saved";
  const ParseResult saved = load_case(r.case_file);
  ASSERT_TRUE(saved.ok()) << saved.error;
  // The shrunk counterexample must still show the variant wrong and production right.
  const auto c = to_case<Q>(saved.value);
  EXPECT_TRUE(check_all(c, wrong).has_value());
  EXPECT_FALSE(check_oracle(c).has_value());
  std::cout << "[teeth] " << wrong.name << " caught after " << r.cases << " cases; shrunk counterexample: "
            << r.case_file << "\n"
            << r.failure << "\n";
}

// Every known-wrong variant of every query's spec, a test each (named
// <query>__<variant>), so that a variant added to a spec is held to this.
struct Tooth {
  std::string name;
  std::function<void()> run;
};
std::vector<Tooth> all_teeth() {
  std::vector<Tooth> out;
  for_each_query([&](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    for (const auto* v : Spec<Q>::variants()) {
      std::string name = std::string(info(Q).name) + "__" + v->name;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      out.push_back({name, [v] { expect_caught<Q>(*v); }});
    }
  });
  return out;
}

class Caught : public ::testing::Test {
 public:
  explicit Caught(std::function<void()> run) : run_(std::move(run)) {}
  void TestBody() override { run_(); }

 private:
  std::function<void()> run_;
};

// Registered before main (as TEST does), one test per variant: teeth.<query>__<variant>.
const int kRegistered = [] {
  for (const Tooth& t : all_teeth())
    ::testing::RegisterTest("teeth", t.name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [run = t.run]() -> ::testing::Test* { return new Caught(run); });
  return 0;
}();

}  // namespace
}  // namespace geomcheck
