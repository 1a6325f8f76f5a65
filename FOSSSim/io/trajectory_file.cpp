#include "io/trajectory_file.h"

#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <filesystem>
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

/// Reads a little-endian int32 at the file's position; false at the end of the file.
bool read_int(std::FILE* file, std::int32_t& value) {
  unsigned char bytes[4];
  if (std::fread(bytes, 1, 4, file) != 4) return false;
  value = static_cast<std::int32_t>(
      static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
      (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24));
  return true;
}

bool read_doubles(std::FILE* file, double* data, std::size_t count) {
  if (count == 0) return true;  // an empty polynomial: data may be null
  if (std::fread(data, sizeof(double), count, file) != count) return false;
  to_little_endian(data, count);
  return true;
}

}  // namespace

TrajectoryLayout trajectory_layout(const SceneModel& model) {
  switch (model.collisions.method) {
    case CollisionMethod::kSimple:
      return TrajectoryLayout::kCollisions;
    case CollisionMethod::kContinuousTime:
    case CollisionMethod::kHybrid:
      return TrajectoryLayout::kCollisionsAndPolynomials;
    case CollisionMethod::kNone:
    case CollisionMethod::kPenalty:
      break;
  }
  return TrajectoryLayout::kFrames;
}

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
  if (count == 0) return;  // an empty polynomial: data may be null
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

void TrajectoryWriter::write_int(std::int32_t value) {
  const auto u = static_cast<std::uint32_t>(value);
  const unsigned char bytes[4] = {static_cast<unsigned char>(u), static_cast<unsigned char>(u >> 8),
                                  static_cast<unsigned char>(u >> 16),
                                  static_cast<unsigned char>(u >> 24)};
  if (std::fwrite(bytes, 1, 4, file_) != 4) {
    throw std::runtime_error("cannot write " + output_.write_path() + ": " + system_reason());
  }
}

void TrajectoryWriter::write_record(TrajectoryLayout layout, const Vector& q, const Vector& v,
                                    const std::vector<CollisionRecord>& collisions,
                                    const std::vector<Polynomial>& polynomials) {
  write_doubles(q.data(), static_cast<std::size_t>(q.size()));
  write_doubles(v.data(), static_cast<std::size_t>(v.size()));
  if (layout == TrajectoryLayout::kFrames) return;
  write_int(static_cast<std::int32_t>(collisions.size()));
  for (const CollisionRecord& c : collisions) {
    write_int(static_cast<std::int32_t>(c.kind));
    write_int(c.first);
    write_int(c.second);
    write_doubles(c.normal.data(), static_cast<std::size_t>(c.normal.size()));
    write_doubles(&c.time, 1);
  }
  if (layout != TrajectoryLayout::kCollisionsAndPolynomials) return;
  write_int(static_cast<std::int32_t>(polynomials.size()));
  for (const Polynomial& p : polynomials) {
    const std::vector<double>& c = p.coefficients();
    write_int(static_cast<std::int32_t>(c.size()));
    write_doubles(c.data(), c.size());
  }
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

TrajectoryReader::TrajectoryReader(std::string path, std::FILE* file, int dofs, std::int64_t frames)
    : path_(std::move(path)), file_(file), dofs_(dofs), num_frames_(frames) {}

namespace {
/// Opens `path` for reading and gives its size in bytes; throws Error (kBadInput) naming the
/// path and the reason.
std::FILE* open_for_reading(const std::string& path, std::int64_t& size) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) fail(path + " is a directory, not a trajectory");
  size = static_cast<std::int64_t>(std::filesystem::file_size(path, error));
  if (error) fail("cannot read " + path + ": " + error.message());
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) fail("cannot open " + path + ": " + system_reason());
  return file;
}
}  // namespace

