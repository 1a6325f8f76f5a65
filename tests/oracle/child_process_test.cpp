#include "child_process.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;
using testing::write_bytes;

ChildLimits quick_limits(double timeout = 20.0) {
  ChildLimits limits;
  limits.timeout_seconds = timeout;
  return limits;
}

TEST(RunChild, CapturesOutputAndExitStatus) {
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "echo out; echo err >&2; exit 7"}, "/", quick_limits());
  EXPECT_EQ(outcome.ending, ChildEnding::kExited);
  EXPECT_EQ(outcome.exit_status, 7);
  EXPECT_EQ(outcome.stdout_tail, "out\n");
  EXPECT_EQ(outcome.stderr_tail, "err\n");
}

TEST(RunChild, RunsInTheWorkingFolderWithoutStandardInput) {
  TemporaryFolder folder;
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "pwd; cat; echo done"}, folder.path(), quick_limits());
  EXPECT_EQ(outcome.exit_status, 0);
  EXPECT_EQ(outcome.stdout_tail, std::filesystem::canonical(folder.path()).string() + "\ndone\n");
}

TEST(RunChild, KeepsOnlyTheTailOfALongOutput) {
  ChildLimits limits = quick_limits();
  limits.tail_bytes = 100;
  const ChildOutcome outcome = run_child(
      {"/bin/sh", "-c", "i=0; while [ $i -lt 2000 ]; do echo line $i; i=$((i+1)); done; echo last"},
      "/", limits);
  EXPECT_EQ(outcome.stdout_tail.size(), 100u);
  EXPECT_NE(outcome.stdout_tail.find("line 1999\nlast\n"), std::string::npos);
  EXPECT_GT(outcome.stdout_bytes, 10000);
}

TEST(RunChild, ReportsACrashBySignal) {
  const ChildOutcome outcome = run_child({"/bin/sh", "-c", "kill -SEGV $$"}, "/", quick_limits());
  EXPECT_EQ(outcome.ending, ChildEnding::kSignaled);
  EXPECT_EQ(outcome.signal, SIGSEGV);
  EXPECT_EQ(describe_signal(SIGSEGV), "SIGSEGV (Segmentation fault)");
}

/// True while the process exists and is not a zombie.
bool process_is_running(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text, command, state;
  if (!(stat >> pid_text >> command >> state)) return false;
  return state != "Z" && state != "X";
}

TEST(RunChild, TimeoutKillsTheWholeProcessGroup) {
  TemporaryFolder folder;
  const std::string pid_file = folder / "sleep.pid";
  const ChildOutcome outcome = run_child(
      {"/bin/sh", "-c", "sleep 1000 & echo $! > " + pid_file + "; wait"}, "/", quick_limits(0.5));
  EXPECT_EQ(outcome.ending, ChildEnding::kTimedOut);
  EXPECT_LT(outcome.seconds, 5.0);
  int sleeper = 0;
  std::ifstream(pid_file) >> sleeper;
  ASSERT_GT(sleeper, 0);
  for (int k = 0; k < 100 && process_is_running(sleeper); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_FALSE(process_is_running(sleeper)) << "the grandchild survived the timeout";
}

TEST(RunChild, KillsWhatTheChildLeftBehindWhenItExits) {
  TemporaryFolder folder;
  const std::string pid_file = folder / "sleep.pid";
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "sleep 1000 > /dev/null 2>&1 & echo $! > " + pid_file}, "/",
                quick_limits());
  EXPECT_EQ(outcome.ending, ChildEnding::kExited);
  int sleeper = 0;
  std::ifstream(pid_file) >> sleeper;
  ASSERT_GT(sleeper, 0);
  for (int k = 0; k < 100 && process_is_running(sleeper); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_FALSE(process_is_running(sleeper));
}

TEST(RunChild, FileSizeLimitStopsARunawayWriter) {
  TemporaryFolder folder;
  ChildLimits limits = quick_limits();
  limits.max_file_bytes = 1 << 16;
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "exec cat /dev/zero > big"}, folder.path(), limits);
  EXPECT_EQ(outcome.ending, ChildEnding::kSignaled);
  EXPECT_EQ(outcome.signal, SIGXFSZ);
  EXPECT_EQ(std::filesystem::file_size(folder / "big"), 1u << 16);
}

