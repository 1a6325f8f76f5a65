#include "pictures/movie_writer.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "pictures/file_names.h"

extern char** environ;

namespace fosssim {

namespace {

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

/// ffmpeg's command line: raw frames on standard input, an MP4 file at `output`.
std::vector<std::string> ffmpeg_arguments(const std::string& program, const MovieSettings& s,
                                          const std::string& output) {
  // Cairo's ARGB32 pixels are native-endian 32-bit words.
  const char* pixel_format = std::endian::native == std::endian::little ? "bgra" : "argb";
  return {program,
          "-hide_banner",
          "-loglevel",
          "error",
          "-y",
          "-f",
          "rawvideo",
          "-pixel_format",
          pixel_format,
          "-video_size",
          std::to_string(s.width) + "x" + std::to_string(s.height),
          "-framerate",
          format_number(s.fps),
          "-i",
          "pipe:0",
          "-an",
          "-c:v",
          "libx264",
          "-preset",
          "medium",
          "-tune",
          "animation",
          "-crf",
          std::to_string(s.crf),
          "-pix_fmt",
          "yuv420p",
          "-movflags",
          "+faststart",
          "-f",
          "mp4",
          output};
}

/// The last lines of ffmpeg's standard error, for messages.
std::string read_log(std::FILE* log) {
  if (log == nullptr) return "";
  std::fflush(log);
  std::rewind(log);
  std::string text;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, log)) > 0) text.append(buffer, n);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  constexpr std::size_t kKeep = 1500;
  if (text.size() > kKeep) text = "..." + text.substr(text.size() - kKeep);
  return text;
}

}  // namespace

std::string mp4_damage(int fd) {
  struct stat status {};
  if (fd < 0 || ::fstat(fd, &status) != 0) return "it cannot be read back";
  if (!S_ISREG(status.st_mode)) return "";  // a device or FIFO cannot be read back
  const auto size = static_cast<std::uint64_t>(status.st_size);
  const auto read_at = [fd](std::uint64_t offset, unsigned char* out, std::size_t n) {
    return ::pread(fd, out, n, static_cast<off_t>(offset)) == static_cast<ssize_t>(n);
  };
  const auto big_endian = [](const unsigned char* b, int n) {
    std::uint64_t value = 0;
    for (int k = 0; k < n; ++k) value = value << 8 | b[k];
    return value;
  };
  if (size == 0) return "it is empty";
  bool movie_box = false;
  std::uint64_t offset = 0;
  // Each box takes at least 8 bytes, so this loop ends within size / 8 turns.
  while (offset < size) {
    unsigned char header[16];
    if (size - offset < 8 || !read_at(offset, header, 8)) {
      return "it ends inside a box header at byte " + std::to_string(offset);
    }
    std::uint64_t box = big_endian(header, 4);
    const std::string type(reinterpret_cast<const char*>(header + 4), 4);
    std::uint64_t header_bytes = 8;
    if (box == 1) {
      if (size - offset < 16 || !read_at(offset + 8, header + 8, 8)) {
        return "it ends inside the '" + type + "' box header";
      }
      box = big_endian(header + 8, 8);
      header_bytes = 16;
    } else if (box == 0) {
      box = size - offset;
    }
    if (offset == 0 && type != "ftyp") return "it does not begin with an 'ftyp' box";
    if (box < header_bytes || box > size - offset) {
      return "its '" + type + "' box at byte " + std::to_string(offset) + " is cut short";
    }
    if (type == "moov") movie_box = true;
    offset += box;
  }
  return movie_box ? "" : "it has no 'moov' box (the index of its frames)";
}

void check_movie_settings(const std::string& path, const MovieSettings& s) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  if (!has_extension(path, ".mp4")) {
    fail("the movie " + path + " must be named *.mp4 (FOSSSim writes H.264 in MP4)");
  }
  if (s.width < 2 || s.height < 2 || s.width % 2 != 0 || s.height % 2 != 0) {
    fail(
        "a movie's width and height must be even and at least 2 (H.264 with 4:2:0 colour), "
        "found " +
        std::to_string(s.width) + "x" + std::to_string(s.height));
  }
  if (!(s.fps > 0.0) || s.fps > 1000.0) {
    fail("a movie's frame rate must be in (0, 1000] frames per second, found " +
         format_number(s.fps));
  }
}

std::optional<std::string> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const std::filesystem::path candidate =
        (directory.empty() ? std::filesystem::current_path() : std::filesystem::path(directory)) /
        name;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate)) {
      return candidate.string();
    }
  }
  return std::nullopt;
}

