#include "io/trajectory_file.h"

#include <unistd.h>

#include <algorithm>
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

/// Moves the stream `count` bytes on, to `target`: by reading them when they are few (keeping
/// the stream's buffer), by seeking to `target` otherwise.
bool skip_bytes(std::FILE* file, std::int64_t count, std::int64_t target) {
  char scratch[512];
  if (count > static_cast<std::int64_t>(sizeof(scratch))) {
    return std::fseek(file, static_cast<long>(target), SEEK_SET) == 0;
  }
  return std::fread(scratch, 1, static_cast<std::size_t>(count), file) ==
         static_cast<std::size_t>(count);
}

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
  return model.collisions.method->records;
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
  std::FILE* file = output.take_stream();
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
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path_ + ": " + system_reason());
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
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path_ + ": " + system_reason());
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
  const std::string& partial = path_;
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
  // A run that stopped before its first frame (another output could not be opened) keeps
  // nothing: an empty OUT.incomplete would only say that.
  const bool empty = file_ != nullptr && std::ftell(file_) == 0;
  close_file();
  finished_ = true;
  if (empty && !output_.in_place()) {
    output_.discard();
    return "";
  }
  return output_.keep_unfinished(".incomplete");
}

// ---- TrajectoryReader -------------------------------------------------------------------------

TrajectoryReader::TrajectoryReader(std::string path, RegularFile file, int dofs, int dim,
                                   TrajectoryLayout layout)
    : path_(std::move(path)), file_(std::move(file)), dofs_(dofs), dim_(dim), layout_(layout) {
  const std::int64_t frame_bytes = trajectory_frame_bytes(dofs);
  if (frame_bytes == 0) {
    throw Error(ErrorKind::kBadInput,
                path_ + ": the scene has no particles, so its trajectory has nothing to read");
  }
  if (layout_ != TrajectoryLayout::kFrames) {
    check_records();
    return;
  }
  if (file_.size % frame_bytes != 0) {
    throw Error(ErrorKind::kBadInput,
                path_ + " has " + std::to_string(file_.size) +
                    " bytes, not a whole number of frames of " + std::to_string(frame_bytes) +
                    " bytes (" + std::to_string(dofs) +
                    " positions and velocities); it was cut short or is for another scene");
  }
  num_frames_ = file_.size / frame_bytes;
  num_records_ = num_frames_;
}

TrajectoryReader TrajectoryReader::open(const std::string& path, int dofs) {
  return open(path, dofs, 2, TrajectoryLayout::kFrames);
}

TrajectoryReader TrajectoryReader::open(const std::string& path, int dofs, int dim,
                                        TrajectoryLayout layout) {
  return TrajectoryReader(path, open_regular_file(path), dofs, dim, layout);
}

TrajectoryReader TrajectoryReader::from_bytes(std::string bytes, int dofs, const std::string& name,
                                              int dim, TrajectoryLayout layout) {
  auto held = std::make_shared<const std::string>(std::move(bytes));
  RegularFile file;
  file.size = static_cast<std::int64_t>(held->size());
  // fmemopen of an empty buffer fails; a one-byte buffer read as empty stands in for it.
  file.stream.reset(::fmemopen(const_cast<char*>(held->empty() ? "" : held->data()),
                               held->empty() ? 1 : held->size(), "rb"));
  if (file.stream == nullptr) {
    throw Error(ErrorKind::kBadInput, "cannot read " + name + ": " + system_reason());
  }
  TrajectoryReader reader(name, std::move(file), dofs, dim, layout);
  reader.bytes_ = std::move(held);
  return reader;
}

std::int64_t TrajectoryReader::record_end(std::int64_t at, std::int64_t index) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  std::FILE* file = file_.stream.get();
  const std::int64_t bytes = file_.size;
  const std::string record = std::to_string(index);
  const auto cut_short = [&](const std::string& what) {
    fail(path_ + " ends inside record " + record + " (" + what +
         "); it was cut short or is not a trajectory of this scene");
  };
  const std::int64_t record_bytes = collision_record_bytes(dim_);
  at += trajectory_frame_bytes(dofs_);
  std::int32_t count = 0;
  if (at > bytes || std::fseek(file, static_cast<long>(at), SEEK_SET) != 0 ||
      !read_int(file, count)) {
    cut_short("its frame or its collision count");
  }
  at += 4;
  if (count < 0 || count > (bytes - at) / record_bytes) {
    fail(path_ + ": record " + record + " claims " + std::to_string(count) +
         " collisions, more than the file holds; it is not a trajectory of this scene");
  }
  for (std::int32_t c = 0; c < count; ++c) {
    std::int32_t type = -1;
    if (std::fseek(file, static_cast<long>(at + c * record_bytes), SEEK_SET) != 0 ||
        !read_int(file, type)) {
      cut_short("its collisions");
    }
    if (type < 0 || type > (dim_ == 3 ? 3 : 2)) {  // 3, particle-sphere, is 3D only
      fail(path_ + ": record " + record + " has a collision of unknown type " +
           std::to_string(type) +
           (dim_ == 3 ? " (expected 0, 1, 2 or 3)" : " (expected 0, 1 or 2)"));
    }
  }
  at += count * record_bytes;
  if (layout_ == TrajectoryLayout::kCollisionsAndPolynomials) {
    std::int32_t polynomials = 0;
    if (std::fseek(file, static_cast<long>(at), SEEK_SET) != 0 || !read_int(file, polynomials)) {
      cut_short("its polynomial count");
    }
    at += 4;
    if (polynomials < 0 || polynomials > (bytes - at) / 4) {
      fail(path_ + ": record " + record + " claims " + std::to_string(polynomials) +
           " polynomials, more than the file holds");
    }
    // The stream sits just after the count. It reads on from there, skipping short
    // coefficient runs by reading them: a seek would drop the stream's buffer and reread it for
    // every polynomial, which made a record padded with millions of them take seconds.
    for (std::int32_t p = 0; p < polynomials; ++p) {
      std::int32_t length = 0;
      if (!read_int(file, length)) cut_short("its polynomials");
      at += 4;
      if (length < 0 || length > (bytes - at) / 8) {
        fail(path_ + ": record " + record + " has a polynomial of length " +
             std::to_string(length) + ", more than the file holds");
      }
      at += 8 * static_cast<std::int64_t>(length);
      if (!skip_bytes(file, 8 * static_cast<std::int64_t>(length), at)) {
        cut_short("its polynomials");
      }
    }
  }
  if (at > bytes) cut_short("its collisions or polynomials");
  return at;
}