TrajectoryReader TrajectoryReader::open(const std::string& path, int dofs) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  std::int64_t size = 0;
  std::FILE* file = open_for_reading(path, size);
  const std::int64_t frame_bytes = trajectory_frame_bytes(dofs);
  const std::int64_t bytes = size;
  if (frame_bytes == 0 || bytes % frame_bytes != 0) {
    std::fclose(file);
    fail(path + " has " + std::to_string(bytes) + " bytes, not a whole number of frames of " +
         std::to_string(frame_bytes) + " bytes (" + std::to_string(dofs) +
         " positions and velocities); it was cut short or is for another scene");
  }
  return TrajectoryReader(path, file, dofs, bytes / frame_bytes);
}

TrajectoryReader TrajectoryReader::open(const std::string& path, int dofs, int dim,
                                        TrajectoryLayout layout) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  if (layout == TrajectoryLayout::kFrames) return open(path, dofs);
  std::int64_t size = 0;
  TrajectoryReader reader(path, open_for_reading(path, size), dofs, 0);
  std::FILE* file = reader.file_.get();
  reader.dim_ = dim;
  reader.layout_ = layout;
  const std::int64_t bytes = size;
  const std::int64_t frame_bytes = trajectory_frame_bytes(dofs);
  const std::int64_t record_bytes = collision_record_bytes(dim);
  std::int64_t at = 0;
  const auto cut_short = [&](const std::string& what) {
    fail(path + " ends inside record " + std::to_string(reader.offsets_.size()) + " (" + what +
         "); it was cut short or is not a trajectory of this scene");
  };
  while (at < bytes) {
    reader.offsets_.push_back(at);
    const std::string record = std::to_string(reader.offsets_.size() - 1);
    at += frame_bytes;
    std::int32_t count = 0;
    if (at > bytes || std::fseek(file, static_cast<long>(at), SEEK_SET) != 0 ||
        !read_int(file, count)) {
      cut_short("its frame or its collision count");
    }
    at += 4;
    if (count < 0 || count > (bytes - at) / record_bytes) {
      fail(path + ": record " + record + " claims " + std::to_string(count) +
           " collisions, more than the file holds; it is not a trajectory of this scene");
    }
    for (std::int32_t c = 0; c < count; ++c) {
      std::int32_t type = -1;
      if (!read_int(file, type)) cut_short("its collisions");
      if (type < 0 || type > (dim == 3 ? 3 : 2)) {  // 3, particle-sphere, is 3D only
        fail(path + ": record " + record + " has a collision of unknown type " +
             std::to_string(type) +
             (dim == 3 ? " (expected 0, 1, 2 or 3)" : " (expected 0, 1 or 2)"));
      }
      std::fseek(file, static_cast<long>(record_bytes - 4), SEEK_CUR);
    }
    at += count * record_bytes;
    if (layout == TrajectoryLayout::kCollisionsAndPolynomials) {
      std::int32_t polynomials = 0;
      if (std::fseek(file, static_cast<long>(at), SEEK_SET) != 0 || !read_int(file, polynomials)) {
        cut_short("its polynomial count");
      }
      at += 4;
      if (polynomials < 0 || polynomials > (bytes - at) / 4) {
        fail(path + ": record " + record + " claims " + std::to_string(polynomials) +
             " polynomials, more than the file holds");
      }
      for (std::int32_t p = 0; p < polynomials; ++p) {
        std::int32_t length = 0;
        if (!read_int(file, length)) cut_short("its polynomials");
        at += 4;
        if (length < 0 || length > (bytes - at) / 8) {
          fail(path + ": record " + record + " has a polynomial of length " +
               std::to_string(length) + ", more than the file holds");
        }
        at += 8 * static_cast<std::int64_t>(length);
        std::fseek(file, static_cast<long>(at), SEEK_SET);
      }
    }
    if (at > bytes) cut_short("its collisions or polynomials");
  }
  const auto records = static_cast<std::int64_t>(reader.offsets_.size());
  if (layout == TrajectoryLayout::kCollisionsAndPolynomials) {
    if (records % 2 == 0) {
      fail(path + " holds " + std::to_string(records) +
           " records, but a continuous-time or hybrid trajectory holds an odd number (the "
           "initial state, then a sync record and an end-of-step record per step)");
    }
    reader.num_frames_ = (records + 1) / 2;
  } else {
    reader.num_frames_ = records;
  }
  return reader;
}

