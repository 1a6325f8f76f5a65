#include "io/trajectory_file.h"

#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace fosssim {

namespace {

static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big,
              "mixed-endian machines are not supported");

/// Reverses the bytes of each double when the machine is big-endian (the file is little-endian).
void to_little_endian(double* data, std::size_t count) {
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t k = 0; k < count; ++k) {
      auto* bytes = reinterpret_cast<unsigned char*>(data + k);
      for (int b = 0; b < 4; ++b) std::swap(bytes[b], bytes[7 - b]);
    }
  } else {
    (void)data;
    (void)count;
  }
}

std::string system_reason() { return std::strerror(errno); }

}  // namespace

// ---- TrajectoryWriter -------------------------------------------------------------------------

TrajectoryWriter::TrajectoryWriter(std::string path, OutputFile output, std::FILE* file)
    : path_(std::move(path)), output_(std::move(output)), file_(file) {}

TrajectoryWriter::TrajectoryWriter(TrajectoryWriter&& other) noexcept
    : path_(std::move(other.path_)),
      output_(std::move(other.output_)),
      file_(other.file_),
      finished_(other.finished_) {
  other.file_ = nullptr;
  other.finished_ = true;
}

TrajectoryWriter& TrajectoryWriter::operator=(TrajectoryWriter&& other) noexcept {
  if (this != &other) {
    if (!finished_) abandon();
    path_ = std::move(other.path_);
    output_ = std::move(other.output_);
    file_ = other.file_;
    finished_ = other.finished_;
    other.file_ = nullptr;
    other.finished_ = true;
  }
  return *this;
}

TrajectoryWriter::~TrajectoryWriter() {
  if (!finished_) abandon();
}

TrajectoryWriter TrajectoryWriter::open(const std::string& path) {
  OutputFile output(path);
  std::FILE* file = std::fopen(output.write_path().c_str(), "wb");
  if (file == nullptr) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot create " + output.write_path() + ": " + system_reason());
  }
  std::setvbuf(file, nullptr, _IOFBF, 1 << 20);
  return TrajectoryWriter(path, std::move(output), file);
}

void TrajectoryWriter::write_doubles(const double* data, std::size_t count) {
  std::vector<double> swapped;
  if constexpr (std::endian::native == std::endian::big) {
    swapped.assign(data, data + count);
    to_little_endian(swapped.data(), count);
    data = swapped.data();
  }
  if (std::fwrite(data, sizeof(double), count, file_) != count) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot write " + output_.write_path() + ": " + system_reason());
  }
}

void TrajectoryWriter::write_frame(const State& state) {
  write_doubles(state.q.data(), static_cast<std::size_t>(state.q.size()));
  write_doubles(state.v.data(), static_cast<std::size_t>(state.v.size()));
}

void TrajectoryWriter::close_file() {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
}

void TrajectoryWriter::commit() {
  const std::string& partial = output_.write_path();
  // fsync makes the renamed file durable; devices such as /dev/null do not support it.
  if (std::fflush(file_) != 0 || (!output_.in_place() && ::fsync(fileno(file_)) != 0)) {
    throw Error(ErrorKind::kCannotWrite, "cannot write " + partial + ": " + system_reason());
  }
  if (std::fclose(file_) != 0) {
    file_ = nullptr;
    throw Error(ErrorKind::kCannotWrite, "cannot write " + partial + ": " + system_reason());
  }
  file_ = nullptr;
  output_.commit();
  finished_ = true;
}

std::string TrajectoryWriter::abandon() {
  close_file();
  finished_ = true;
  const std::string kept = output_.keep_unfinished(".incomplete");
  return kept.empty() ? output_.write_path() : kept;
}

// ---- TrajectoryReader -------------------------------------------------------------------------

TrajectoryReader::TrajectoryReader(std::string path, RegularFile file, int dofs)
    : path_(std::move(path)), file_(std::move(file)), dofs_(dofs) {
  const std::int64_t frame_bytes = trajectory_frame_bytes(dofs);
  if (frame_bytes == 0) {
    throw Error(ErrorKind::kBadInput,
                path_ + ": the scene has no particles, so its trajectory has nothing to read");
  }
  if (file_.size % frame_bytes != 0) {
    throw Error(ErrorKind::kBadInput,
                path_ + " has " + std::to_string(file_.size) +
                    " bytes, not a whole number of frames of " + std::to_string(frame_bytes) +
                    " bytes (" + std::to_string(dofs) +
                    " positions and velocities); it was cut short or is for another scene");
  }
  num_frames_ = file_.size / frame_bytes;
}

TrajectoryReader TrajectoryReader::open(const std::string& path, int dofs) {
  return TrajectoryReader(path, open_regular_file(path), dofs);
}

TrajectoryReader TrajectoryReader::from_bytes(std::string bytes, int dofs,
                                              const std::string& name) {
  auto held = std::make_shared<const std::string>(std::move(bytes));
  RegularFile file;
  file.size = static_cast<std::int64_t>(held->size());
  // fmemopen of an empty buffer fails; a one-byte buffer read as empty stands in for it.
  file.stream.reset(::fmemopen(const_cast<char*>(held->empty() ? "" : held->data()),
                               held->empty() ? 1 : held->size(), "rb"));
  if (file.stream == nullptr) {
    throw Error(ErrorKind::kBadInput, "cannot read " + name + ": " + system_reason());
  }
  TrajectoryReader reader(name, std::move(file), dofs);
  reader.bytes_ = std::move(held);
  return reader;
}

void TrajectoryReader::read_frame(std::int64_t k, Vector& q, Vector& v) {
  q.resize(dofs_);
  v.resize(dofs_);
  const std::int64_t offset = k * trajectory_frame_bytes(dofs_);
  const auto count = static_cast<std::size_t>(dofs_);
  std::FILE* file = file_.stream.get();
  if (k < 0 || k >= num_frames_ || std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
      std::fread(q.data(), sizeof(double), count, file) != count ||
      std::fread(v.data(), sizeof(double), count, file) != count) {
    throw Error(ErrorKind::kBadInput, "cannot read frame " + std::to_string(k) + " of " + path_);
  }
  to_little_endian(q.data(), count);
  to_little_endian(v.data(), count);
}

}  // namespace fosssim