TEST(RunChild, SetsTheCpuAndAddressSpaceLimitsForEverythingTheChildStarts) {
  ChildLimits limits = quick_limits();
  limits.max_cpu_seconds = 7;
  limits.max_address_space_bytes = std::int64_t(1) << 30;
  // The shell reports the limits it inherited: CPU seconds, then address space in KiB.
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "ulimit -t; ulimit -v; sh -c 'ulimit -t'"}, "/", limits);
  EXPECT_EQ(outcome.exit_status, 0) << outcome.stderr_tail;
  EXPECT_EQ(outcome.stdout_tail, "7\n1048576\n7\n");
}

TEST(RunChild, TooManyProcessesAtOnceStopTheChild) {
  ChildLimits limits = quick_limits();
  limits.max_processes = 3;
  const ChildOutcome outcome =
      run_child({"/bin/sh", "-c", "for i in 1 2 3 4 5 6; do sleep 1000 & done; wait"}, "/", limits);
  EXPECT_EQ(outcome.ending, ChildEnding::kStoppedByWatch);
  EXPECT_NE(outcome.watch_message.find("more than the limit of 3"), std::string::npos)
      << outcome.watch_message;
  EXPECT_LT(outcome.seconds, 5.0);
}

TEST(RunChild, WatchCanStopTheChild) {
  ChildLimits limits = quick_limits();
  limits.watch = []() -> std::optional<std::string> { return "enough"; };
  const ChildOutcome outcome = run_child({"/bin/sleep", "1000"}, "/", limits);
  EXPECT_EQ(outcome.ending, ChildEnding::kStoppedByWatch);
  EXPECT_EQ(outcome.watch_message, "enough");
  EXPECT_LT(outcome.seconds, 5.0);
}

TEST(RunChild, ReportsAMissingOrNonExecutableProgram) {
  TemporaryFolder folder;
  const ChildOutcome missing = run_child({folder / "missing"}, "/", quick_limits());
  EXPECT_EQ(missing.ending, ChildEnding::kCannotStart);
  EXPECT_EQ(missing.start_step, "exec");
  EXPECT_EQ(missing.start_error, ENOENT);

  testing::write_bytes(folder / "script", "#!/bin/sh\necho hi\n");
  const ChildOutcome not_executable = run_child({folder / "script"}, "/", quick_limits());
  EXPECT_EQ(not_executable.ending, ChildEnding::kCannotStart);
  EXPECT_EQ(not_executable.start_error, EACCES);

  const ChildOutcome bad_folder = run_child({"/bin/true"}, folder / "nowhere", quick_limits());
  EXPECT_EQ(bad_folder.ending, ChildEnding::kCannotStart);
  EXPECT_EQ(bad_folder.start_step, "chdir");
}

TEST(RunChild, ManyChildrenAtOnceFromSeveralThreads) {
  std::vector<std::thread> threads;
  std::vector<int> statuses(8, -1);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([t, &statuses]() {
      const ChildOutcome outcome =
          run_child({"/bin/sh", "-c", "exit " + std::to_string(t)}, "/", quick_limits());
      statuses[t] = outcome.exit_status;
    });
  }
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < 8; ++t) EXPECT_EQ(statuses[t], t);
}

TEST(ResolveExecutable, SearchesThePathForABareName) {
  const std::string sh = resolve_executable("sh");
  ASSERT_FALSE(sh.empty());
  EXPECT_EQ(sh.front(), '/');
  EXPECT_EQ(resolve_executable("no-such-program-fosssim"), "");
  EXPECT_EQ(resolve_executable("/bin/../bin/sh"), "/bin/sh");
}

// Issue 23: a candidate in the current folder but not on PATH was reported as "does not exist".
TEST(ResolveExecutable, ANameFoundOnlyInTheCurrentFolderIsExplained) {
  TemporaryFolder folder;
  write_bytes(folder / "mysim-fosssim", "#!/bin/sh\nexit 0\n");
  ::chmod((folder / "mysim-fosssim").c_str(), 0755);
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(folder.path());
  EXPECT_EQ(resolve_executable("mysim-fosssim"), "");  // exec would not find it either
  const std::string here = why_not_found("mysim-fosssim");
  const std::string elsewhere = why_not_found("no-such-program-fosssim");
  const std::string missing = why_not_found("./no-such-program-fosssim");
  std::filesystem::current_path(previous);
  EXPECT_EQ(here,
            "is not on PATH; the current folder has one, so give ./mysim-fosssim (a name "
            "without a '/' is looked for in the PATH, never in the current folder)");
  EXPECT_EQ(elsewhere,
            "is not on PATH (give its path, such as ./no-such-program-fosssim, if it is not "
            "installed)");
  EXPECT_EQ(missing, "does not exist");
}

}  // namespace
}  // namespace fosssim
