// fosssim-oracle: grades any simulator that speaks the course's command line against the scenes
// of a suite, writes the reports autograders read, merges shards of large runs, and keeps the
// regression manifest of FOSSSim's own trajectories. Only this file chooses exit statuses.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <variant>

#include "atomic_file.h"
#include "batch.h"
#include "child_process.h"
#include "cli/exit_codes.h"
#include "cli/parse_command_line.h"
#include "core/text.h"
#include "gradescope_report.h"
#include "io/file_identity.h"
#include "io/text_lines.h"
#include "junit_report.h"
#include "manifest.h"
#include "result_table.h"
#include "sandbox.h"
#include "scene_grading.h"
#include "seconds_since.h"
#include "shard_result_file.h"

namespace fosssim {
namespace {

constexpr const char* kRegenerateCommand =
    "cmake --build --preset release --target oracle-manifest";

/// Where the reports of a run go, and how Gradescope scores it.
struct ReportOptions {
  std::string junit, gradescope;
  GradescopeOptions scoring;
  bool quiet = false;
};

struct GradeCommand {
  std::string candidate;
  std::vector<std::string> folders, extra_credit;
  int jobs = 1;
  std::string shard = "1/1";
  double timeout = 600.0;
  std::string timeouts;  ///< --timeouts FILE: per-scene wall-time limits
  std::string shard_result, diagnose_dir, work_dir;
  bool keep_work = false;
  bool no_sandbox = false;
  std::vector<std::string> allow_read;
  std::int64_t max_memory_mib =
      kDefaultCandidateMemoryBytes < 0 ? 0 : kDefaultCandidateMemoryBytes >> 20;
  int max_processes = kDefaultCandidateProcesses;
  ReportOptions reports;
};

/// Longest --timeout: a week. Larger values (and inf, nan) are refused, not taken as "none".
constexpr double kMaxTimeoutSeconds = 7 * 24 * 3600.0;

/// Sets each scene's own time-out from a --timeouts file: one line per scene, its name (as in
/// the reports) and seconds, separated by white space; '#' starts a comment. A line for a scene
/// that is not in the run, a repeated scene, or seconds outside (0, a week] is an error naming
/// the file and line. Scenes without a line keep --timeout. The file holds at most one line per
/// scene of the run plus comments: it is read under the text-file size limit of io/.
void apply_timeouts_file(const std::string& path, std::vector<SceneEntry>& scenes) {
  std::string text;
  try {
    text = read_text_file(path);
  } catch (const Error& error) {
    throw Error(ErrorKind::kBadInput, "--timeouts " + path + ": " + error.what());
  }
  std::map<std::string, SceneEntry*> by_name;
  for (SceneEntry& entry : scenes) by_name[entry.name] = &entry;
  std::map<std::string, int> seen;
  const std::vector<Word> words = split_words(text);
  for (std::size_t i = 0; i < words.size(); i += 2) {
    const Word& name = words[i];
    const auto where = [&](int line) { return path + ":" + std::to_string(line) + ": "; };
    if (i + 1 >= words.size() || words[i + 1].line != name.line) {
      throw Error(ErrorKind::kBadInput, where(name.line) + "expected a scene name and seconds");
    }
    if (i + 2 < words.size() && words[i + 2].line == name.line) {
      throw Error(ErrorKind::kBadInput,
                  where(name.line) + "more than a scene name and seconds on one line");
    }
    double seconds = 0.0;
    if (!parse_finite(words[i + 1].text, seconds) || !(seconds > 0.0) ||
        seconds > kMaxTimeoutSeconds) {
      throw Error(ErrorKind::kBadInput, where(name.line) + "seconds " + quote(words[i + 1].text) +
                                            " are not a number above 0 and at most a week");
    }
    const std::string scene(name.text);
    const auto found = by_name.find(scene);
    if (found == by_name.end()) {
      throw Error(ErrorKind::kBadInput,
                  where(name.line) + "no scene " + quote(scene) + " in this run");
    }
    if (const auto [previous, fresh] = seen.emplace(scene, name.line); !fresh) {
      throw Error(ErrorKind::kBadInput, where(name.line) + "scene " + quote(scene) +
                                            " already given on line " +
                                            std::to_string(previous->second));
    }
    found->second->timeout_seconds = seconds;
  }
}
/// Largest --points-per-scene.
constexpr double kMaxPointsPerScene = 1e6;
/// Most -j workers, and most --max-processes.
constexpr int kMaxJobs = 256;
constexpr int kMaxProcessesLimit = 4096;

/// Accepts a decimal number that is finite, greater than `above` and at most `at_most`; CLI11's
/// own checks let nan and inf through.
CLI::Validator finite_number(double above, double at_most) {
  return CLI::Validator(
      [above, at_most](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(value)) {
          return "expected a finite number, got " + text;
        }
        if (!(value > above) || value > at_most) {
          return "expected a number greater than " + to_text(above) + " and at most " +
                 to_text(at_most) + ", got " + text;
        }
        return "";
      },
      "NUMBER in (" + to_text(above) + ", " + to_text(at_most) + "]");
}

/// Throws Error (kBadInput) unless `folder` is empty or an existing folder: a missing work
/// folder is the caller's mistake, not the candidate's.
void check_work_dir(const std::string& folder) {
  if (folder.empty()) return;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw Error(ErrorKind::kBadInput,
                "--work-dir " + folder + ": " +
                    (std::filesystem::exists(folder, error) ? "not a folder" : "no such folder"));
  }
}

