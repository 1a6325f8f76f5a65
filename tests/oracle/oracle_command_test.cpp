// The fosssim-oracle executable end to end: grading the test suite, sharding and merging,
// diagnosis files, exit statuses and the manifest commands.

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;

ChildOutcome oracle(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), testing::kOracle);
  return testing::run_program(arguments);
}

/// The report without its timings, which differ from run to run.
std::string without_times(const std::string& report) {
  static const std::regex xml_time(" time=\"[0-9.]+\"");
  static const std::regex json_time("\"execution_time\": [0-9]+");
  return std::regex_replace(std::regex_replace(report, xml_time, ""), json_time, "");
}

TEST(OracleCommand, GradesTheSuiteAndWritesBothReports) {
  TemporaryFolder out;
  const ChildOutcome run =
      oracle({"grade", "--candidate", testing::kFossSim, "-j", "2", testing::kAssets,
              "--extra-credit", testing::kExtraCredit, "--junit", out / "reports/junit.xml",
              "--gradescope", out / "reports/results.json"});
  EXPECT_EQ(run.exit_status, 0) << run.stdout_tail << run.stderr_tail;
  EXPECT_NE(run.stdout_tail.find("assets/implicit/orbit_implicit.xml"), std::string::npos);
  EXPECT_NE(run.stdout_tail.find("Regular scenes: 4 of 4 passed; extra credit: 1 of 1 passed."),
            std::string::npos)
      << run.stdout_tail;
  EXPECT_NE(run.stderr_tail.find("[5/5] PASS"), std::string::npos) << run.stderr_tail;
  tinyxml2::XMLDocument junit;
  ASSERT_EQ(junit.LoadFile((out / "reports/junit.xml").c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_EQ(junit.RootElement()->IntAttribute("tests"), 5);
  const auto results = nlohmann::json::parse(testing::read_bytes(out / "reports/results.json"));
  EXPECT_EQ(results.at("score").get<double>(), 5.0);
  EXPECT_FALSE(std::filesystem::exists(out / "reports/junit.xml.partial"));
}

TEST(OracleCommand, MergedShardsGiveTheSameReportsAsOneRun) {
  TemporaryFolder out;
  testing::use_perturbing_candidate(17, 2, 0, "1e-9");
  const std::string candidate = testing::candidate("perturbing_candidate.sh");
  const std::vector<std::string> suite = {testing::kAssets, "--extra-credit",
                                          testing::kExtraCredit};
  auto grade = [&](std::vector<std::string> extra) {
    std::vector<std::string> arguments = {"grade", "-q", "--candidate", candidate};
    arguments.insert(arguments.end(), suite.begin(), suite.end());
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return oracle(arguments);
  };
  const ChildOutcome whole =
      grade({"-j", "2", "--junit", out / "whole.xml", "--gradescope", out / "whole.json"});
  EXPECT_EQ(whole.exit_status, 1) << whole.stderr_tail;  // the perturbed scenes fail
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    const std::string name = std::string("shard") + shard[0] + ".json";
    const ChildOutcome part = grade({"--shard", shard, "--shard-result", out / name});
    EXPECT_NE(part.exit_status, 2) << part.stderr_tail;
  }
  const ChildOutcome merged =
      oracle({"merge", out / "shard3.json", out / "shard1.json", out / "shard2.json", "--junit",
              out / "merged.xml", "--gradescope", out / "merged.json"});
  EXPECT_EQ(merged.exit_status, 1) << merged.stderr_tail;
  EXPECT_EQ(without_times(testing::read_bytes(out / "merged.xml")),
            without_times(testing::read_bytes(out / "whole.xml")));
  EXPECT_EQ(without_times(testing::read_bytes(out / "merged.json")),
            without_times(testing::read_bytes(out / "whole.json")));
  // The perturbed explicit chain fails at the perturbed step in the merged reports too.
  EXPECT_NE(testing::read_bytes(out / "merged.xml").find("first divergence at step 17, particle 2"),
            std::string::npos);
  // A missing shard is refused.
  const ChildOutcome incomplete = oracle({"merge", out / "shard1.json", out / "shard3.json"});
  EXPECT_EQ(incomplete.exit_status, 2);
  EXPECT_NE(incomplete.stderr_tail.find("the shards 2/3 are missing"), std::string::npos);
}

TEST(OracleCommand, DiagnosesAFailingSceneInItsFolder) {
  TemporaryFolder out;
  testing::use_perturbing_candidate(17, 2, 0, "1e-9");
  const ChildOutcome run =
      oracle({"grade", "-q", "--candidate", testing::candidate("perturbing_candidate.sh"),
              testing::kChainScene, "--diagnose-dir", out / "diagnosis"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.stdout_tail.find("FAIL"), std::string::npos);
  EXPECT_NE(run.stdout_tail.find("step 17, particle 2"), std::string::npos) << run.stdout_tail;
  for (const char* suffix : {".diagnosis.txt", ".residuals.tsv", ".residuals.svg"}) {
    EXPECT_TRUE(
        std::filesystem::exists(out / (std::string("diagnosis/spring_chain_explicit") + suffix)))
        << suffix;
  }
  // What the files say: the first divergence, the per-step table around it and the plot.
  const std::string stem = out / "diagnosis/spring_chain_explicit";
  const std::string text = testing::read_bytes(stem + ".diagnosis.txt");
  EXPECT_NE(text.find("First divergence at step 17, particle 2: position residual 1.0000000"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("file frame 17:"), std::string::npos) << text;
  const std::string table = testing::read_bytes(stem + ".residuals.tsv");
  const auto intact = testing::tsv_row(table, "16");
  ASSERT_EQ(intact.size(), 8u) << table;
  EXPECT_EQ(intact[2], "0");  // step 16 is still exact
  const auto failing = testing::tsv_row(table, "17");
  ASSERT_EQ(failing.size(), 8u) << table;
  EXPECT_NEAR(std::stod(failing[2]), 1e-9, 1e-15);         // max position residual
  EXPECT_EQ(failing[3], "2");                              // at particle 2
  EXPECT_EQ(failing[4], "0");                              // the velocity of frame 17 is intact
  testing::expect_residual_plot(stem + ".residuals.svg");  // marked at step 17
}

TEST(OracleCommand, ExitStatusesForBadInput) {
  EXPECT_EQ(oracle({"grade", "--candidate", testing::kFossSim, "--shard", "3/2", testing::kAssets})
                .exit_status,
            2);
  EXPECT_EQ(oracle({"grade", "--candidate", testing::kFossSim, "/no/such/folder"}).exit_status, 2);
  EXPECT_EQ(oracle({"grade", testing::kAssets}).exit_status, 2);  // --candidate is required
  EXPECT_EQ(oracle({"nonsense"}).exit_status, 2);
  EXPECT_EQ(oracle({"--help"}).exit_status, 0);
  // A candidate that is not there fails every scene, but the run completes and reports.
  TemporaryFolder out;
  const ChildOutcome missing = oracle({"grade", "-q", "--candidate", out / "nothing",
                                       testing::kAssets, "--junit", out / "junit.xml"});
  EXPECT_EQ(missing.exit_status, 1);
  EXPECT_NE(missing.stdout_tail.find("CANNOT-RUN"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out / "junit.xml"));
}

TEST(OracleCommand, InterruptStopsTheRunningCandidateAndWritesNoReports) {
  TemporaryFolder out;
  const std::string pid_file = out / "sleep.pid";
  testing::set_env("ORACLE_TEST_PID_FILE", pid_file);
  // Start a run on a hanging candidate, wait until the candidate is up, then press "Ctrl-C".
  const std::string script =
      "\"$0\" grade -q --candidate \"$1\" --junit \"$2\" \"$3\" & oracle=$!; "
      "while [ ! -s \"$4\" ]; do sleep 0.02; done; kill -INT $oracle; wait $oracle; echo status $?";
  const ChildOutcome run = testing::run_program(
      {"/bin/sh", "-c", script, testing::kOracle, testing::candidate("hanging_candidate.sh"),
       out / "junit.xml", testing::kAssets, pid_file},
      60.0);
  EXPECT_EQ(run.stdout_tail, "status 130\n") << run.stderr_tail;
  EXPECT_NE(run.stderr_tail.find("interrupted; no reports written"), std::string::npos)
      << run.stderr_tail;
  EXPECT_FALSE(std::filesystem::exists(out / "junit.xml"));
  int sleeper = 0;
  std::ifstream(pid_file) >> sleeper;
  ASSERT_GT(sleeper, 0);
  const std::string proc = "/proc/" + std::to_string(sleeper) + "/stat";
  std::string state;
  for (int k = 0; k < 100; ++k) {
    std::ifstream stat(proc);
    std::string pid_text, command;
    state.clear();
    if (!(stat >> pid_text >> command >> state) || state == "Z") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(state.empty() || state == "Z") << "the candidate's child survived the interrupt";
}

TEST(OracleCommand, ManifestUpdateThenCheckAndADetectedChange) {
  TemporaryFolder out;
  const std::string manifest = out / "manifest";
  const ChildOutcome update =
      oracle({"manifest", "update", "--candidate", testing::kFossSim, "--manifest", manifest,
              testing::kAssets, testing::kExtraCredit, out / "absent"});
  ASSERT_EQ(update.exit_status, 0) << update.stderr_tail;
  const ChildOutcome check =
      oracle({"manifest", "check", "--candidate", testing::kFossSim, "--manifest", manifest, "-j",
              "2", testing::kAssets, testing::kExtraCredit});
  EXPECT_EQ(check.exit_status, 0) << check.stdout_tail;
  EXPECT_NE(check.stdout_tail.find("All 5 scenes match"), std::string::npos);
  // Checking only some folders reports the others' entries as gone.
  const ChildOutcome partial = oracle({"manifest", "check", "--candidate", testing::kFossSim,
                                       "--manifest", manifest, testing::kAssets});
  EXPECT_EQ(partial.exit_status, 1);
  EXPECT_NE(
      partial.stdout_tail.find("extracreditassets/vortex/vortex_symplectic.xml: in the manifest"),
      std::string::npos)
      << partial.stdout_tail;
  // A trajectory that changes by one bit while the manifest does not fails the check.
  testing::use_perturbing_candidate(5, 0, 3, "flip-bit");
  const ChildOutcome changed =
      oracle({"manifest", "check", "--candidate", testing::candidate("perturbing_candidate.sh"),
              "--manifest", manifest, testing::kAssets, testing::kExtraCredit});
  EXPECT_EQ(changed.exit_status, 1);
  EXPECT_NE(changed.stdout_tail.find("the trajectory changed"), std::string::npos)
      << changed.stdout_tail;
  EXPECT_NE(changed.stdout_tail.find("cmake --build --preset release --target oracle-manifest"),
            std::string::npos);
}

}  // namespace
}  // namespace fosssim
