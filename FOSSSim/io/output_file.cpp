#include "io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <utility>

#include "core/error.h"

namespace fosssim {

namespace {

/// How many unpredictable names are tried before giving up on a folder where each one is taken.
constexpr int kNameAttempts = 64;

std::string reason(int error) { return std::strerror(error); }

[[noreturn]] void refuse_output(const std::string& path, const std::string& problem) {
  throw Error(ErrorKind::kBadInput, "the output " + path + " " + problem);
}

/// Six characters no one can guess in advance.
std::string random_tag() {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[6];
  // getentropy, not getrandom: Emscripten's C library (the WebAssembly build) has only it.
  if (::getentropy(bytes, sizeof bytes) != 0) {
    std::random_device device;
    for (unsigned char& b : bytes) b = static_cast<unsigned char>(device());
  }
  std::string tag;
  for (unsigned char b : bytes) tag += kAlphabet[b % (sizeof kAlphabet - 1)];
  return tag;
}

/// The file a symbolic link names, with every link on the way resolved.
std::string resolved(const std::string& path) {
  char* real = ::realpath(path.c_str(), nullptr);
  if (real == nullptr) return path;
  std::string out(real);
  std::free(real);
  return out;
}

std::string link_text(const std::string& path) {
  char buffer[PATH_MAX];
  const ssize_t n = ::readlink(path.c_str(), buffer, sizeof buffer);
  return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : std::string("?");
}

bool in_place_kind(mode_t mode) { return S_ISCHR(mode) || S_ISFIFO(mode); }

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path), final_path_(path) {
  if (path.empty()) {
    throw Error(ErrorKind::kBadInput, "an output file name cannot be empty");
  }
  struct stat status {};
  if (::lstat(path.c_str(), &status) == 0 && S_ISLNK(status.st_mode)) {
    if (::stat(path.c_str(), &status) != 0) {
      refuse_output(path, "is a symbolic link to " + link_text(path) +
                              ", which does not exist; FOSSSim writes through a link only to an "
                              "existing file");
    }
    final_path_ = resolved(path);
  } else if (::stat(path.c_str(), &status) != 0) {
    status.st_mode = 0;  // nothing there yet (or unreachable: creating it will say why)
  }
  if (S_ISDIR(status.st_mode)) refuse_output(path, "is a folder");
  if (in_place_kind(status.st_mode)) {
    // O_NONBLOCK: a FIFO nobody reads fails at once (ENXIO) instead of blocking the run.
    fd_ = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) {
      const int error = errno;
      if (error == ENXIO) {
        throw Error(ErrorKind::kCannotWrite,
                    "cannot write " + path + ": it is a FIFO that no program is reading");
      }
      throw Error(ErrorKind::kCannotWrite, "cannot open " + path + ": " + reason(error));
    }
    struct stat opened {};
    if (::fstat(fd_, &opened) != 0 || !in_place_kind(opened.st_mode)) {
      ::close(fd_);
      fd_ = -1;
      throw Error(ErrorKind::kCannotWrite, "cannot write " + path + ": it changed while opened");
    }
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    in_place_ = true;
    write_path_ = path;
    finished_ = false;
    return;
  }
  if (status.st_mode != 0 && !S_ISREG(status.st_mode)) {
    refuse_output(path, "is neither a regular file, a character device nor a FIFO");
  }
  for (int attempt = 0; attempt < kNameAttempts; ++attempt) {
    write_path_ = final_path_ + "." + random_tag() + ".partial";
    // Read and write: a movie is read back before it is renamed (pictures/movie_writer.h).
    fd_ = ::open(write_path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      finished_ = false;
      return;
    }
    if (errno != EEXIST) break;
  }
  const int error = errno;
  write_path_.clear();
  throw Error(ErrorKind::kCannotWrite, "cannot create " + path + ": " + reason(error));
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : path_(std::move(other.path_)),
      final_path_(std::move(other.final_path_)),
      write_path_(std::move(other.write_path_)),
      fd_(std::exchange(other.fd_, -1)),
      in_place_(other.in_place_),
      finished_(std::exchange(other.finished_, true)) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    if (!finished_) discard();
    path_ = std::move(other.path_);
    final_path_ = std::move(other.final_path_);
    write_path_ = std::move(other.write_path_);
    fd_ = std::exchange(other.fd_, -1);
    in_place_ = other.in_place_;
    finished_ = std::exchange(other.finished_, true);
  }
  return *this;
}

OutputFile::~OutputFile() {
  if (!finished_) discard();
  close_descriptor();
}

void OutputFile::close_descriptor() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::FILE* OutputFile::take_stream() {
  std::FILE* file = fd_ >= 0 ? ::fdopen(fd_, "wb") : nullptr;
  if (file == nullptr) {
    const int error = fd_ >= 0 ? errno : EBADF;
    discard();
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path_ + ": " + reason(error));
  }
  fd_ = -1;
  return file;
}

void OutputFile::commit() {
  if (finished_) return;
  if (fd_ >= 0) {
    // fsync makes the renamed file durable; devices and FIFOs do not take it.
    const bool synced = in_place_ || ::fsync(fd_) == 0;
    const int error = errno;
    const bool closed = ::close(fd_) == 0;
    fd_ = -1;
    if (!synced || !closed) {
      discard();
      throw Error(ErrorKind::kCannotWrite,
                  "cannot write " + path_ + ": " + reason(synced ? errno : error));
    }
  }
  finished_ = true;
  if (in_place_) return;
  if (::rename(write_path_.c_str(), final_path_.c_str()) != 0) {
    const int error = errno;
    ::unlink(write_path_.c_str());
    throw Error(ErrorKind::kCannotWrite,
                "cannot rename " + write_path_ + " to " + final_path_ + ": " + reason(error));
  }
}

std::string OutputFile::keep_unfinished(const std::string& suffix) {
  if (finished_) return "";
  close_descriptor();
  finished_ = true;
  if (in_place_) return write_path_;
  const std::string kept = final_path_ + suffix;
  if (::rename(write_path_.c_str(), kept.c_str()) == 0) return kept;
  ::unlink(write_path_.c_str());
  return "";
}

void OutputFile::discard() {
  close_descriptor();
  if (finished_) return;
  finished_ = true;
  if (!in_place_) ::unlink(write_path_.c_str());
}

bool output_is_in_place(const std::string& path) {
  struct stat status {};
  return !path.empty() && ::stat(path.c_str(), &status) == 0 && in_place_kind(status.st_mode);
}

bool write_all(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      if (written == 0) errno = EIO;
      return false;
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

void stream_output_file(const std::string& path, const std::function<void(std::FILE*)>& body) {
  OutputFile output(path);
  std::FILE* file = output.take_stream();
  try {
    body(file);
  } catch (...) {
    std::fclose(file);
    output.discard();
    throw;
  }
  const auto fail = [&](int error) {
    output.discard();
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path + ": " + reason(error));
  };
  errno = 0;
  if (std::fflush(file) != 0 || std::ferror(file) ||
      (!output.in_place() && ::fsync(::fileno(file)) != 0)) {
    const int error = errno != 0 ? errno : EIO;
    std::fclose(file);
    fail(error);
  }
  if (std::fclose(file) != 0) fail(errno);
  output.commit();
}

void write_output_file(const std::string& path, const std::string& content) {
  stream_output_file(
      path, [&content](std::FILE* file) { std::fwrite(content.data(), 1, content.size(), file); });
}

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& body) {
  std::ostringstream content;
  body(content);
  write_output_file(path, content.str());
}

}  // namespace fosssim
