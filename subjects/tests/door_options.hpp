// geomcheck — the door tests' options: a fixed seed (VerifyOptions'
// default), quiet, their files under the test's temporary folder.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "geomcheck/verify.hpp"

namespace geomcheck::testing {

/// `cases` cases, quiet, no summary, files under TempDir()/out (emptied).
inline VerifyOptions quiet_options(const std::string& out, int cases) {
  VerifyOptions opt;
  opt.cases = cases;
  opt.out = std::filesystem::path(::testing::TempDir()) / out;
  std::filesystem::remove_all(opt.out);
  opt.quiet = true;
  opt.summary = false;
  return opt;
}

/// The run failed, each failing case by `property` alone, and saved files.
inline void expect_caught_only_as(const VerifyResult& r, const std::string& property) {
  ASSERT_GT(r.failures, 0);
  EXPECT_EQ(r.by_property.size(), 1u);
  EXPECT_EQ(r.by_property.count(property), 1u);
  EXPECT_FALSE(r.saved.empty());
}

}  // namespace geomcheck::testing
