#pragma once
// Confining a candidate with bubblewrap (bwrap, Debian's package `bubblewrap`): the command
// line that runs a program in fresh namespaces where it sees only the system's programs and
// libraries, its own folder and the scene read-only, and one private writable folder.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fosssim {

/// What one sandboxed run may see. Every path is absolute and appears at the same path inside.
struct SandboxLayout {
  std::string bwrap;                   ///< the bwrap executable
  std::vector<std::string> read_only;  ///< bound read-only (folders or files), in this order
  std::string writable;                ///< bound read-write; the working folder
  /// Size of each private in-memory folder (/tmp, /dev/shm), in bytes.
  std::int64_t scratch_bytes = std::int64_t(64) << 20;
};

/// The system folders a program needs to start, bound read-only: /usr and the top-level
/// folders that point into it (or are real folders on systems without the merged /usr), and
/// the few files of /etc that the dynamic loader and libraries read.
std::vector<std::string> sandbox_system_arguments();

/// The command that runs `command` (argv; command[0] an absolute path) confined by `layout`:
/// new user, PID, network, IPC, UTS and cgroup namespaces (no network but a loopback that is
/// down; every process dies with the sandbox's first process, setsid daemons included), no
/// capabilities, a new session, the system folders and `layout.read_only` read-only, a
/// private /proc and /dev, size-limited private /tmp and /dev/shm, `layout.writable`
/// read-write as the working folder, everything else read-only or absent, and the sandbox
/// killed when the process that started bwrap dies.
std::vector<std::string> sandboxed_command(const SandboxLayout& layout,
                                           const std::vector<std::string>& command);

/// Nothing when `bwrap` can build the sandbox on this machine (checked by running /bin/true
/// in it, in `scratch_folder`); otherwise why not, in one line, from bwrap's own message.
std::optional<std::string> sandbox_unavailable(const std::string& bwrap,
                                               const std::string& scratch_folder);

/// Exit statuses above this are how bwrap reports a sandboxed program killed by a signal:
/// 128 + the signal number.
constexpr int kSandboxSignalBase = 128;

}  // namespace fosssim
