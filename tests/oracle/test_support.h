#pragma once
// Shared helpers of the oracle's tests: where things are, temporary folders, trajectories.

#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
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

/// What the test candidates read besides their own folder and the scene's, and so what their
/// sandbox must show them: the build folder (FOSSSim, the perturbing tool) and the tests folder
/// (the sanitizers' suppression file).
inline std::vector<std::string> sandbox_readable() {
  namespace fs = std::filesystem;
  return {fs::path(kFossSim).parent_path().parent_path().string(),
          fs::path(kData).parent_path().parent_path().string()};
}

/// The same as --allow-read arguments of `fosssim-oracle grade`.
inline std::vector<std::string> allow_read_arguments() {
  std::vector<std::string> arguments;
  for (const std::string& path : sandbox_readable()) {
    arguments.insert(arguments.end(), {"--allow-read", path});
  }
  return arguments;
}

/// The bytes of a /proc file, empty if it cannot be read. Read with read(2): a process that
/// ends while its file is read makes read fail with ESRCH, which libstdc++'s filebuf turns
/// into an exception.
inline std::string read_proc_file(const std::filesystem::path& path) {
  std::string bytes;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return bytes;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) bytes.append(buffer, n);
  ::close(fd);
  return bytes;
}

/// The live processes of the machine (zombies left out) that have `argument` among their
/// arguments, as read from /proc. Processes may end while the listing is read.
inline std::vector<int> processes_with_argument(const std::string& argument) {
  std::vector<int> found;
  std::error_code error;
  for (std::filesystem::directory_iterator it("/proc", error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string arguments = '\0' + read_proc_file(it->path() / "cmdline");
    if (arguments.find('\0' + argument + '\0') == std::string::npos) continue;
    const std::string stat = read_proc_file(it->path() / "stat");
    const std::string line = stat.substr(0, stat.find('\n'));
    const std::size_t close = line.rfind(')');
    if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z') continue;
    found.push_back(std::stoi(name));
  }
  return found;
}

/// Waits up to `seconds` for every process with `argument` to be gone; returns those left.
inline std::vector<int> wait_for_processes_to_end(const std::string& argument, double seconds) {
  std::vector<int> left;
  for (int k = 0; k < static_cast<int>(seconds * 50); ++k) {
    left = processes_with_argument(argument);
    if (left.empty()) break;
    ::usleep(20000);
  }
  return left;
}

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

/// A stroked path of an SVG written by Cairo: whether it is dashed, and its points.
struct SvgStroke {
  bool dashed = false;
  std::vector<std::pair<double, double>> points;
};

/// The stroked paths of an SVG written by Cairo, in drawing order ("M x y L x y ..."; text is
/// drawn as filled glyph outlines and is left out).
inline std::vector<SvgStroke> svg_strokes(const std::string& svg) {
  tinyxml2::XMLDocument document;
  EXPECT_EQ(document.Parse(svg.c_str()), tinyxml2::XML_SUCCESS) << svg.substr(0, 500);
  std::vector<SvgStroke> strokes;
  std::vector<const tinyxml2::XMLElement*> pending{document.RootElement()};
  while (!pending.empty()) {  // depth first, children in document order
    const tinyxml2::XMLElement* element = pending.back();
    pending.pop_back();
    if (element == nullptr) continue;
    const char* style = element->Attribute("style");
    const char* d = element->Attribute("d");
    if (std::strcmp(element->Name(), "path") == 0 && style && d &&
        std::strstr(style, "stroke:rgb") != nullptr) {
      SvgStroke stroke;
      stroke.dashed = std::strstr(style, "stroke-dasharray") != nullptr;
      std::istringstream words(d);
      for (std::string word; words >> word;) {
        if (std::isalpha(static_cast<unsigned char>(word[0]))) continue;  // M, L, Z
        double y = 0.0;
        words >> y;
        stroke.points.emplace_back(std::stod(word), y);
      }
      strokes.push_back(std::move(stroke));
    }
    std::vector<const tinyxml2::XMLElement*> children;
    for (auto* c = element->FirstChildElement(); c; c = c->NextSiblingElement())
      children.push_back(c);
    pending.insert(pending.end(), children.rbegin(), children.rend());
  }
  return strokes;
}

/// Checks the residual plot of a diagnosis (an SVG file). The plot draws its reference lines
/// (dashed), then the position and the velocity curve, then the legend; Cairo merges collinear
/// segments, so a curve has a vertex where it changes direction. Checked: the dashed vertical
/// marker of the first divergence, the position curve rising there from the zero line it
/// started on, and the velocity curve over the same steps.
inline void expect_residual_plot(const std::string& path) {
  const std::vector<SvgStroke> strokes = svg_strokes(read_bytes(path));
  std::size_t last_dashed = strokes.size();
  const SvgStroke* marker = nullptr;
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    const SvgStroke& s = strokes[k];
    if (!s.dashed) continue;
    last_dashed = k;
    if (s.points.size() == 2 && s.points[0].first == s.points[1].first) marker = &s;
  }
  ASSERT_NE(marker, nullptr) << path;
  ASSERT_LT(last_dashed + 2, strokes.size()) << path;
  const auto& position = strokes[last_dashed + 1].points;
  const auto& velocity = strokes[last_dashed + 2].points;
  ASSERT_GE(position.size(), 3u) << path;
  ASSERT_GE(velocity.size(), 2u) << path;
  EXPECT_EQ(position.front().first, velocity.front().first);
  EXPECT_EQ(position.back().first, velocity.back().first);
  const double zero_line = position.front().second;
  bool rises_at_marker = false;
  for (std::size_t k = 1; k < position.size(); ++k) {
    rises_at_marker =
        rises_at_marker || (std::abs(position[k].first - marker->points[0].first) <= 1.0 &&
                            position[k - 1].second == zero_line &&
                            position[k].second < zero_line - 50.0);  // pixels: y grows downwards
  }
  EXPECT_TRUE(rises_at_marker) << path;
}

}  // namespace fosssim::testing
