// geomcheck — running a check function as a RapidCheck property.
//
// run_property() runs a property with the configuration from RC_PARAMS
// (ctest sets a fixed seed; the seed is printed), classifies every case
// (hit/miss and the generator's mode), fails when the hit rate leaves
// [min_hit, max_hit], and on failure saves the shrunk counterexample as a
// case file and prints the exact commands that replay it.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <functional>
#include <optional>
#include <sstream>
#include <ostream>
#include <string>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

// RapidCheck prints counterexamples with these (the form case_from_rapidcheck_text reads).
void showValue(const Cylinder& s, std::ostream& os);
void showValue(const Sphere& s, std::ostream& os);
void showValue(const Segment& s, std::ostream& os);
void showValue(const Capsule& s, std::ostream& os);
void showValue(const Obb& s, std::ostream& os);
void showValue(const Triangle& s, std::ostream& os);
void showValue(const MovingSphere& s, std::ostream& os);
template <class A, class B, QueryId Q>
void showValue(const PairCase<A, B, Q>& c, std::ostream& os) {
  showValue(c.a, os);
  os << ", ";
  showValue(c.b, os);
}

/// Outcome of one property run.
struct PropertyRun {
  bool passed = false;
  int cases = 0;
  int hits = 0;
  std::string failure;       ///< RapidCheck's failure description
  std::string case_file;     ///< where the shrunk counterexample was saved
};

struct PropertyOptions {
  double min_hit = 0.20;
  double max_hit = 0.80;
  bool check_rate = true;
};

/// A listener that prints nothing (results are reported by run_property).
rc::detail::TestListener& listener();

/// Saves a counterexample under <build>/failures/ and returns the path.
std::string save_counterexample(const CaseFile& f, const std::string& name);

/// Runs `check` over `gen` as a RapidCheck property named `name`.
template <QueryId Q>
PropertyRun run_property(const std::string& name,
                         const rc::Gen<std::pair<typename QueryTraits<Q>::Case, std::string>>& gen,
                         const std::function<CheckResult(const typename QueryTraits<Q>::Case&)>& check,
                         const std::function<bool(const typename QueryTraits<Q>::Case&)>& hit_of) {
  using Case = typename QueryTraits<Q>::Case;
  std::optional<Case> last_failing;
  int seen = 0, seen_hits = 0;  // passing runs do not shrink, so these count the cases
  auto prop = [&] {
    const auto drawn = *gen;
    const Case& c = drawn.first;
    const bool hit = hit_of(c);
    ++seen;
    seen_hits += hit;
    RC_TAG(hit ? "hit" : "miss", drawn.second);
    const CheckResult f = check(c);
    if (f) {
      last_failing = c;  // the last failure seen is the final shrunk counterexample
      RC_FAIL(f->property + ": " + f->detail);
    }
  };
  rc::detail::TestMetadata meta;
  meta.id = name;
  meta.description = name;
  const auto& config = rc::detail::configuration();
  const auto result = rc::detail::checkTestable(prop, meta, config.testParams, listener(), config.reproduce);
  PropertyRun run;
  rc::detail::SuccessResult success;
  rc::detail::FailureResult failure;
  if (result.match(success)) {
    run.passed = true;
    run.cases = seen;
    run.hits = seen_hits;
  } else {
    std::ostringstream os;
    rc::detail::printResultMessage(result, os);
    run.failure = os.str();
    if (result.match(failure)) run.cases = failure.numSuccess + 1;
    if (last_failing) {
      run.case_file = save_counterexample(
          from_case<Q>(*last_failing, "rapidcheck property " + name + " RC_PARAMS=\"seed=" + std::to_string(config.testParams.seed) + "\"", "",
                       run.failure.substr(0, 400)),
          name);
    }
  }
  return run;
}

/// gtest assertions for a run of production: passed, and hit rate in range.
void expect_passed(const PropertyRun& run, const std::string& name, const PropertyOptions& opt = {});

}  // namespace geomcheck
