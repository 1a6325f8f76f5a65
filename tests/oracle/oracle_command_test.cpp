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

/// Runs fosssim-oracle; `grade` also gets the --allow-read arguments the test candidates need.
ChildOutcome oracle(std::vector<std::string> arguments) {
  if (!arguments.empty() && arguments[0] == "grade") {
    const auto extra = testing::allow_read_arguments();
    arguments.insert(arguments.begin() + 1, extra.begin(), extra.end());
  }
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

TEST(OracleCommand, OptionValuesAreCheckedBeforeAnyCandidateRuns) {
  TemporaryFolder out;
  const auto refused = [&](std::vector<std::string> extra, const std::string& named) {
    std::vector<std::string> arguments = {"grade", "-q", "--candidate", testing::kFossSim,
                                          testing::kAssets};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    const ChildOutcome run = oracle(arguments);
    EXPECT_EQ(run.exit_status, 2) << named << "\n" << run.stdout_tail << run.stderr_tail;
    EXPECT_NE(run.stderr_tail.find(named), std::string::npos) << run.stderr_tail;
    EXPECT_EQ(run.stdout_tail.find("CANNOT-RUN"), std::string::npos) << run.stdout_tail;
  };
  for (const char* value : {"nan", "inf", "-inf", "-1", "0", "1e9", "5s"}) {
    refused({"--timeout", value}, "--timeout");
  }
  for (const char* value : {"nan", "inf", "-2", "0"})
    refused({"--points-per-scene", value}, "--points-per-scene");
  for (const char* value : {"0", "-1", "100000"}) refused({"-j", value}, "--jobs");
  refused({"--max-processes", "0"}, "--max-processes");
  refused({"--max-memory", "-5"}, "--max-memory");
  // A missing work folder is the oracle's own error, not every scene's CANNOT-RUN.
  refused({"--work-dir", out / "no-such-folder"}, "--work-dir");
  refused({"--allow-read", out / "no-such-file"}, "--allow-read");
}

TEST(OracleCommand, PerSceneTimeoutsComeFromTheTimeoutsFile) {
  TemporaryFolder out;
  const std::string basics = std::string(testing::kAssets) + "/basics";
  // One scene gets 0.5 s from the file; the other keeps --timeout (1 s).
  testing::write_bytes(out / "timeouts.tsv",
                      "# per-scene time-outs\nbasics/spring_chain_explicit.xml 0.5\n");
  const ChildOutcome run =
      oracle({"grade", "-q", "--candidate", testing::candidate("hanging_candidate.sh"), "-j", "2",
              "--timeout", "1", "--timeouts", out / "timeouts.tsv", basics});
  EXPECT_EQ(run.exit_status, 1) << run.stdout_tail << run.stderr_tail;
  EXPECT_NE(run.stdout_tail.find("spring_chain_explicit.xml: TIMEOUT: the candidate did not "
                                 "finish within the timeout of 0.5 s"),
            std::string::npos)
      << run.stdout_tail;
  EXPECT_NE(run.stdout_tail.find("spring_chain_symplectic.xml: TIMEOUT: the candidate did not "
                                 "finish within the timeout of 1 s"),
            std::string::npos)
      << run.stdout_tail;
  // A scene that is not in the run is refused before any candidate runs, naming file and line.
  testing::write_bytes(out / "bad.tsv", "basics/spring_chain_explicit.xml 0.5\nbasics/none.xml 1\n");
  const ChildOutcome bad =
      oracle({"grade", "-q", "--candidate", testing::candidate("hanging_candidate.sh"),
              "--timeouts", out / "bad.tsv", basics});
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.stderr_tail.find(out / "bad.tsv" + ":2: no scene \"basics/none.xml\""),
            std::string::npos)
      << bad.stderr_tail;
}

