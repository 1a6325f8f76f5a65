#include "gradescope_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report_samples.h"

namespace fosssim {
namespace {

using nlohmann::json;

TEST(GradescopeReport, ScoresRegularScenesAndExtraCreditApart) {
  GradescopeOptions options;
  options.points_per_scene = 2.0;
  options.visibility = "after_due_date";
  const json results = json::parse(gradescope_json(testing::sample_run(), options));
  // One regular pass and one extra-credit pass, two points each.
  EXPECT_EQ(results.at("score").get<double>(), 4.0);
  EXPECT_EQ(results.at("execution_time").get<int>(), 3);
  EXPECT_EQ(results.at("visibility"), "after_due_date");
  const json& tests = results.at("tests");
  ASSERT_EQ(tests.size(), 6u);
  double regular_max = 0.0, sum = 0.0;
  for (const json& test : tests) {
    sum += test.at("score").get<double>();
    if (test.at("tags")[0] == "regular") regular_max += test.at("max_score").get<double>();
    EXPECT_EQ(test.at("visibility"), "after_due_date");
  }
  EXPECT_EQ(regular_max, 8.0);  // four regular scenes
  EXPECT_EQ(sum, results.at("score").get<double>());
  EXPECT_EQ(tests[0].at("name"), "assets/a/one.xml");
  EXPECT_EQ(tests[0].at("status"), "passed");
  EXPECT_EQ(tests[1].at("status"), "failed");
  EXPECT_EQ(tests[1].at("score").get<double>(), 0.0);
  EXPECT_EQ(tests[4].at("name"), "Extra credit: extra/c/five.xml");
  EXPECT_EQ(tests[4].at("max_score").get<double>(), 0.0);
  EXPECT_EQ(tests[4].at("score").get<double>(), 2.0);
  EXPECT_EQ(tests[4].at("status"), "passed");
  EXPECT_EQ(tests[5].at("status"), "failed");  // max_score 0: the status says it failed
  EXPECT_EQ(tests[5].at("tags")[0], "extra-credit");
  EXPECT_NE(results.at("output").get<std::string>().find("Regular scenes: 1 of 4 passed"),
            std::string::npos);
  EXPECT_NE(results.at("output").get<std::string>().find("Extra credit: 1 of 2 passed"),
            std::string::npos);
}

TEST(GradescopeReport, OutputExplainsFailuresAndExtraDataKeepsResiduals) {
  const json results = json::parse(gradescope_json(testing::sample_run()));
  const json& failed = results.at("tests")[1];
  EXPECT_NE(failed.at("output").get<std::string>().find("First divergence at step 17"),
            std::string::npos);
  EXPECT_EQ(failed.at("extra_data").at("verdict"), "failed");
  EXPECT_EQ(failed.at("extra_data").at("first_divergence_step"), 17);
  EXPECT_EQ(failed.at("extra_data").at("first_divergence_particle"), 2);
  EXPECT_EQ(failed.at("extra_data").at("max_position_residual").get<double>(), 1e-9);
  EXPECT_EQ(failed.at("extra_data").at("max_velocity_residual"), "nan");  // JSON has no NaN
  const json& crashed = results.at("tests")[2];
  const std::string output = crashed.at("output").get<std::string>();
  EXPECT_NE(output.find("exploded <at> step & \"quoted\" 'single' \xce\xbb\\x01\\xff"),
            std::string::npos);
  EXPECT_NE(output.find("line <two> & \\x07"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
