// FOSSSim --stats-json (docs/command-line.md, 'Run summaries'): the summary of a completed run,
// byte-identical from run to run outside its "timings" object, refused with grading and when
// it would replace an input, and never left behind by a run that failed.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class CliStatsJson : public ::testing::Test {
 protected:
  void SetUp() override { folder_.write("scene.xml", testing::kTinyScene); }
  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(
        folder_,
        "timeout -k 5 60 " + testing::quoted(testing::fosssim_program()) + " " + arguments);
  }
  /// The file's text without its "timings" object (the last key, on lines of its own).
  std::string without_timings(const std::string& name) {
    const std::string text = folder_.read(name);
    const std::string key = "  \"timings\": {";
    const std::size_t timings = text.find(key);
    EXPECT_NE(timings, std::string::npos) << text;
    EXPECT_EQ(text.find("\"timings\"", timings + key.size()), std::string::npos) << "once";
    return text.substr(0, timings);
  }
  testing::ScratchFolder folder_;
};

TEST_F(CliStatsJson, TwoRunsGiveTheSameBytesOutsideTheTimings) {
  ASSERT_EQ(fosssim("-s scene.xml -d 0 -q --stats-json a.json").status, 0);
  ASSERT_EQ(fosssim("-s scene.xml -d 0 -q --stats-json b.json -o out.bin").status, 0);
  const std::string a = without_timings("a.json");
  EXPECT_EQ(a, without_timings("b.json"));
  const auto summary = nlohmann::json::parse(folder_.read("a.json"));
  EXPECT_EQ(summary["schema"], "fosssim-run-stats");
  EXPECT_EQ(summary["version"], 1);
  EXPECT_EQ(summary["steps"], testing::kTinySteps);
  EXPECT_EQ(summary["integrator"]["method"], "explicit-euler");
  EXPECT_GE(summary["timings"]["wall_seconds"].get<double>(), 0.0);
  // The byte layout: two-space indents, a final newline.
  const std::string start = "{\n  \"schema\": \"fosssim-run-stats\",\n  \"version\": 1,\n";
  EXPECT_EQ(folder_.read("a.json").substr(0, start.size()), start);
  EXPECT_EQ(folder_.read("a.json").back(), '\n');
}

TEST_F(CliStatsJson, RefusedWithGradingAndOverAnInput) {
  ASSERT_EQ(fosssim("-s scene.xml -d 0 -q -o out.bin").status, 0);
  auto result = fosssim("-s scene.xml -d 0 -i out.bin --stats-json s.json");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--stats-json describe a run; they cannot be combined with grading"),
            std::string::npos)
      << result.err;
  const std::string scene = folder_.read("scene.xml");
  result = fosssim("-s scene.xml -d 0 --stats-json scene.xml");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--stats-json scene.xml is the scene file scene.xml: an output must "
                            "never replace an input"),
            std::string::npos)
      << result.err;
  EXPECT_EQ(folder_.read("scene.xml"), scene);
  EXPECT_FALSE(folder_.exists("s.json"));
}

TEST_F(CliStatsJson, AFailedRunLeavesNoSummary) {
  // The spring explodes at this step: the health check stops the run (status 3).
  folder_.write("explodes.xml", R"(<scene>
  <duration time="10"/><integrator type="explicit-euler" dt="1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="2" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="1e300" l0="1"/>
</scene>)");
  const auto result = fosssim("-s explodes.xml -d 0 -q --stats-json s.json");
  EXPECT_EQ(result.status, 3) << result.err;
  for (const auto& entry : fs::directory_iterator(folder_.path())) {
    EXPECT_EQ(entry.path().filename().string().find("s.json"), std::string::npos)
        << entry.path() << ": a failed run leaves no summary, whole or partial";
  }
}

}  // namespace
}  // namespace fosssim
