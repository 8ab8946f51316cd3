#include "support.hpp"

#include <rapidcheck/detail/TestListenerAdapter.h>

#include <filesystem>
#include <iostream>

namespace geomcheck {

void showValue(const Cylinder& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const Sphere& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const Segment& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const Capsule& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const Obb& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const Triangle& s, std::ostream& os) { os << describe_shape(s); }
void showValue(const MovingSphere& s, std::ostream& os) { os << describe_shape(s); }

rc::detail::TestListener& listener() {
  static rc::detail::TestListenerAdapter quiet;
  return quiet;
}

std::string save_counterexample(const CaseFile& f, const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(GEOMCHECK_BINARY_DIR) / "failures";
  std::error_code ec;
  fs::create_directories(dir, ec);
  std::string stem = name;
  for (char& ch : stem)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
  const fs::path path = dir / (stem + kCaseFileExtension);
  std::string err;
  if (!save_case(path, f, err)) {
    std::cerr << "could not save the counterexample: " << err << "\n";
    return {};
  }
  return path.string();
}

void expect_passed(const PropertyRun& run, const std::string& name, const PropertyOptions& opt) {
  const auto& config = rc::detail::configuration();
  std::cout << "[property] " << name << ": " << run.cases << " cases, " << run.hits << " hits"
            << " (seed " << config.testParams.seed << ")\n";
  if (!run.passed) {
    ADD_FAILURE() << name << " failed:\n"
                  << run.failure << "\nshrunk counterexample saved as " << run.case_file
                  << "\nreplay it:  " << GEOMCHECK_TOOL_PATH << " replay " << run.case_file
                  << "\nrerun it:   RC_PARAMS=\"seed=" << config.testParams.seed << "\" "
                  << ::testing::internal::GetArgvs()[0] << " --gtest_filter="
                  << ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() << "."
                  << ::testing::UnitTest::GetInstance()->current_test_info()->name() << "\n";
    return;
  }
  if (opt.check_rate && run.cases > 0) {
    const double rate = double(run.hits) / run.cases;
    EXPECT_GE(rate, opt.min_hit) << name << ": hit rate " << rate << " below " << opt.min_hit
                                 << " (the generator went blind)";
    EXPECT_LE(rate, opt.max_hit) << name << ": hit rate " << rate << " above " << opt.max_hit
                                 << " (the generator went blind)";
  }
}

}  // namespace geomcheck
