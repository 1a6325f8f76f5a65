#include "residual_history.h"

#include <string_view>

#include "core/error.h"
#include "core/text.h"
#include "io/output_file.h"

namespace fosssim {

namespace {
constexpr std::string_view kTableHeader =
    "step\ttime\tmax_position\tposition_particle\tmax_velocity\tvelocity_particle"
    "\tsum_position\tsum_velocity\n";
}  // namespace

ResidualHistory::ResidualHistory(std::int64_t steps, double dt, const GradingCriteria& criteria,
                                 bool keep_table)
    : dt_(dt),
      position_limit_(criteria.maximum_limit),
      velocity_limit_(criteria.maximum_velocity_limit),
      columns_(steps) {
  if (keep_table) {
    table_.reset(std::tmpfile());
    table_failed_ = table_ == nullptr;
  }
}

void ResidualHistory::add(const StepResidual& r) {
  columns_.add(r);
  const bool exceeds =
      !(below_limit(r.max_position, position_limit_) && below_limit(r.max_velocity, velocity_limit_));
  if (exceeds) {
    if (over_++ == 0) first_over_ = r.step;
    last_over_ = r.step;
  }
  for (double m : {r.max_position, r.max_velocity}) {
    if (replaces_maximum(m, worst_)) {
      worst_ = m;
      worst_step_ = r.step;
    }
  }
  if (table_ == nullptr) return;
  const std::string row =
      std::to_string(r.step) + '\t' + to_text(static_cast<double>(r.step) * dt_) + '\t' +
      to_text(r.max_position) + '\t' + std::to_string(r.max_position_particle) + '\t' +
      to_text(r.max_velocity) + '\t' + std::to_string(r.max_velocity_particle) + '\t' +
      to_text(r.sum_position) + '\t' + to_text(r.sum_velocity) + '\n';
  if (std::fwrite(row.data(), 1, row.size(), table_.get()) != row.size()) table_failed_ = true;
}

void ResidualHistory::write_table(const std::string& path) const {
  if (table_failed_ || table_ == nullptr) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot write " + path + ": the table's temporary file could not be written");
  }
  std::FILE* rows = table_.get();
  stream_output_file(path, [rows](std::FILE* out) {
    std::fwrite(kTableHeader.data(), 1, kTableHeader.size(), out);
    std::rewind(rows);
    char buffer[1 << 16];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, rows)) > 0;)
      std::fwrite(buffer, 1, n, out);
  });
}

}  // namespace fosssim
