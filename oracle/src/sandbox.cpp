#include "sandbox.h"

#include <sys/stat.h>

#include <filesystem>

#include "child_process.h"
#include "printable_text.h"

namespace fosssim {

namespace fs = std::filesystem;

std::vector<std::string> sandbox_system_arguments() {
  std::vector<std::string> args = {"--ro-bind", "/usr", "/usr"};
  // On a merged /usr these are symbolic links into it; elsewhere real folders.
  for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code error;
    const fs::file_status status = fs::symlink_status(top, error);
    if (error || !fs::exists(status)) continue;
    if (fs::is_symlink(status)) {
      const fs::path target = fs::read_symlink(top, error);
      if (!error) args.insert(args.end(), {"--symlink", target.string(), top});
    } else if (fs::is_directory(status)) {
      args.insert(args.end(), {"--ro-bind", top, top});
    }
  }
  // The loader's cache and configuration, the alternatives that name the BLAS library, the
  // time zone, and the user names that some runtimes look up. Missing ones are skipped.
  for (const char* file : {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d",
                           "/etc/alternatives", "/etc/localtime", "/etc/passwd", "/etc/group"}) {
    args.insert(args.end(), {"--ro-bind-try", file, file});
  }
  return args;
}

std::vector<std::string> sandboxed_command(const SandboxLayout& layout,
                                           const std::vector<std::string>& command) {
  const std::string scratch = std::to_string(layout.scratch_bytes);
  std::vector<std::string> args = {layout.bwrap,    "--unshare-all", "--die-with-parent",
                                   "--new-session", "--cap-drop",    "ALL"};
  const std::vector<std::string> system = sandbox_system_arguments();
  args.insert(args.end(), system.begin(), system.end());
  args.insert(args.end(),
              {"--proc", "/proc", "--dev", "/dev", "--size", scratch, "--tmpfs", "/dev/shm",
               "--remount-ro", "/dev", "--size", scratch, "--tmpfs", "/tmp"});
  for (const std::string& path : layout.read_only) {
    args.insert(args.end(), {"--ro-bind", path, path});
  }
  if (!layout.writable.empty()) {
    args.insert(args.end(),
                {"--bind", layout.writable, layout.writable, "--chdir", layout.writable});
  }
  // The root bwrap builds is an in-memory folder: read-only, so that nothing is written
  // outside the writable folder and the two size-limited ones.
  args.insert(args.end(), {"--setenv", "TMPDIR", "/tmp", "--remount-ro", "/", "--"});
  args.insert(args.end(), command.begin(), command.end());
  return args;
}

std::optional<std::string> sandbox_unavailable(const std::string& bwrap,
                                               const std::string& scratch_folder) {
  if (bwrap.empty()) {
    return "bubblewrap (bwrap) is not installed (Debian package `bubblewrap`)";
  }
  SandboxLayout layout;
  layout.bwrap = bwrap;
  layout.writable = scratch_folder;
  ChildLimits limits;
  limits.timeout_seconds = 30.0;
  const ChildOutcome outcome =
      run_child(sandboxed_command(layout, {"/bin/true"}), scratch_folder, limits);
  if (outcome.ending == ChildEnding::kExited && outcome.exit_status == 0) return std::nullopt;
  std::string why = first_line(printable_text(outcome.stderr_tail));
  if (outcome.ending == ChildEnding::kCannotStart) {
    why = "cannot start " + bwrap;
  } else if (why.empty()) {
    why = "bwrap failed without a message";
  }
  return "bubblewrap cannot build the sandbox on this machine: " + why;
}

}  // namespace fosssim
