#include "shard_result_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "gradescope_report.h"
#include "junit_report.h"
#include "printable_text.h"
#include "report_samples.h"
#include "result_table.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

TEST(ShardResultFile, RoundTripsEveryFieldBitForBit) {
  GradingRun run = testing::sample_run();
  run.results[1].residuals->accumulated_position = 0.1 + 0.2;  // not a short decimal
  run.results[1].residuals->accumulated_velocity = -HUGE_VAL;
  ASSERT_TRUE(run.results[1].first_divergence);
  run.results[1].first_divergence->rigid_body = true;  // a Theme 3 scene's body
  auto parsed = parse_shard_result(shard_result_json(run), "test");
  EXPECT_EQ(parsed.candidate, run.candidate);
  EXPECT_EQ(parsed.scenes, run.scenes);
  ASSERT_EQ(parsed.results.size(), run.results.size());
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    const SceneResult& a = run.results[k];
    const SceneResult& b = parsed.results[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.verdict, b.verdict);
    EXPECT_EQ(printable_text(a.reason), b.reason);  // texts are stored printable
    EXPECT_EQ(printable_text(a.stderr_tail), b.stderr_tail);
    EXPECT_EQ(a.details, b.details);
    EXPECT_EQ(a.extra_credit, b.extra_credit);
    EXPECT_EQ(a.residuals.has_value(), b.residuals.has_value());
    if (a.residuals) {
      EXPECT_TRUE(same_bits(a.residuals->accumulated_position, b.residuals->accumulated_position));
      EXPECT_TRUE(same_bits(a.residuals->accumulated_velocity, b.residuals->accumulated_velocity));
      EXPECT_TRUE(same_bits(a.residuals->max_position, b.residuals->max_position));
      EXPECT_EQ(std::isnan(a.residuals->max_velocity), std::isnan(b.residuals->max_velocity));
    }
    EXPECT_EQ(a.first_divergence.has_value(), b.first_divergence.has_value());
    if (a.first_divergence && b.first_divergence) {
      EXPECT_EQ(a.first_divergence->particle, b.first_divergence->particle);
      EXPECT_EQ(a.first_divergence->rigid_body, b.first_divergence->rigid_body);
    }
  }
  // The reports written from the parsed run are the same bytes.
  EXPECT_EQ(junit_xml(parsed), junit_xml(run));
  EXPECT_EQ(gradescope_json(parsed), gradescope_json(run));
}

TEST(ShardResultFile, RejectsOtherFiles) {
  EXPECT_THROW(parse_shard_result("not json", "x"), Error);
  EXPECT_THROW(parse_shard_result("{\"tests\": []}", "x"), Error);
  const Error wrong_error = thrown_by<Error>([&] {
    parse_shard_result("{\"format\": \"fosssim-oracle-results\", \"version\": 99}", "x.json");
  });
  EXPECT_NE(std::string(wrong_error.what()).find("version 99"), std::string::npos);
}

/// Splits a run into its shards the way `grade --shard K/N` selects scenes.
std::vector<GradingRun> split(const GradingRun& whole, int count) {
  std::vector<GradingRun> shards;
  for (int k = 1; k <= count; ++k) {
    GradingRun shard = whole;
    shard.shard = Shard{k, count};
    shard.results.clear();
    for (std::size_t i = 0; i < whole.results.size(); ++i) {
      if (shard.shard.contains(i)) shard.results.push_back(whole.results[i]);
    }
    shards.push_back(shard);
  }
  return shards;
}

TEST(ShardResultFile, ARunWithoutTheSandboxSaysSoInEveryReportAndThroughAMerge) {
  GradingRun run = testing::sample_run();
  EXPECT_EQ(junit_xml(run).find("--no-sandbox"), std::string::npos);
  run.sandboxed = false;
  const GradingRun parsed = parse_shard_result(shard_result_json(run), "test");
  EXPECT_FALSE(parsed.sandboxed);
  EXPECT_NE(junit_xml(parsed).find(R"x(<property name="sandbox" value="none (--no-sandbox)"/>)x"),
            std::string::npos);
  EXPECT_NE(gradescope_json(parsed).find(kNoSandboxNote), std::string::npos);
  std::ostringstream table;
  print_result_table(table, parsed);
  EXPECT_NE(table.str().find(kNoSandboxNote), std::string::npos);
  // One shard without the sandbox makes the merged run one without it.
  GradingRun whole = testing::sample_run();
  std::vector<GradingRun> shards = split(whole, 2);
  EXPECT_TRUE(merge_shards(shards, {"a", "b"}).sandboxed);
  shards[1].sandboxed = false;
  EXPECT_FALSE(merge_shards(shards, {"a", "b"}).sandboxed);
}

TEST(MergeShards, GivesTheWholeRunsReportsWhateverTheShardOrder) {
  const GradingRun whole = testing::sample_run();
  std::vector<GradingRun> shards = split(whole, 4);
  std::swap(shards[0], shards[3]);
  auto merged = merge_shards(shards, {"a", "b", "c", "d"});
  ASSERT_EQ(merged.results.size(), whole.results.size());
  for (std::size_t k = 0; k < whole.results.size(); ++k) {
    EXPECT_EQ(merged.results[k].name, whole.results[k].name);
  }
  GradingRun timeless = merged;
  timeless.wall_seconds = whole.wall_seconds;
  EXPECT_EQ(junit_xml(timeless), junit_xml(whole));
  EXPECT_EQ(gradescope_json(timeless), gradescope_json(whole));
}

TEST(MergeShards, RefusesIncompleteDuplicatedOrForeignShards) {
  const GradingRun whole = testing::sample_run();
  std::vector<GradingRun> shards = split(whole, 3);
  const Error missing_error = thrown_by<Error>([&] {
    merge_shards({shards[0], shards[2]}, {"a", "c"});
  });
  EXPECT_NE(std::string(missing_error.what()).find("2/3 are missing"), std::string::npos)
      << missing_error.what();
  const Error twice_error = thrown_by<Error>([&] {
    merge_shards({shards[0], shards[1], shards[1], shards[2]}, {"a", "b", "b2", "c"});
  });
  EXPECT_NE(std::string(twice_error.what()).find("given twice"), std::string::npos);
  GradingRun foreign = shards[2];
  foreign.scenes.pop_back();
  const Error other_error = thrown_by<Error>([&] {
    merge_shards({shards[0], shards[1], foreign}, {"a", "b", "c"});
  });
  EXPECT_NE(std::string(other_error.what()).find("lists other scenes"), std::string::npos);
  GradingRun wrong_count = shards[2];
  wrong_count.shard = Shard{3, 4};
  EXPECT_THROW(merge_shards({shards[0], shards[1], wrong_count}, {"a", "b", "c"}), Error);
  GradingRun lost = shards[1];
  lost.results.pop_back();
  const Error incomplete_error = thrown_by<Error>([&] {
    merge_shards({shards[0], lost, shards[2]}, {"a", "b", "c"});
  });
  EXPECT_NE(std::string(incomplete_error.what()).find("does not hold the result"),
            std::string::npos);
}

}  // namespace
}  // namespace fosssim
