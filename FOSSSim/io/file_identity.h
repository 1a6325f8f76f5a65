#pragma once
// Telling whether two names are the same file, so that an output never replaces an input.

#include <sys/types.h>

#include <optional>
#include <string>

namespace fosssim {

/// A file's identity on this machine: its device and inode, the same under every name it has
/// (hard links, "./x" and "x", symbolic links to it).
struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileIdentity&) const = default;
};

/// The identity of the file at `path`, following symbolic links; nothing when no file is there.
std::optional<FileIdentity> file_identity(const std::string& path);

}  // namespace fosssim
