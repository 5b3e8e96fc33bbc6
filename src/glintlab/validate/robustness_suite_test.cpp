#include "glintlab/validate/robustness_suite.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

// The reduced robustness suite (1e5 values shared by weight; the CLI's runs
// 1e7), one test per model so that ctest runs them in parallel: the model
// gets its share of the evaluations, none is NaN, Inf or negative (the first
// offending inputs are printed), and only the explicit model refuses inputs
// (footprints holding more facets than its max_facets_per_footprint: its
// documented budget). wang2020 refused roughness 0.02 (the float 0.0199999996
// against a double bound) before the fix in wang2020_shading.cpp / _dpf.cpp.
class RobustnessSuiteModel : public ::testing::TestWithParam<const char*> {};

TEST_P(RobustnessSuiteModel, EvaluatesFiniteNonNegativeValues) {
    RobustnessSuiteOptions o;
    o.evaluations = 100'000;
    o.seed = 5;
    o.reduced = true;
    o.models = {GetParam()};
    const std::vector<RobustnessModelResult> results = run_robustness(o);
    ASSERT_EQ(results.size(), 1u);
    const RobustnessModelResult& r = results[0];
    EXPECT_GE(r.evaluations, 64) << r.model;
    EXPECT_EQ(r.bad_values, 0) << r.model << ": " << r.first_bad;
    if (r.model != "explicit") {
        EXPECT_EQ(r.refused, 0) << r.model << ": " << r.first_refusal;
    }
    EXPECT_LT(r.refused, r.evaluations / 2) << r.model;
}

INSTANTIATE_TEST_SUITE_P(Models, RobustnessSuiteModel,
                         ::testing::Values("smooth", "deliot2023", "zirr2016", "chermain2020",
                                           "kneiphof2025", "jakob2014", "explicit", "wang2020"));

// The report follows the suite contract: one `<model>_bad_values == 0` check
// per model, and the per-model counts in "models".
TEST(RobustnessSuite, ReportHasOneCheckPerModel) {
    RobustnessSuiteOptions o;
    o.evaluations = 2000;
    o.models = {"smooth", "deliot2023"};
    const ValidationReport r = validate_robustness(o);
    EXPECT_EQ(r.suite, "robustness");
    ASSERT_EQ(r.checks.size(), 2u);
    EXPECT_EQ(r.checks[0].name, "smooth_bad_values");
    EXPECT_EQ(r.checks[1].name, "deliot2023_bad_values");
    EXPECT_TRUE(r.passed());
    const nlohmann::json j = r.to_json();
    ASSERT_EQ(j.at("models").size(), 2u);
    EXPECT_GE(j.at("models")[0].at("evaluations").get<int64_t>(), 64);
}

// `validate robustness --models`: a model run alone gets the evaluations and
// draws it gets among others (its share by weight of the whole suite, the
// same seed), so per-model runs add up to the full suite; an unknown name is
// an error listing the models.
TEST(RobustnessSuite, AModelAloneGetsItsShareOfTheWholeSuite) {
    RobustnessSuiteOptions both;
    both.evaluations = 20'000;
    both.seed = 3;
    both.models = {"smooth", "zirr2016"};
    const std::vector<RobustnessModelResult> together = run_robustness(both);
    ASSERT_EQ(together.size(), 2u);
    RobustnessSuiteOptions alone = both;
    alone.models = {"zirr2016"};
    const std::vector<RobustnessModelResult> single = run_robustness(alone);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_EQ(single[0].model, "zirr2016");
    EXPECT_EQ(single[0].evaluations, together[1].evaluations);
    EXPECT_EQ(single[0].bad_values, together[1].bad_values);
    EXPECT_EQ(single[0].refused, together[1].refused);

    alone.models = {"zirr2017"};
    try {
        run_robustness(alone);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("\"zirr2017\""), std::string::npos) << m;
        EXPECT_NE(m.find("zirr2016"), std::string::npos) << m;
    }
}

}  // namespace
}  // namespace glintlab