/// Throws Error (kBadInput) when a report path names the same file as an input (a scene, a file
/// a scene reads, the candidate, a shard result being merged) or as another report: a report
/// never replaces an input, and two reports never share a file.
void check_outputs_are_not_inputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                                  const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    if (path.empty()) continue;
    const std::optional<FileIdentity> identity = file_identity(path);
    if (!identity) continue;  // not there yet: it cannot be an input
    for (const std::string& input : inputs) {
      if (file_identity(input) == identity) {
        throw Error(ErrorKind::kBadInput, option + " " + path + " is the input " + input +
                                              "; a report never replaces an input");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].second.empty() && file_identity(outputs[j].second) == identity) {
        throw Error(ErrorKind::kBadInput, option + " " + path + " is also " + outputs[j].first +
                                              "; give each report a file of its own");
      }
    }
  }
}

struct MergeCommand {
  std::vector<std::string> files;
  ReportOptions reports;
};

struct ManifestCommand {
  std::string candidate = "FOSSSim";
  std::string folder = "oracle/manifest";
  std::vector<std::string> scene_folders;
  int jobs = 1;
  double timeout = 600.0;
  std::string work_dir;
};

extern "C" void on_interrupt(int) { stop_all_children(); }

void install_interrupt_handler() {
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = on_interrupt;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void add_report_options(CLI::App& command, ReportOptions& reports) {
  command.add_option("--junit", reports.junit, "Write the JUnit XML report here");
  command.add_option("--gradescope", reports.gradescope, "Write Gradescope's results.json here");
  command
      .add_option("--points-per-scene", reports.scoring.points_per_scene,
                  "Gradescope points for each passing scene")
      ->check(finite_number(0.0, kMaxPointsPerScene))
      ->capture_default_str();
  command
      .add_option("--visibility", reports.scoring.visibility,
                  "Gradescope visibility of every test: visible, hidden, after_due_date or "
                  "after_published")
      ->check(CLI::IsMember({"visible", "hidden", "after_due_date", "after_published"}))
      ->capture_default_str();
  command.add_flag("-q,--quiet", reports.quiet, "No progress lines on standard error");
}

/// Prints the table and writes the requested reports; returns the exit status.
int report(const GradingRun& run, const ReportOptions& options) {
  print_result_table(std::cout, run);
  int status = tally(run.results).all_passed() ? kExitOk : kExitGradingFailed;
  const auto write = [&status](const std::string& path, const std::string& content,
                               const char* what) {
    if (path.empty()) return;
    try {
      write_file_atomically(path, content);
      std::cout << what << " written to " << path << "\n";
    } catch (const Error& error) {
      std::cerr << "fosssim-oracle: error: " << error.what() << "\n";
      status = exit_status(error.kind());
    }
  };
  write(options.junit, junit_xml(run), "JUnit XML");
  write(options.gradescope, gradescope_json(run, options.scoring), "Gradescope results");
  return status;
}

int run_grade(const GradeCommand& command) {
  const auto start = std::chrono::steady_clock::now();
  const Shard shard = parse_shard(command.shard);
  std::vector<SceneEntry> scenes = discover_scenes(command.folders, command.extra_credit);
  if (scenes.empty()) {
    std::cerr << "fosssim-oracle: error: no scene files (*.xml) in the given folders\n";
    return kExitBadInput;
  }
  if (!command.timeouts.empty()) apply_timeouts_file(command.timeouts, scenes);
  check_work_dir(command.work_dir);
  GradingOptions options;
  options.run.candidate = resolve_executable(command.candidate);
  if (options.run.candidate.empty()) {
    options.run.candidate = command.candidate;
    std::cerr << "fosssim-oracle: warning: the candidate " << command.candidate << " "
              << why_not_found(command.candidate) << "; every scene will fail\n";
  }
  options.run.timeout_seconds = command.timeout;
  options.run.sandbox = !command.no_sandbox;
  options.run.readable = command.allow_read;
  options.run.max_memory_bytes =
      command.max_memory_mib > 0 ? command.max_memory_mib << 20 : std::int64_t(-1);
  options.run.max_processes = command.max_processes;
  options.work_dir = command.work_dir;
  options.keep_work = command.keep_work;
  options.diagnose_dir = command.diagnose_dir;
  for (const std::string& path : command.allow_read) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
      throw Error(ErrorKind::kBadInput, "--allow-read " + path + ": no such file or folder");
    }
  }

  GradingRun run;
  run.candidate = command.candidate;
  run.sandboxed = options.run.sandbox;
  run.shard = shard;
  run.scenes = listing_of(scenes);
  // The oracle's own copy of every scene, taken before any candidate runs (scene_grading.h).
  std::vector<SceneEntry> selected = select_shard(scenes, shard);
  read_scene_files(selected);
  std::vector<std::string> inputs = {options.run.candidate};
  for (const SceneEntry& entry : scenes) inputs.push_back(entry.path);
  if (!command.timeouts.empty()) inputs.push_back(command.timeouts);
  for (const SceneEntry& entry : selected) {
    for (const auto& file : entry.files) inputs.push_back(file.first);
  }
  check_outputs_are_not_inputs({{"--junit", command.reports.junit},
                                {"--gradescope", command.reports.gradescope},
                                {"--shard-result", command.shard_result}},
                               inputs);
  if (options.run.sandbox) {
    options.run.bwrap = resolve_executable("bwrap");
    WorkFolder probe(command.work_dir);
    if (auto why = sandbox_unavailable(options.run.bwrap, probe.path())) {
      throw Error(ErrorKind::kUnavailable,
                  *why +
                      "; candidates are not run unconfined unless asked: install bubblewrap, or "
                      "give --no-sandbox to run them without a sandbox (they can then read and "
                      "write whatever this user can)");
    }
  } else if (!command.reports.quiet) {
    std::cerr << "fosssim-oracle: warning: --no-sandbox: candidates run unconfined, with the "
                 "time, CPU, memory, file-size and process limits only\n";
  }
  if (!command.reports.quiet) {
    std::cerr << "fosssim-oracle: grading " << selected.size() << " of " << scenes.size()
              << " scenes (shard " << shard.index << "/" << shard.count << ") with " << command.jobs
              << (command.jobs == 1 ? " job" : " jobs") << "\n";
  }
  install_interrupt_handler();
  const bool quiet = command.reports.quiet;
  run.results = grade_scenes(selected, options, command.jobs,
                             [quiet](const SceneResult& r, std::size_t done, std::size_t total) {
                               if (!quiet) std::cerr << progress_line(r, done, total) << std::endl;
                             });
  run.wall_seconds = seconds_since(start);
  if (children_stopped()) {
    std::cerr << "fosssim-oracle: interrupted; no reports written\n";
    return kExitInterrupted;
  }
  int status = report(run, command.reports);
  if (!command.shard_result.empty()) {
    try {
      write_file_atomically(command.shard_result, shard_result_json(run));
      std::cout << "Shard results written to " << command.shard_result << "\n";
    } catch (const Error& error) {
      std::cerr << "fosssim-oracle: error: " << error.what() << "\n";
      status = exit_status(error.kind());
    }
  }
  return status;
}

