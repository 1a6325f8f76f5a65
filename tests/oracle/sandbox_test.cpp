// The sandbox of oracle/src/sandbox.h: its command line, and a hostile candidate that tries to
// write outside its folder, rewrite the suite, read a file outside, use the network and leave a
// daemon behind, with and without the sandbox (without it, every attempt must succeed, which
// shows that the checks can fail).

#include "sandbox.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>

#include "batch.h"
#include "scene_grading.h"
#include "test_support.h"
#include "core/sanitizers.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;
using testing::TemporaryFolder;

bool sandbox_text_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::ptrdiff_t position_of(const std::vector<std::string>& args, const std::string& value) {
  return std::find(args.begin(), args.end(), value) - args.begin();
}

TEST(SandboxedCommand, BindsOnlyWhatItIsGivenAfterThePrivateTmp) {
  SandboxLayout layout;
  layout.bwrap = "/usr/bin/bwrap";
  layout.read_only = {"/tmp/candidate", "/data/suite"};
  layout.writable = "/tmp/work/run";
  layout.scratch_bytes = 1 << 20;
  const auto args = sandboxed_command(layout, {"/tmp/candidate/sim", "-s", "x.xml"});
  ASSERT_GE(args.size(), 4u);
  EXPECT_EQ(args[0], "/usr/bin/bwrap");
  for (const char* flag : {"--unshare-all", "--die-with-parent", "--new-session"}) {
    EXPECT_LT(position_of(args, flag), position_of(args, "--")) << flag;
  }
  const auto tmp = position_of(args, "/tmp");  // --tmpfs /tmp comes before the binds under it
  EXPECT_LT(tmp, position_of(args, "/tmp/candidate"));
  EXPECT_LT(tmp, position_of(args, "/tmp/work/run"));
  EXPECT_EQ(args[position_of(args, "/tmp/candidate") - 1], "--ro-bind");
  EXPECT_EQ(args[position_of(args, "/data/suite") - 1], "--ro-bind");
  EXPECT_EQ(args[position_of(args, "/tmp/work/run") - 1], "--bind");
  EXPECT_EQ(std::count(args.begin(), args.end(), "--bind"), 1);  // one writable folder
  const std::vector<std::string> tail(args.end() - 4, args.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"--", "/tmp/candidate/sim", "-s", "x.xml"}));
}

TEST(SandboxUnavailable, NamesTheProblem) {
  TemporaryFolder scratch;
  EXPECT_EQ(sandbox_unavailable(resolve_executable("bwrap"), scratch.path()), std::nullopt)
      << "this machine (and CI) can sandbox";
  const auto missing = sandbox_unavailable("", scratch.path());
  ASSERT_TRUE(missing);
  EXPECT_TRUE(sandbox_text_contains(*missing, "bubblewrap")) << *missing;
  const auto broken = sandbox_unavailable("/bin/false", scratch.path());
  ASSERT_TRUE(broken);
  EXPECT_TRUE(sandbox_text_contains(*broken, "cannot build the sandbox")) << *broken;
}

/// A TCP socket listening on 127.0.0.1, non-blocking; closed when destroyed.
class Listener {
 public:
  Listener() {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof(address);
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&address), size) != 0 ||
        ::listen(fd_, 8) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
      throw std::runtime_error("cannot listen on 127.0.0.1");
    }
    port_ = ntohs(address.sin_port);
  }
  ~Listener() { ::close(fd_); }
  int port() const { return port_; }
  /// True when someone connected.
  bool connected() {
    const int client = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (client < 0) return false;
    ::close(client);
    return true;
  }

 private:
  int fd_ = -1;
  int port_ = 0;
};

/// A hostile run: a copy of the two chain scenes, the hostile candidate's targets, and the
/// results of grading both scenes with it.
struct HostileRun {
  TemporaryFolder suite, outside, secret_folder, work;
  Listener listener;
  std::string token = "3000." + std::to_string(::getpid());
  std::vector<SceneEntry> scenes;
  std::vector<SceneResult> results;
  std::string original_bytes;

  explicit HostileRun(bool sandbox) {
    fs::copy(testing::kAssets + "/basics", suite / "basics");
    testing::write_bytes(secret_folder / "secret.txt", "the-secret-" + token);
    testing::set_env("FOSSSIM", testing::kFossSim);
    testing::set_env("HOSTILE_OUTSIDE", outside.path());
    testing::set_env("HOSTILE_REPLACEMENT", testing::kAssets + "/implicit/orbit_implicit.xml");
    testing::set_env("HOSTILE_SECRET", secret_folder / "secret.txt");
    testing::set_env("HOSTILE_PORT", std::to_string(listener.port()));
    testing::set_env("HOSTILE_TOKEN", token);
    original_bytes = testing::read_bytes(suite / "basics/spring_chain_symplectic.xml");
    scenes = discover_scenes({suite / "basics"}, {});
    read_scene_files(scenes);  // as `fosssim-oracle grade` does before any candidate runs
    GradingOptions options;
    options.run.candidate = testing::candidate("hostile_candidate.sh");
    options.run.timeout_seconds = 30.0;
    options.run.sandbox = sandbox;
    options.run.readable = testing::sandbox_readable();
    options.work_dir = work.path();
    results = grade_scenes(scenes, options, 1);
  }
  ~HostileRun() {  // the daemon escapes without the sandbox; it is ours to end
    for (int pid : testing::processes_with_argument(token)) ::kill(pid, SIGKILL);
  }
};