void TrajectoryReader::read_record_at(std::int64_t index, TrajectoryRecord& record) {
  record.q.resize(dofs_);
  record.v.resize(dofs_);
  record.collisions.clear();
  record.polynomials.clear();
  std::FILE* file = file_.get();
  const auto count = static_cast<std::size_t>(dofs_);
  const auto fail = [&]() {
    throw Error(ErrorKind::kBadInput,
                "cannot read record " + std::to_string(index) + " of " + path_);
  };
  const std::int64_t offset = layout_ == TrajectoryLayout::kFrames
                                  ? index * trajectory_frame_bytes(dofs_)
                                  : offsets_.at(static_cast<std::size_t>(index));
  if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
      !read_doubles(file, record.q.data(), count) || !read_doubles(file, record.v.data(), count)) {
    fail();
  }
  if (layout_ == TrajectoryLayout::kFrames) return;
  std::int32_t collisions = 0;
  if (!read_int(file, collisions)) fail();
  for (std::int32_t c = 0; c < collisions; ++c) {
    CollisionRecord r;
    std::int32_t type = 0;
    if (!read_int(file, type) || !read_int(file, r.first) || !read_int(file, r.second)) fail();
    r.kind = static_cast<CollisionKind>(type);
    r.normal.resize(dim_);
    if (!read_doubles(file, r.normal.data(), static_cast<std::size_t>(dim_)) ||
        !read_doubles(file, &r.time, 1)) {
      fail();
    }
    record.collisions.push_back(std::move(r));
  }
  if (layout_ != TrajectoryLayout::kCollisionsAndPolynomials) return;
  std::int32_t polynomials = 0;
  if (!read_int(file, polynomials)) fail();
  for (std::int32_t p = 0; p < polynomials; ++p) {
    std::int32_t length = 0;
    if (!read_int(file, length)) fail();
    std::vector<double> c(static_cast<std::size_t>(length));
    if (!read_doubles(file, c.data(), c.size())) fail();
    record.polynomials.push_back(Polynomial::as_written(std::move(c)));
  }
}

void TrajectoryReader::read_record(std::int64_t k, TrajectoryRecord& record) {
  read_record_at(has_sync_records() ? 2 * k : k, record);
}

void TrajectoryReader::read_sync_record(std::int64_t k, TrajectoryRecord& record) {
  if (!has_sync_records() || k < 1) {
    throw std::logic_error("read_sync_record: the layout has no sync record for step " +
                           std::to_string(k));
  }
  read_record_at(2 * k - 1, record);
}

void TrajectoryReader::read_frame(std::int64_t k, Vector& q, Vector& v) {
  q.resize(dofs_);
  v.resize(dofs_);
  const std::int64_t offset =
      layout_ == TrajectoryLayout::kFrames
          ? k * trajectory_frame_bytes(dofs_)
          : offsets_.at(static_cast<std::size_t>(has_sync_records() ? 2 * k : k));
  const auto count = static_cast<std::size_t>(dofs_);
  if (std::fseek(file_.get(), static_cast<long>(offset), SEEK_SET) != 0 ||
      std::fread(q.data(), sizeof(double), count, file_.get()) != count ||
      std::fread(v.data(), sizeof(double), count, file_.get()) != count) {
    throw Error(ErrorKind::kBadInput, "cannot read frame " + std::to_string(k) + " of " + path_);
  }
  to_little_endian(q.data(), count);
  to_little_endian(v.data(), count);
}

}  // namespace fosssim