int run_merge(const MergeCommand& command) {
  check_outputs_are_not_inputs(
      {{"--junit", command.reports.junit}, {"--gradescope", command.reports.gradescope}},
      command.files);
  std::vector<GradingRun> shards;
  for (const std::string& file : command.files) {
    std::string text;
    try {
      text = read_text_file(file);
    } catch (const Error&) {
      throw Error(ErrorKind::kBadInput, "cannot read " + file);
    }
    shards.push_back(parse_shard_result(text, file));
  }
  return report(merge_shards(shards, command.files), command.reports);
}

/// The manifest entries of a fresh run, or an exit status.
std::variant<std::vector<ManifestEntry>, int> compute_for(const ManifestCommand& command) {
  const std::vector<SceneEntry> scenes =
      discover_scenes(command.scene_folders, {}, /*missing_folders_are_empty=*/true);
  check_work_dir(command.work_dir);
  CandidateRunOptions options;
  // FOSSSim is this repository's own program, not a submission: it runs without a sandbox, so
  // that the manifest does not depend on bubblewrap; the limits still apply.
  options.sandbox = false;
  options.candidate = resolve_executable(command.candidate);
  if (options.candidate.empty()) {
    std::cerr << "fosssim-oracle: error: the candidate " << command.candidate << " "
              << why_not_found(command.candidate) << "\n";
    return kExitBadInput;
  }
  options.timeout_seconds = command.timeout;
  install_interrupt_handler();
  auto entries = compute_manifest(scenes, options, command.work_dir, command.jobs);
  if (children_stopped()) return kExitInterrupted;
  return entries;
}

