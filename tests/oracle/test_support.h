#pragma once
// Shared helpers of the oracle's tests: where things are, temporary folders, trajectories.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"

namespace fosssim::testing {

inline const std::string kFossSim = FOSSSIM_EXE;
inline const std::string kOracle = ORACLE_EXE;
inline const std::string kPerturbTool = PERTURB_EXE;
inline const std::string kData = ORACLE_TEST_DATA;
inline const std::string kCandidates = ORACLE_TEST_CANDIDATES;

/// The test scenes: four regular ones in two folders and one extra-credit scene.
inline const std::string kAssets = kData + "/assets";
inline const std::string kExtraCredit = kData + "/extracreditassets";
inline const std::string kChainScene = kAssets + "/basics/spring_chain_explicit.xml";

inline std::string candidate(const std::string& script) { return kCandidates + "/" + script; }

/// A fresh temporary folder for one test, removed afterwards.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "oracle-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The tab-separated fields of the line of `table` whose first field is `key`; empty if none.
inline std::vector<std::string> tsv_row(const std::string& table, const std::string& key) {
  std::istringstream lines(table);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, '\t');) fields.push_back(cell);
    if (!fields.empty() && fields[0] == key) return fields;
  }
  return {};
}

/// Runs a program and returns its outcome, keeping up to 1 MiB of each output stream.
inline ChildOutcome run_program(const std::vector<std::string>& argv, double timeout = 120.0) {
  ChildLimits limits;
  limits.timeout_seconds = timeout;
  limits.tail_bytes = 1 << 20;
  return run_child(argv, std::filesystem::current_path().string(), limits);
}

/// FOSSSim's own trajectory of `scene`, as bytes.
inline std::string fosssim_trajectory(const std::string& scene, const TemporaryFolder& folder) {
  const std::string out = folder / "reference.bin";
  const ChildOutcome outcome = run_program({kFossSim, "-s", scene, "-d", "0", "-q", "-o", out});
  EXPECT_EQ(outcome.ending, ChildEnding::kExited);
  EXPECT_EQ(outcome.exit_status, 0) << outcome.stderr_tail;
  return read_bytes(out);
}

/// Sets an environment variable for the candidates this test starts (each test runs in a
/// process of its own under ctest).
inline void set_env(const char* name, const std::string& value) {
  ::setenv(name, value.c_str(), 1);
}

/// Configures candidates/perturbing_candidate.sh: FOSSSim's trajectory with `change` ("1e-9",
/// or "flip-bit") applied to frame `frame`, particle `particle`, component `component`.
inline void use_perturbing_candidate(int frame, int particle, int component,
                                     const std::string& change) {
  set_env("FOSSSIM", kFossSim);
  set_env("PERTURB_TOOL", kPerturbTool);
  set_env("PERTURB_FRAME", std::to_string(frame));
  set_env("PERTURB_PARTICLE", std::to_string(particle));
  set_env("PERTURB_COMPONENT", std::to_string(component));
  set_env("PERTURB_DELTA", change);
}

}  // namespace fosssim::testing