TEST(OracleCommand, ReportsNeverReplaceAnInput) {
  TemporaryFolder out;
  std::filesystem::copy(testing::kAssets, out / "suite", std::filesystem::copy_options::recursive);
  const std::string scene = out / "suite/basics/spring_chain_explicit.xml";
  const std::string candidate = out / "candidate.sh";
  std::filesystem::copy_file(testing::candidate("crashing_candidate.sh"), candidate);
  const std::string scene_bytes = testing::read_bytes(scene);
  const std::string candidate_bytes = testing::read_bytes(candidate);
  const auto refused = [&](std::vector<std::string> reports, const std::string& named) {
    std::vector<std::string> arguments = {"grade", "-q", "--candidate", candidate, out / "suite"};
    arguments.insert(arguments.end(), reports.begin(), reports.end());
    const ChildOutcome run = oracle(arguments);
    EXPECT_EQ(run.exit_status, 2) << run.stdout_tail << run.stderr_tail;
    EXPECT_NE(run.stderr_tail.find(named), std::string::npos) << run.stderr_tail;
  };
  refused({"--junit", scene}, "is the input " + scene);
  refused({"--gradescope", candidate}, "is the input " + candidate);
  refused({"--shard-result", out / "suite/basics/../basics/spring_chain_symplectic.xml"},
          "--shard-result");
  testing::write_bytes(out / "report.xml", "old");
  refused({"--junit", out / "report.xml", "--gradescope", out / "./report.xml"}, "is also --junit");
  EXPECT_EQ(testing::read_bytes(scene), scene_bytes);
  EXPECT_EQ(testing::read_bytes(candidate), candidate_bytes);
  EXPECT_EQ(testing::read_bytes(out / "report.xml"), "old");
  // merge: the shard result files are its inputs.
  testing::write_bytes(out / "shard.json", "{}");
  const ChildOutcome merge = oracle({"merge", out / "shard.json", "--junit", out / "shard.json"});
  EXPECT_EQ(merge.exit_status, 2) << merge.stderr_tail;
  EXPECT_NE(merge.stderr_tail.find("is the input"), std::string::npos) << merge.stderr_tail;
  EXPECT_EQ(testing::read_bytes(out / "shard.json"), "{}");
}

TEST(OracleCommand, WithoutBubblewrapGradeRefusesUnlessToldNoSandbox) {
  TemporaryFolder empty;  // a $PATH in which bwrap is not found
  const auto grade = [&](std::vector<std::string> extra) {
    std::vector<std::string> arguments = {
        "/usr/bin/env", "PATH=" + empty.path(), testing::kOracle,  "grade",
        "-q",           "--candidate",          testing::kFossSim, testing::kAssets};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return testing::run_program(arguments);
  };
  const ChildOutcome refused = grade({});
  EXPECT_EQ(refused.exit_status, 2) << refused.stdout_tail << refused.stderr_tail;
  EXPECT_NE(refused.stderr_tail.find("bubblewrap (bwrap) is not installed"), std::string::npos)
      << refused.stderr_tail;
  EXPECT_NE(refused.stderr_tail.find("--no-sandbox"), std::string::npos) << refused.stderr_tail;
  EXPECT_EQ(refused.stdout_tail, "");  // no scene ran
  const ChildOutcome unconfined = grade({"--no-sandbox"});
  EXPECT_EQ(unconfined.exit_status, 0) << unconfined.stdout_tail << unconfined.stderr_tail;
  EXPECT_NE(unconfined.stdout_tail.find("Candidates ran without a sandbox (--no-sandbox)."),
            std::string::npos)
      << unconfined.stdout_tail;
}

TEST(OracleCommand, InterruptStopsTheRunningCandidateAndWritesNoReports) {
  TemporaryFolder out;
  // The sandboxed candidate writes only into its own folder under --work-dir, and its process
  // ids are those of its own namespace: it is found by its sleep's unique argument instead.
  const std::string token = "1000." + std::to_string(::getpid());
  testing::set_env("ORACLE_TEST_SLEEP", token);
  // Start a run on a hanging candidate, wait until the candidate is up, then press "Ctrl-C".
  const std::string script =
      "\"$0\" grade -q --candidate \"$1\" --work-dir \"$4\" --junit \"$2\" \"$3\" & oracle=$!; "
      "until [ -n \"$(find \"$4\" -name sleep.pid 2>/dev/null)\" ]; do sleep 0.02; done; "
      "kill -INT $oracle; wait $oracle; echo status $?";
  const ChildOutcome run = testing::run_program(
      {"/bin/sh", "-c", script, testing::kOracle, testing::candidate("hanging_candidate.sh"),
       out / "junit.xml", testing::kAssets, out.path()},
      60.0);
  EXPECT_EQ(run.stdout_tail, "status 130\n") << run.stderr_tail;
  EXPECT_NE(run.stderr_tail.find("interrupted; no reports written"), std::string::npos)
      << run.stderr_tail;
  EXPECT_FALSE(std::filesystem::exists(out / "junit.xml"));
  EXPECT_EQ(testing::wait_for_processes_to_end(token, 2.0), std::vector<int>{})
      << "the candidate's child survived the interrupt";
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