TEST(Sandbox, HostileCandidateEscapesNothingAndStillRunsFossSim) {
  HostileRun run(/*sandbox=*/true);
  ASSERT_EQ(run.results.size(), 2u);
  for (const SceneResult& r : run.results) {
    // FOSSSim itself ran in the sandbox (its libraries, its scene) and passed.
    EXPECT_EQ(r.verdict, Verdict::kPassed) << r.name << ": " << r.reason << "\n" << r.stderr_tail;
    EXPECT_FALSE(sandbox_text_contains(r.stderr_tail, "ESCAPED")) << r.stderr_tail;
    EXPECT_FALSE(sandbox_text_contains(r.stderr_tail, "the-secret-")) << r.stderr_tail;
  }
  EXPECT_FALSE(fs::exists(run.outside / "escaped"));
  EXPECT_EQ(testing::read_bytes(run.suite / "basics/spring_chain_symplectic.xml"),
            run.original_bytes);
  EXPECT_FALSE(run.listener.connected());
  EXPECT_EQ(testing::wait_for_processes_to_end(run.token, 2.0), std::vector<int>{})
      << "the setsid daemon survived the sandbox";
}

TEST(Sandbox, WithoutItTheCandidateEscapesButIsGradedOnTheOraclesCopyOfTheScenes) {
  HostileRun run(/*sandbox=*/false);
  ASSERT_EQ(run.results.size(), 2u);
  EXPECT_TRUE(fs::exists(run.outside / "escaped"));
  EXPECT_NE(testing::read_bytes(run.suite / "basics/spring_chain_symplectic.xml"),
            run.original_bytes);
  EXPECT_TRUE(sandbox_text_contains(run.results[0].stderr_tail, "the-secret-"))
      << run.results[0].stderr_tail;
  EXPECT_TRUE(run.listener.connected());
  EXPECT_FALSE(testing::processes_with_argument(run.token).empty());
  // The candidate simulated the rewritten scenes, but each scene is graded against the copy the
  // oracle read before any candidate ran: a rewrite cannot turn a run into a pass.
  for (const SceneResult& r : run.results) {
    EXPECT_NE(r.verdict, Verdict::kPassed) << r.name;
    EXPECT_EQ(r.particles, 4) << r.name;  // the chain's, not the replacement's
  }
}

TEST(Sandbox, TheCandidateRunsUnderTheLimitsWithTheTimeoutAsItsCpuTime) {
  TemporaryFolder work;
  testing::write_bytes(work / "limits.sh",
                       "#!/bin/sh\necho \"cpu $(ulimit -t) memory $(ulimit -v) file $(ulimit -f)\" "
                       ">&2\nexit 3\n");
  fs::permissions(work / "limits.sh", fs::perms::owner_all);
  GradingOptions options;
  options.run.candidate = work / "limits.sh";
  options.run.timeout_seconds = 29.5;
  options.run.max_memory_bytes = std::int64_t(512) << 20;
  options.work_dir = work.path();
  const SceneResult r = grade_scene({"basics/chain.xml", testing::kChainScene}, options);
  EXPECT_EQ(r.verdict, Verdict::kExitStatus) << r.reason;
  // 64 MiB, the least file limit, in the shell's 512-byte blocks.
  EXPECT_EQ(r.stderr_tail, "cpu 31 memory 524288 file 131072");
}

TEST(Sandbox, TooManyProcessesStopTheCandidate) {
  TemporaryFolder work;
  GradingOptions options;
  options.run.candidate = testing::candidate("forking_candidate.sh");
  options.run.timeout_seconds = 20.0;
  options.run.max_processes = 8;
  options.work_dir = work.path();
  const SceneResult r = grade_scene({"basics/chain.xml", testing::kChainScene}, options);
  EXPECT_NE(r.verdict, Verdict::kPassed);
  EXPECT_TRUE(sandbox_text_contains(r.reason, "more than the limit of 8")) << r.reason;
  EXPECT_LT(r.run_seconds, 4.0);
}

TEST(Sandbox, MemoryLimitStopsALargeAllocation) {
#if FOSSSIM_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
  TemporaryFolder work;
  testing::write_bytes(work / "big.xml", R"(<scene dim="3"><duration time="0.05"/>
<integrator type="linearly-implicit-euler" dt="0.01"/>
<generate type="cloth" nx="250" ny="250" k="1" m="1"/></scene>)");
  GradingOptions options;
  options.run.candidate = testing::kFossSim;
  options.run.timeout_seconds = 60.0;
  options.run.max_memory_bytes = std::int64_t(300) << 20;
  options.work_dir = work.path();
  const SceneResult r = grade_scene({"x/big.xml", work / "big.xml"}, options);
  EXPECT_EQ(r.verdict, Verdict::kExitStatus) << r.reason << "\n" << r.stderr_tail;
  EXPECT_TRUE(sandbox_text_contains(r.stderr_tail, "out of memory")) << r.stderr_tail;
}

}  // namespace
}  // namespace fosssim