int run_manifest_update(const ManifestCommand& command) {
  auto computed = compute_for(command);
  if (auto* status = std::get_if<int>(&computed)) return *status;
  const auto& entries = std::get<std::vector<ManifestEntry>>(computed);
  write_manifest(command.folder, entries, kRegenerateCommand);
  std::cout << "Manifest of " << entries.size() << " scenes written to " << command.folder << "\n";
  for (const ManifestEntry& e : entries) {
    if (e.status != "ok") std::cout << "  note: " << e.scene << ": " << e.status << "\n";
  }
  return kExitOk;
}

int run_manifest_check(const ManifestCommand& command) {
  std::vector<ManifestEntry> golden;
  try {
    golden = read_manifest(command.folder);
  } catch (const Error& error) {
    throw Error(error.kind(),
                std::string(error.what()) + "; create it with `" + kRegenerateCommand + "`");
  }
  auto computed = compute_for(command);
  if (auto* status = std::get_if<int>(&computed)) return *status;
  const auto& entries = std::get<std::vector<ManifestEntry>>(computed);
  const auto problems = compare_manifest(golden, entries, kRegenerateCommand);
  if (problems.empty()) {
    std::cout << "All " << entries.size() << " scenes match the manifest " << command.folder
              << "\n";
    return kExitOk;
  }
  for (const std::string& problem : problems) std::cout << problem << "\n";
  return kExitGradingFailed;
}

void add_grade_command(CLI::App& app, GradeCommand& c) {
  CLI::App* grade = app.add_subcommand(
      "grade", "Run a candidate simulator on every scene and grade its trajectories");
  grade
      ->add_option("--candidate", c.candidate,
                   "The simulator to grade: a path, or a name found in $PATH; it is run as\n"
                   "CANDIDATE -s SCENE -d 0 -o FILE in a temporary folder of its own")
      ->required();
  grade->add_option("folders", c.folders, "Scene folders (searched for *.xml) or scene files")
      ->required();
  grade
      ->add_option("--extra-credit", c.extra_credit,
                   "An extra-credit scene folder, scored apart (repeat for several)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  grade->add_option("-j,--jobs", c.jobs, "Scenes graded at once")
      ->check(CLI::Range(1, kMaxJobs))
      ->capture_default_str();
  grade
      ->add_option("--shard", c.shard,
                   "Grade only shard K of N: the scenes at positions i (0-based, in sorted order)\n"
                   "with i mod N = K - 1")
      ->capture_default_str();
  grade
      ->add_option("--timeout", c.timeout,
                   "Seconds a candidate may run on one scene (wall time; its CPU time is limited "
                   "to the same, rounded up)")
      ->check(finite_number(0.0, kMaxTimeoutSeconds))
      ->capture_default_str();
  grade->add_option("--timeouts", c.timeouts,
                    "A file of per-scene time-outs: lines '<scene name> <seconds>' (names as in "
                    "the\nreports); scenes it does not list keep --timeout");
  grade->add_flag("--no-sandbox", c.no_sandbox,
                  "Run the candidate without the bubblewrap sandbox (where it cannot be built):\n"
                  "it then sees and can write whatever this user can; the limits still apply");
  grade
      ->add_option("--allow-read", c.allow_read,
                   "A file or folder the sandboxed candidate may also read, at the same path\n"
                   "(repeat for several); it always reads its own folder and the scene's")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  grade
      ->add_option("--max-memory", c.max_memory_mib,
                   "MiB of address space each process of the candidate may map (RLIMIT_AS);\n"
                   "0: no limit")
      ->check(CLI::Range(std::int64_t(0), std::int64_t(1) << 30))
      ->capture_default_str();
  grade
      ->add_option("--max-processes", c.max_processes,
                   "Processes the candidate may have at once; more stop it")
      ->check(CLI::Range(1, kMaxProcessesLimit))
      ->capture_default_str();
  grade->add_option("--shard-result", c.shard_result,
                    "Write this run's results as JSON, for `fosssim-oracle merge`");
  grade->add_option(
      "--diagnose-dir", c.diagnose_dir,
      "Write each failing scene's diagnosis (text, per-step residual table, SVG plot)");
  grade->add_option("--work-dir", c.work_dir,
                    "Where the per-scene temporary folders go (default $TMPDIR)");
  grade->add_flag("--keep-work", c.keep_work,
                  "Keep the per-scene folders with the candidate's files");
  add_report_options(*grade, c.reports);
}

void add_merge_command(CLI::App& app, MergeCommand& c) {
  CLI::App* merge = app.add_subcommand(
      "merge", "Merge the --shard-result files of all shards into the reports of the whole run");
  merge->add_option("files", c.files, "Shard result files, one per shard")->required();
  add_report_options(*merge, c.reports);
}

void add_manifest_options(CLI::App& command, ManifestCommand& c) {
  command.add_option("--candidate", c.candidate, "The FOSSSim executable")->capture_default_str();
  command.add_option("--manifest", c.folder, "The manifest folder")->capture_default_str();
  command
      .add_option("folders", c.scene_folders,
                  "Scene folders (a folder that does not exist counts as empty)")
      ->required();
  command.add_option("-j,--jobs", c.jobs, "Scenes run at once")
      ->check(CLI::Range(1, kMaxJobs))
      ->capture_default_str();
  command.add_option("--timeout", c.timeout, "Seconds FOSSSim may run on one scene")
      ->check(finite_number(0.0, kMaxTimeoutSeconds))
      ->capture_default_str();
  command.add_option("--work-dir", c.work_dir, "Where the per-scene temporary folders go");
}

}  // namespace
}  // namespace fosssim

