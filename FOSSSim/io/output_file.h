#pragma once
// Outputs appear whole or not at all, without ever replacing a device or a link.

#include <cstdio>
#include <functional>
#include <ostream>
#include <string>

namespace fosssim {

/// Where and how to write the output file `path`:
/// - a new or regular file is written as "<path>.partial" beside it and renamed over it by
///   commit(), so `path` is never seen half written;
/// - if `path` is a symbolic link, the file it points to is the one replaced (the link stays);
/// - a `path` that exists but is not a regular file (/dev/null, /dev/stdout on a terminal or a
///   pipe, a FIFO) is written in place: renaming over it would replace the device itself.
class OutputFile {
 public:
  explicit OutputFile(const std::string& path);

  /// The name to open for writing now.
  const std::string& write_path() const { return write_path_; }
  /// True when the output is written directly (a device or FIFO), without rename.
  bool in_place() const { return in_place_; }

  /// Renames the finished temporary file into place; nothing in place. Throws Error
  /// (kCannotWrite) naming both names and the reason (the temporary file is then removed).
  void commit() const;
  /// Keeps an unfinished output as "<final path><suffix>" and returns that name; in place,
  /// returns the path written to. Returns "" when there was nothing to keep.
  std::string keep_unfinished(const std::string& suffix = ".incomplete") const;
  /// Removes the temporary file of a failed output; nothing in place.
  void discard() const;

 private:
  std::string final_path_, write_path_;
  bool in_place_ = false;
};

/// Writes `content` to `path` through an OutputFile (a regular file is also flushed to disk
/// before the rename). Throws Error (kCannotWrite) naming the file and the system's reason; a
/// failed output leaves no file behind.
void write_output_file(const std::string& path, const std::string& content);

/// The same for what `body` streams.
void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& body);

/// The same for what `body` writes straight to the open file (with std::fwrite and the like),
/// so that an output of any size is never held in memory. Write errors are found when the file
/// is flushed; what `body` throws removes the temporary file and is thrown again.
void stream_output_file(const std::string& path, const std::function<void(std::FILE*)>& body);

}  // namespace fosssim
