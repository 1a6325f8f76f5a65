#include "diagnosis.h"

#include <sstream>
#include <stdexcept>

#include "atomic_file.h"
#include "core/text.h"
#include "printable_text.h"
#include "residual_plot.h"

namespace fosssim {

std::string diagnosis_text(const SceneResult& result) {
  std::ostringstream out;
  out << result.name << ": " << verdict_label(result.verdict);
  if (!result.integrator.empty()) {
    out << " (" << result.integrator << ", " << result.particles
        << (result.particles == 1 ? " particle in " : " particles in ") << result.dim << "D, "
        << result.steps << (result.steps == 1 ? " step of " : " steps of ") << to_text(result.dt)
        << " s)";
  }
  out << "\n";
  if (!result.reason.empty()) out << result.reason << "\n";
  if (result.residuals) {
    const Residuals& r = *result.residuals;
    out << "Residuals: accumulated position " << to_text(r.accumulated_position)
        << ", accumulated velocity " << to_text(r.accumulated_velocity) << ", maximum position "
        << to_text(r.max_position) << ", maximum velocity " << to_text(r.max_velocity) << "\n";
  }
  if (!result.details.empty()) out << result.details;
  if (!result.stderr_tail.empty()) {
    out << "The candidate's standard error (last lines):\n"
        << indent_lines(result.stderr_tail, "  ");
  }
  return out.str();
}

std::string diagnosis_stem(const std::string& folder, const std::string& scene_name) {
  std::string stem = scene_name;
  if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".xml") == 0)
    stem.resize(stem.size() - 4);
  return folder + "/" + stem;
}

void write_diagnosis(const std::string& folder, const SceneResult& result,
                     const GradeReport* report, const ResidualHistory& history) {
  const std::string stem = diagnosis_stem(folder, result.name);
  write_file_atomically(stem + ".diagnosis.txt", diagnosis_text(result));
  if (report == nullptr) return;
  history.write_table(stem + ".residuals.tsv");
  ResidualPlotOptions plot;
  plot.title = result.name + ": largest residual per step (" + result.integrator + ")";
  plot.dt = result.dt;
  plot.limit = report->criteria.maximum_limit;
  plot.velocity_limit = report->criteria.maximum_velocity_limit;
  if (report->first_divergence) plot.marked_step = report->first_divergence->step;
  write_line_plot(residual_plot(history.columns(), plot), stem + ".residuals.svg");
}

void write_rigid_diagnosis(const std::string& folder, const SceneResult& result,
                           const RigidGradeReport& report, const ResidualHistory& history) {
  const std::string stem = diagnosis_stem(folder, result.name);
  write_file_atomically(stem + ".diagnosis.txt", diagnosis_text(result));
  history.write_table(stem + ".residuals.tsv");
  ResidualPlotOptions plot;
  plot.title = result.name + ": largest residual per step (" + result.integrator + ")";
  plot.dt = result.dt;
  plot.limit = report.criteria.maximum_limit;
  plot.velocity_limit = report.criteria.maximum_limit;
  if (report.first_divergence && report.first_divergence->step > 0) {
    plot.marked_step = report.first_divergence->step;
  }
  write_line_plot(residual_plot(history.columns(), plot), stem + ".residuals.svg");
}

}  // namespace fosssim
