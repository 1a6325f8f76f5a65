#include "result_table.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "printable_text.h"

namespace fosssim {

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), pattern, value);
  return text;
}

std::string residual_cell(const std::optional<Residuals>& r, double Residuals::*which) {
  if (!r) return "-";
  const double value = (*r).*which;
  return value == 0.0 ? "0" : format("%.3g", value);
}

std::string first_failure_cell(const SceneResult& r) {
  if (r.passed() || !r.residuals) return "-";
  if (r.first_divergence) {
    return "step " + std::to_string(r.first_divergence->step) + ", " +
           r.first_divergence->object() + " " + std::to_string(r.first_divergence->particle);
  }
  return "accumulated only";
}

std::vector<std::string> row_of(const SceneResult& r) {
  return {r.name,
          r.integrator.empty() ? "-" : r.integrator,
          verdict_label(r.verdict),
          residual_cell(r.residuals, &Residuals::max_position),
          residual_cell(r.residuals, &Residuals::max_velocity),
          first_failure_cell(r),
          format("%.2f", r.seconds())};
}

void print_row(std::ostream& out, const std::vector<std::string>& cells,
               const std::vector<std::size_t>& widths) {
  std::string line;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool right = c == 3 || c == 4 || c == 6;  // numbers
    const std::size_t pad = widths[c] > cells[c].size() ? widths[c] - cells[c].size() : 0;
    if (c > 0) line += "  ";
    line += right ? std::string(pad, ' ') + cells[c] : cells[c] + std::string(pad, ' ');
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  out << line << "\n";
}

}  // namespace

void print_result_table(std::ostream& out, const GradingRun& run) {
  const std::vector<std::string> header = {"scene",       "integrator",    "verdict", "max pos res",
                                           "max vel res", "first failure", "time s"};
  std::vector<std::vector<std::string>> rows;
  for (const SceneResult& r : run.results) rows.push_back(row_of(r));
  std::vector<std::size_t> widths;
  for (const std::string& h : header) widths.push_back(h.size());
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  print_row(out, header, widths);
  bool extra_heading = false;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (run.results[i].extra_credit && !extra_heading) {
      out << "-- extra credit --\n";
      extra_heading = true;
    }
    print_row(out, rows[i], widths);
  }

  bool failures_heading = false;
  for (const SceneResult& r : run.results) {
    if (r.passed()) continue;
    if (!failures_heading) {
      out << "\nFailures:\n";
      failures_heading = true;
    }
    out << "  " << r.name << ": " << verdict_label(r.verdict) << ": " << printable_text(r.reason)
        << "\n";
    if (!r.stderr_tail.empty() && r.verdict != Verdict::kFailed) {
      out << indent_lines(last_lines(printable_text(r.stderr_tail), 3), "    stderr| ");
    }
  }
  const Tally t = tally(run.results);
  out << "\nRegular scenes: " << t.regular_passed << " of " << t.regular << " passed";
  if (t.extra > 0) out << "; extra credit: " << t.extra_passed << " of " << t.extra << " passed";
  out << ". Wall time " << format("%.2f", run.wall_seconds) << " s.\n";
  if (!run.sandboxed) out << kNoSandboxNote << "\n";
}

std::string progress_line(const SceneResult& result, std::size_t done, std::size_t total) {
  const int width = static_cast<int>(std::to_string(total).size());
  char counter[64];
  std::snprintf(counter, sizeof(counter), "[%*zu/%zu] %-11s ", width, done, total,
                verdict_label(result.verdict));
  return counter + result.name + format("  (%.2f s)", result.seconds());
}

}  // namespace fosssim
