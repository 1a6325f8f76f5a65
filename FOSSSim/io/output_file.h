#pragma once
// Outputs appear whole or not at all, without ever replacing a device or a link, and without
// ever writing through a name someone else planted.

#include <cstdio>
#include <functional>
#include <ostream>
#include <string>

namespace fosssim {

/// One output file, open for writing. What happens depends on what `path` names now
/// (docs/limits-and-failures.md, 'Outputs'):
/// - nothing, or a regular file: a new temporary file with an unpredictable name
///   ("<path>.<random>.partial") is created exclusively beside it (O_CREAT | O_EXCL, so a link
///   or file planted under that name is never opened) and renamed over `path` by commit(), so
///   `path` is never seen half written;
/// - a symbolic link to an existing file: that file is the one replaced, through a temporary
///   file in its own folder; the link stays. A link to nothing (dangling) is refused;
/// - a character device (/dev/null, a terminal) or a FIFO is written in place: renaming over it
///   would replace the device itself. A FIFO is opened without waiting: one that nobody reads
///   is refused instead of hanging;
/// - an empty name, a folder, a block device or a socket is refused.
class OutputFile {
 public:
  /// Opens the output. Throws Error: kBadInput for a name that cannot be an output (empty, a
  /// folder, a dangling link, a block device, a socket), kCannotWrite when the file cannot be
  /// created or a FIFO has no reader; the message names `path` and the reason.
  explicit OutputFile(const std::string& path);
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Discards an output that was neither committed nor kept.
  ~OutputFile();

  /// The name given, for messages.
  const std::string& path() const { return path_; }
  /// The name being written now: the temporary file, or `path` in place.
  const std::string& write_path() const { return write_path_; }
  /// True when the output is written directly (a device or FIFO), without rename.
  bool in_place() const { return in_place_; }
  /// The open descriptor; -1 once take_stream() handed it over or the output was finished.
  int descriptor() const { return fd_; }

  /// A buffered stream on the descriptor, which it then owns: the caller closes it (fclose)
  /// before commit(). Throws Error (kCannotWrite) when none can be made.
  std::FILE* take_stream();

  /// Flushes a regular file to disk, closes the descriptor if still held and renames the
  /// temporary file into place; in place, only closes. Throws Error (kCannotWrite) naming the
  /// file and the reason (the temporary file is then removed).
  void commit();
  /// Keeps an unfinished output as "<final path><suffix>" and returns that name; in place,
  /// returns the path written to. Returns "" when there was nothing to keep.
  std::string keep_unfinished(const std::string& suffix = ".incomplete");
  /// Removes the temporary file of a failed output; in place, only closes.
  void discard();

 private:
  void close_descriptor();

  std::string path_, final_path_, write_path_;
  int fd_ = -1;
  bool in_place_ = false;
  bool finished_ = true;
};

/// True when `path` names something an output is written to in place (a character device or a
/// FIFO, directly or through links), so that no "<path>.incomplete" is ever made beside it.
bool output_is_in_place(const std::string& path);

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

/// Writes all `size` bytes of `data` to the descriptor `fd`, going on after signals; returns
/// false with errno set when the system refuses.
bool write_all(int fd, const void* data, std::size_t size);

}  // namespace fosssim