MovieWriter MovieWriter::open(const std::string& path, const MovieSettings& settings) {
  check_movie_settings(path, settings);
  const auto program = find_program("ffmpeg");
  if (!program) {
    throw Error(ErrorKind::kCannotWrite,
                "writing a movie needs the ffmpeg program, which is not on PATH "
                "(on Debian: apt-get install ffmpeg)");
  }
  // A dead ffmpeg must turn our next write into an EPIPE error, not kill FOSSSim. A handler
  // already installed (app/interrupt.h) stays: it only records the signal.
  struct sigaction pipe_action {};
  if (::sigaction(SIGPIPE, nullptr, &pipe_action) == 0 && pipe_action.sa_handler == SIG_DFL) {
    std::signal(SIGPIPE, SIG_IGN);
  }

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot create a pipe: " + std::string(std::strerror(errno)));
  }
  OutputFile output(path);
  // ffmpeg writes the file FOSSSim created exclusively, reached through the descriptor it
  // inherits as 3, never by a name that could be swapped meanwhile.
  const int movie_fd = ::fcntl(output.descriptor(), F_DUPFD_CLOEXEC, 10);
  if (movie_fd < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path + ": " + std::strerror(error));
  }
  std::FILE* log = std::tmpfile();
  const auto arguments = ffmpeg_arguments(*program, settings, "/dev/fd/3");
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (log != nullptr) posix_spawn_file_actions_adddup2(&actions, fileno(log), STDERR_FILENO);
  posix_spawn_file_actions_adddup2(&actions, movie_fd, 3);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
  pid_t pid = -1;
  const int spawned =
      posix_spawn(&pid, program->c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(fds[0]);
  ::close(movie_fd);
  if (spawned != 0) {
    ::close(fds[1]);
    if (log != nullptr) std::fclose(log);
    throw Error(ErrorKind::kCannotWrite,
                "cannot start " + *program + ": " + std::strerror(spawned));
  }
  return MovieWriter(path, std::move(output), settings, pid, fds[1], log);
}

MovieWriter::MovieWriter(std::string path, OutputFile output, MovieSettings settings, pid_t pid,
                         int pipe, std::FILE* log)
    : path_(std::move(path)),
      output_(std::move(output)),
      settings_(settings),
      pid_(pid),
      pipe_(pipe),
      log_(log) {}

MovieWriter::MovieWriter(MovieWriter&& other) noexcept
    : path_(std::move(other.path_)),
      output_(std::move(other.output_)),
      settings_(other.settings_),
      pid_(other.pid_),
      pipe_(other.pipe_),
      log_(other.log_),
      frames_(other.frames_),
      done_(other.done_) {
  other.pid_ = -1;
  other.pipe_ = -1;
  other.log_ = nullptr;
  other.done_ = true;
}

MovieWriter::~MovieWriter() {
  if (!done_) abandon();
  if (log_ != nullptr) std::fclose(log_);
}

void MovieWriter::write_frame(const Image& frame) {
  if (frame.width != settings_.width || frame.height != settings_.height) {
    throw std::logic_error("movie frame of the wrong size");
  }
  const char* data = reinterpret_cast<const char*>(frame.pixels.data());
  std::size_t left = frame.pixels.size() * sizeof(std::uint32_t);
  while (left > 0) {
    const ssize_t written = ::write(pipe_, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const auto message = finish_process();
      done_ = true;
      output_.discard();
      throw Error(ErrorKind::kCannotWrite, "ffmpeg stopped while writing " + path_ + ": " +
                                               message.value_or("it closed its input"));
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  ++frames_;
}

std::optional<std::string> MovieWriter::finish_process() {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  if (pid_ < 0) return std::nullopt;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::nullopt;
  std::string message = WIFEXITED(status)
                            ? "ffmpeg exited with status " + std::to_string(WEXITSTATUS(status))
                            : "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
  const std::string log = read_log(log_);
  return log.empty() ? message : message + ":\n" + log;
}

void MovieWriter::commit() {
  done_ = true;
  std::optional<std::string> problem = finish_process();
  // ffmpeg can report success for a file the disk could not hold: look at the file itself.
  if (!problem) {
    const std::string damage = mp4_damage(output_.descriptor());
    if (!damage.empty()) problem = "the file ffmpeg wrote is incomplete: " + damage;
  }
  if (problem) {
    output_.discard();
    throw Error(ErrorKind::kCannotWrite, "cannot write the movie " + path_ + ": " + *problem);
  }
  output_.commit();
}

std::string MovieWriter::abandon() {
  done_ = true;
  // Closing ffmpeg's input lets it finish a playable file of the frames it has.
  const bool ok = !finish_process().has_value();
  if (ok && frames_ > 0) return output_.keep_unfinished();
  output_.discard();
  return "";
}

}  // namespace fosssim
