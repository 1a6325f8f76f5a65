#include "io/input_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/page_population.h"

namespace fosssim {

namespace {

/// What a file that is not regular is, for messages; nullptr for a regular file.
const char* irregular_kind(mode_t mode) {
  if (S_ISREG(mode)) return nullptr;
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  return "is not a regular file";
}

[[noreturn]] void refuse_input(const std::string& path, const std::string& problem) {
  throw SceneError(path, 0, "", problem);
}

std::string file_limit_problem(std::int64_t max_bytes) {
  constexpr std::int64_t kMiB = std::int64_t{1} << 20;
  return "the file is " + (max_bytes % kMiB == 0
                               ? over_limit(max_bytes / kMiB, "MiB", "--max-file-size")
                               : over_limit(max_bytes, "bytes", "--max-file-size"));
}

}  // namespace

RegularFile open_regular_file(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    refuse_input(path, std::string("cannot open the file: ") + std::strerror(errno));
  }
  if (const char* kind = irregular_kind(status.st_mode)) refuse_input(path, kind);
  // Without O_NONBLOCK, opening a FIFO that replaced the file since stat() would wait for a
  // writer; the descriptor is checked again below.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) refuse_input(path, std::string("cannot open the file: ") + std::strerror(errno));
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    const char* kind = irregular_kind(status.st_mode);
    ::close(fd);
    refuse_input(path, kind != nullptr ? kind : "cannot read the file");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::FILE* stream = ::fdopen(fd, "rb");
  if (stream == nullptr) {
    ::close(fd);
    refuse_input(path, std::string("cannot open the file: ") + std::strerror(errno));
  }
  RegularFile file;
  file.stream.reset(stream);
  file.size = static_cast<std::int64_t>(status.st_size);
  return file;
}

std::string read_text_file(const std::string& path, std::int64_t max_bytes) {
  const RegularFile file = open_regular_file(path);
  if (file.size > max_bytes) refuse_input(path, file_limit_problem(max_bytes));
  // Read straight into the string, at the size stat() gave, its pages mapped at once (one
  // copy of a 2.6 MB scene, not two through a buffer, and no page faults one by one); a file
  // that grew since is read on through a buffer, within max_bytes.
  std::string content;
  content.reserve(static_cast<std::size_t>(file.size));
  populate_pages(content.data(), content.capacity());
  content.resize(static_cast<std::size_t>(file.size));
  content.resize(std::fread(content.data(), 1, content.size(), file.stream.get()));
  char more[1 << 12];
  for (std::size_t n; (n = std::fread(more, 1, sizeof more, file.stream.get())) > 0;) {
    if (static_cast<std::int64_t>(content.size() + n) > max_bytes) {
      refuse_input(path, file_limit_problem(max_bytes));
    }
    content.append(more, n);
  }
  if (std::ferror(file.stream.get())) {
    refuse_input(path, std::string("cannot read the file: ") + std::strerror(errno));
  }
  return content;
}

InputFiles InputFiles::in_memory(std::map<std::string, std::string> files, const Limits& limits) {
  InputFiles inputs(limits);
  inputs.memory_ = std::move(files);
  return inputs;
}

std::string InputFiles::read(const std::string& path) {
  paths_.push_back(path);
  if (!memory_) return read_text_file(path, limits_.max_file_bytes);
  const auto found = memory_->find(path);
  if (found == memory_->end())
    refuse_input(path, "cannot open the file: No such file or directory");
  if (static_cast<std::int64_t>(found->second.size()) > limits_.max_file_bytes) {
    refuse_input(path, file_limit_problem(limits_.max_file_bytes));
  }
  return found->second;
}

}  // namespace fosssim