int main(int argc, char** argv) {
  using namespace fosssim;
  CLI::App app{
      "fosssim-oracle: grades any simulator that speaks the course's command line\n"
      "(CANDIDATE -s SCENE -d 0 -o FILE) with the course's exact criteria",
      "fosssim-oracle"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "fosssim-oracle 0.1.0");
  GradeCommand grade;
  MergeCommand merge;
  ManifestCommand manifest;
  add_grade_command(app, grade);
  add_merge_command(app, merge);
  CLI::App* manifest_command = app.add_subcommand(
      "manifest", "The regression store of FOSSSim's own trajectories (oracle/manifest)");
  manifest_command->require_subcommand(1);
  CLI::App* update = manifest_command->add_subcommand(
      "update", "Run FOSSSim on every scene and rewrite the manifest");
  CLI::App* check = manifest_command->add_subcommand(
      "check", "Run FOSSSim on every scene and compare with the manifest");
  add_manifest_options(*update, manifest);
  add_manifest_options(*check, manifest);
  app.footer(
      "Exit status: 0 every scene passed (manifest: matches); 1 some scene failed (manifest:\n"
      "differs); 2 bad command line, folder or result file; 4 a report could not be written;\n"
      "130 interrupted.\n\n"
      "Examples:\n"
      "  fosssim-oracle grade --candidate build/release/bin/FOSSSim -j 2 assets \\\n"
      "      --extra-credit extracreditassets --junit junit.xml --gradescope results.json\n"
      "  fosssim-oracle grade --candidate ./student --shard 3/8 --shard-result s3.json assets\n"
      "  fosssim-oracle merge s*.json --junit junit.xml --gradescope results.json\n"
      "  fosssim-oracle manifest check --candidate build/release/bin/FOSSSim assets "
      "extracreditassets");
  if (auto status = parse_command_line(
          app, argc, argv,
          "Run fosssim-oracle --help (or fosssim-oracle COMMAND --help) for the options.")) {
    return *status;
  }
  try {
    if (app.got_subcommand("grade")) return run_grade(grade);
    if (app.got_subcommand("merge")) return run_merge(merge);
    if (update->parsed()) return run_manifest_update(manifest);
    if (check->parsed()) return run_manifest_check(manifest);
  } catch (const Error& error) {
    std::cerr << "fosssim-oracle: error: " << error.what() << "\n";
    return exit_status(error.kind());
  } catch (const std::exception& error) {
    std::cerr << "fosssim-oracle: error: " << error.what() << "\n";
    return kExitBadInput;
  }
  return kExitBadInput;
}
