#include "result_table.h"

#include <gtest/gtest.h>

#include <sstream>

#include "report_samples.h"

namespace fosssim {
namespace {

TEST(ResultTable, ShowsEverySceneTheFailuresAndTheTotals) {
  std::ostringstream out;
  print_result_table(out, testing::sample_run());
  const std::string table = out.str();
  EXPECT_EQ(
      table.rfind("scene               integrator      verdict      max pos res  max vel res  "
                  "first failure        time s\n",
                  0),
      0u)
      << table;
  EXPECT_NE(
      table.find("\nassets/a/two.xml    explicit-euler  FAIL               1e-09          nan  "
                 "step 17, particle 2    0.38\n"),
      std::string::npos)
      << table;
  EXPECT_NE(
      table.find("\nassets/b/four.xml   -               SCENE-ERROR            -            -  -"),
      std::string::npos)
      << table;
  EXPECT_LT(table.find("-- extra credit --"), table.find("extra/c/five.xml"));
  EXPECT_NE(table.find("  assets/b/three.xml: CRASH: exploded <at> step"), std::string::npos);
  EXPECT_NE(table.find("    stderr| line <two> & \\x07"), std::string::npos) << table;
  EXPECT_NE(
      table.find("Regular scenes: 1 of 4 passed; extra credit: 1 of 2 passed. Wall time 2.60 s."),
      std::string::npos)
      << table;
  for (unsigned char c : table) EXPECT_TRUE(c >= 0x20 || c == '\n');
}

TEST(ResultTable, AThemeThreeFailureNamesTheBody) {
  GradingRun run = testing::sample_run();
  for (SceneResult& r : run.results) {
    if (r.first_divergence) r.first_divergence->rigid_body = true;
  }
  std::ostringstream out;
  print_result_table(out, run);
  // The table's cell (the failures' reasons below it are the grader's own text).
  EXPECT_NE(out.str().find("  step 17, body 2  "), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("  step 17, particle 2  "), std::string::npos) << out.str();
}

TEST(ResultTable, ProgressLineCountsScenes) {
  const SceneResult r = testing::sample_result("assets/a/one.xml", Verdict::kPassed);
  EXPECT_EQ(progress_line(r, 3, 12), "[ 3/12] PASS        assets/a/one.xml  (0.38 s)");
}

}  // namespace
}  // namespace fosssim