void TrajectoryReader::check_records() {
  std::int64_t records = 0;
  for (std::int64_t at = 0; at < file_.size; ++records) at = record_end(at, records);
  num_records_ = records;
  if (layout_ == TrajectoryLayout::kCollisionsAndPolynomials) {
    if (records % 2 == 0) {
      throw Error(ErrorKind::kBadInput,
                  path_ + " holds " + std::to_string(records) +
                      " records, but a continuous-time or hybrid trajectory holds an odd number "
                      "(the initial state, then a sync record and an end-of-step record per "
                      "step)");
    }
    num_frames_ = (records + 1) / 2;
  } else {
    num_frames_ = records;
  }
}

std::int64_t TrajectoryReader::record_offset(std::int64_t index) {
  if (layout_ == TrajectoryLayout::kFrames) return index * trajectory_frame_bytes(dofs_);
  if (index < cursor_index_) {
    cursor_index_ = 0;
    cursor_offset_ = 0;
  }
  for (; cursor_index_ < index; ++cursor_index_) {
    cursor_offset_ = record_end(cursor_offset_, cursor_index_);
  }
  return cursor_offset_;
}

void TrajectoryReader::read_record_at(std::int64_t index, TrajectoryRecord& record,
                                      std::int64_t max_polynomials) {
  record.q.resize(dofs_);
  record.v.resize(dofs_);
  record.collisions.clear();
  record.polynomials.clear();
  std::FILE* file = file_.stream.get();
  const auto count = static_cast<std::size_t>(dofs_);
  const auto fail = [&]() {
    throw Error(ErrorKind::kBadInput,
                "cannot read record " + std::to_string(index) + " of " + path_);
  };
  if (index < 0 || index >= num_records_) fail();
  const std::int64_t offset = record_offset(index);
  if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
      !read_doubles(file, record.q.data(), count) || !read_doubles(file, record.v.data(), count)) {
    fail();
  }
  if (layout_ == TrajectoryLayout::kFrames) return;
  // The counts were checked against the file's size when it was opened.
  std::int32_t collisions = 0;
  if (!read_int(file, collisions) || collisions < 0) fail();
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
  if (!read_int(file, polynomials) || polynomials < 0) fail();
  const std::int64_t kept =
      std::min<std::int64_t>(polynomials, std::max<std::int64_t>(max_polynomials, 0) + 1);
  for (std::int64_t p = 0; p < kept; ++p) {
    std::int32_t length = 0;
    if (!read_int(file, length) || length < 0) fail();
    std::vector<double> c(static_cast<std::size_t>(length));
    if (!read_doubles(file, c.data(), c.size())) fail();
    record.polynomials.push_back(Polynomial::as_written(std::move(c)));
  }
}

void TrajectoryReader::read_record(std::int64_t k, TrajectoryRecord& record,
                                   std::int64_t max_polynomials) {
  read_record_at(has_sync_records() ? 2 * k : k, record, max_polynomials);
}

void TrajectoryReader::read_sync_record(std::int64_t k, TrajectoryRecord& record,
                                        std::int64_t max_polynomials) {
  if (!has_sync_records() || k < 1) {
    throw std::logic_error("read_sync_record: the layout has no sync record for step " +
                           std::to_string(k));
  }
  read_record_at(2 * k - 1, record, max_polynomials);
}

void TrajectoryReader::read_frame(std::int64_t k, Vector& q, Vector& v) {
  q.resize(dofs_);
  v.resize(dofs_);
  const auto count = static_cast<std::size_t>(dofs_);
  const auto fail = [&]() {
    throw Error(ErrorKind::kBadInput, "cannot read frame " + std::to_string(k) + " of " + path_);
  };
  if (k < 0 || k >= num_frames_) fail();
  const std::int64_t offset = record_offset(has_sync_records() ? 2 * k : k);
  std::FILE* file = file_.stream.get();
  if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
      !read_doubles(file, q.data(), count) || !read_doubles(file, v.data(), count)) {
    fail();
  }
}

}  // namespace fosssim
