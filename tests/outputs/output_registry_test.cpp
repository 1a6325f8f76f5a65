// The output registry (outputs/output_registry.h): every entry is complete and unambiguous, each
// format is one file pair and one registry line (docs/architecture.md, 'Where a change goes'),
// docs/command-line.md lists every format's option, and every format, opened on a tiny scene,
// writes its destination when the run completes and leaves nothing that looks complete when the
// run is abandoned.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/step/simulation.h"
#include "outputs/frame_outputs.h"
#include "outputs/output_registry.h"
#include "pictures/movie_writer.h"
#include "render/scene_view.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

std::string source_file(const std::string& relative) {
  std::ifstream in(std::string(FOSSSIM_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// "-o", "--output" of "-o,--output".
std::vector<std::string> names_of(std::string_view flags) {
  std::vector<std::string> names;
  std::string item;
  std::stringstream in{std::string(flags)};
  while (std::getline(in, item, ',')) names.push_back(item);
  return names;
}

TEST(OutputRegistry, EveryEntryIsCompleteAndNamesAreUnique) {
  std::set<std::string> names, options;
  for (const OutputFormat* format : output_formats()) {
    SCOPED_TRACE(std::string(format->name));
    EXPECT_TRUE(names.insert(std::string(format->name)).second) << "two formats of one name";
    EXPECT_EQ(find_output_format(format->name), format);
    EXPECT_NE(format->open, nullptr);
    EXPECT_FALSE(format->help.empty());
    EXPECT_FALSE(format->value_name.empty());
    ASSERT_FALSE(format->flags.empty());
    std::vector<std::string> all = names_of(format->flags);
    for (const std::string& name : names_of(format->switch_flags)) all.push_back(name);
    for (const std::string& name : all) {
      EXPECT_TRUE(std::regex_match(name, std::regex("-[a-z]|--[a-z][a-z0-9-]*"))) << name;
      EXPECT_TRUE(options.insert(name).second) << name << " is declared twice";
    }
    EXPECT_EQ(format->target == OutputTarget::kFolder, !format->picture_extension.empty())
        << "a folder of pictures, and only that, has its pictures' extension";
    if (!format->switch_flags.empty()) {
      EXPECT_FALSE(format->switch_help.empty());
      EXPECT_FALSE(format->default_destination.empty()) << "a switch writes to a default place";
      EXPECT_EQ(format->request_name(), names_of(format->switch_flags).front());
    } else {
      EXPECT_TRUE(format->default_destination.empty()) << "asked for by naming its destination";
      EXPECT_EQ(format->request_name(), format->option_name());
    }
    EXPECT_EQ(format->needs.window, format->headless_reason.empty())
        << "an output the window cannot write says why";
    EXPECT_TRUE(format->needs.runs_2d || format->needs.runs_3d);
    EXPECT_TRUE(format->needs.particles || format->needs.rigid_bodies);
  }
  EXPECT_EQ(find_output_format("no-such-format"), nullptr);
  // The course's outputs keep their flags (docs/command-line.md: course-compatible).
  ASSERT_NE(find_output_format("trajectory"), nullptr);
  EXPECT_EQ(find_output_format("trajectory")->option_name(), "-o");
  ASSERT_NE(find_output_format("png-sequence"), nullptr);
  EXPECT_EQ(find_output_format("png-sequence")->request_name(), "-g");
  ASSERT_NE(find_output_format("svg-sequence"), nullptr);
  EXPECT_EQ(find_output_format("svg-sequence")->option_name(), "-m");
}

TEST(OutputRegistry, ChoicesAskForWhatTheCommandLineNamed) {
  OutputChoices choices;
  EXPECT_TRUE(choices.requests().empty()) << "nothing is written unless asked for";
  const OutputFormat& png = *find_output_format("png-sequence");
  const OutputFormat& csv = *find_output_format("energy-csv");
  EXPECT_EQ(choices.destination(png), "pngs");
  choices.destination(csv) = "e.csv";
  choices.switched(png) = 1;
  const std::vector<OutputRequest> requests = choices.requests();
  ASSERT_EQ(requests.size(), 2u);
  // Registry order, whatever order the options came in.
  EXPECT_EQ(requests[0].format, &png);
  EXPECT_EQ(requests[0].destination, "pngs");
  EXPECT_EQ(requests[1].format, &csv);
  EXPECT_EQ(requests[1].destination, "e.csv");
}

// Adding an output is one file pair and one registry line: each header of outputs/ that
// declares entries ("extern const OutputFormat kX;") has its .cpp defining them, and the
// registry lists exactly the declared entries, each once.
TEST(OutputRegistry, EachFormatIsOneFilePairAndOneRegistryLine) {
  const std::string registry = source_file("FOSSSim/outputs/output_registry.cpp");
  ASSERT_FALSE(registry.empty());
  const std::regex declaration(R"(extern const OutputFormat (k\w+);)");
  std::size_t declared = 0;
  for (const auto& entry : fs::directory_iterator(std::string(FOSSSIM_SOURCE_DIR) +
                                                  "/FOSSSim/outputs")) {
    if (entry.path().extension() != ".h") continue;
    const std::string header = source_file("FOSSSim/outputs/" + entry.path().filename().string());
    for (std::sregex_iterator it(header.begin(), header.end(), declaration), end; it != end;
         ++it) {
      const std::string name = (*it)[1];
      SCOPED_TRACE(name + " of " + entry.path().filename().string());
      ++declared;
      fs::path pair = entry.path();
      pair.replace_extension(".cpp");
      EXPECT_NE(source_file("FOSSSim/outputs/" + pair.filename().string())
                    .find("const OutputFormat " + name + "{"),
                std::string::npos)
          << "defined in its own .cpp";
      const std::regex listed("&" + name + R"(\b)");
      EXPECT_EQ(std::distance(std::sregex_iterator(registry.begin(), registry.end(), listed),
                              std::sregex_iterator()),
                1)
          << "listed once in output_registry.cpp";
    }
  }
  EXPECT_EQ(declared, output_formats().size());
}

// docs/command-line.md lists every format's options, and docs/architecture.md says where a
// new one goes.
TEST(OutputRegistry, DocumentedInCommandLineAndArchitecture) {
  const std::string command_line = source_file("docs/command-line.md");
  ASSERT_FALSE(command_line.empty());
  for (const OutputFormat* format : output_formats()) {
    EXPECT_NE(command_line.find("`" + std::string(format->request_name())), std::string::npos)
        << format->name;
    EXPECT_NE(command_line.find(std::string(format->option_name())), std::string::npos)
        << format->name;
  }
  const std::string architecture = source_file("docs/architecture.md");
  EXPECT_NE(architecture.find("outputs/output_registry.cpp"), std::string::npos);
}

// What a format says it needs is checked before anything is opened: a format for 3D scenes
// only is refused on a 2D scene, naming its option, and writes nothing.
TEST(OutputRegistry, WhatAFormatNeedsIsCheckedBeforeOpening) {
  static bool opened = false;
  OutputFormat only_3d = *find_output_format("energy-csv");
  only_3d.flags = "--only-3d";
  only_3d.needs.runs_2d = false;
  only_3d.open = [](const std::string&, const OutputContext&) -> std::unique_ptr<FrameOutput> {
    opened = true;
    return nullptr;
  };
  const Scene scene = testing::tiny_scene();  // 2D, particles
  const std::vector<OutputRequest> requests = {{&only_3d, "x.csv"}};
  try {
    FrameOutputs::open(scene, requests, OutputSettings{});
    ADD_FAILURE() << "a 3D-only output was opened for a 2D scene";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
    EXPECT_EQ(std::string(error.what()), "--only-3d cannot be written for 2D scenes (tiny.xml)");
  }
  EXPECT_FALSE(opened);
  OutputFormat no_rigid = only_3d;
  no_rigid.needs = {.rigid_bodies = false};
  EXPECT_NO_THROW(check_needs(no_rigid, scene)) << "the tiny scene has particles";
}

/// Runs the tiny scene to its end (or `abandon_after` steps) feeding one output of `format` at
/// `destination`; returns the note abandon() gave ("" after a completed run).
std::string run_tiny(const OutputFormat& format, const std::string& destination,
                     int abandon_after = -1) {
  const Scene scene = testing::tiny_scene();
  OutputSettings settings;
  settings.movie.width = settings.movie.height = 64;
  const std::vector<OutputRequest> requests = {{&format, destination}};
  FrameOutputs outputs = FrameOutputs::open(scene, requests, settings);
  Simulation simulation(scene.model, scene.initial);
  SceneView view(scene, simulation.state(), 64, 64);
  outputs.write(simulation.state(), view, nullptr, &simulation.integrator());
  while (!simulation.finished()) {
    if (simulation.state().step == abandon_after) return outputs.abandon();
    simulation.step();
    outputs.write(simulation.state(), view, &simulation.last_record(), &simulation.integrator());
  }
  outputs.commit();
  EXPECT_NE(outputs.describe().find(destination), std::string::npos) << outputs.describe();
  return "";
}

std::string destination_for(const OutputFormat& format) {
  if (format.target == OutputTarget::kFolder) return "out_" + std::string(format.name);
  if (format.check == nullptr) return "out_" + std::string(format.name);
  // A format that checks its name: the first of a few usual extensions it accepts.
  for (const char* extension : {".mp4", ".png", ".json", ".csv", ".bin"}) {
    const std::string name = "out_" + std::string(format.name) + extension;
    try {
      OutputSettings settings;
      format.check(name, settings);
      return name;
    } catch (const Error&) {
    }
  }
  ADD_FAILURE() << format.name << " accepts none of the usual extensions";
  return "";
}

TEST(OutputRegistry, EveryFormatWritesACompletedRunAndNothingCompleteOfAnAbandonedOne) {
  const bool have_ffmpeg = find_program("ffmpeg").has_value();
  for (const OutputFormat* format : output_formats()) {
    SCOPED_TRACE(std::string(format->name));
    if (format->name == "movie" && !have_ffmpeg) {
      ADD_FAILURE() << "ffmpeg is not installed (tools/install-deps.sh installs it)";
      continue;
    }
    testing::ScratchFolder folder;
    const fs::path done = folder / destination_for(*format);
    run_tiny(*format, done.string());
    if (format->target == OutputTarget::kFolder) {
      // One picture per state, the initial one included.
      std::size_t pictures = 0;
      for (const auto& entry : fs::directory_iterator(done)) {
        EXPECT_EQ(entry.path().extension(), "." + std::string(format->picture_extension));
        ++pictures;
      }
      EXPECT_EQ(pictures, static_cast<std::size_t>(testing::kTinySteps + 1));
      continue;
    }
    ASSERT_TRUE(fs::is_regular_file(done));
    EXPECT_GT(fs::file_size(done), 0u);
    const fs::path stopped = folder / ("stopped_" + done.filename().string());
    run_tiny(*format, stopped.string(), /*abandon_after=*/5);
    EXPECT_FALSE(fs::exists(stopped)) << "an abandoned run leaves no file under the final name";
    for (const auto& entry : fs::directory_iterator(folder.path())) {
      EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
          << entry.path() << ": no temporary file is left behind";
    }
  }
}

}  // namespace
}  // namespace fosssim
