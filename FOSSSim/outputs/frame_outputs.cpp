#include "outputs/frame_outputs.h"

#include "core/error.h"

namespace fosssim {

void check_needs(const OutputFormat& format, const Scene& scene) {
  const OutputNeeds& needs = format.needs;
  const SceneModel& model = scene.model;
  std::string refused;
  if (model.dim == 2 && !needs.runs_2d) refused = "2D scenes";
  if (model.dim == 3 && !needs.runs_3d) refused = "3D scenes";
  if (model.rigid_bodies && !needs.rigid_bodies) refused = "rigid-body scenes";
  if (!model.rigid_bodies && !needs.particles) refused = "particle scenes";
  if (refused.empty()) return;
  throw Error(ErrorKind::kBadInput, std::string(format.option_name()) + " cannot be written for " +
                                        refused + " (" + scene.source + ")");
}

FrameOutputs FrameOutputs::open(const Scene& scene, std::span<const OutputRequest> requests,
                                const OutputSettings& settings) {
  FrameOutputs outputs;
  const OutputContext context{scene, settings};
  for (const OutputRequest& request : requests) check_needs(*request.format, scene);
  for (const OutputRequest& request : requests) {
    outputs.outputs_.push_back(request.format->open(request.destination, context));
  }
  return outputs;
}

void FrameOutputs::write(const State& state, const SceneView& view, const StepRecord* record,
                         const Integrator* integrator) {
  Frame frame(state, view, record, integrator);
  for (auto& output : outputs_) output->write(frame);
}

void FrameOutputs::commit() {
  for (auto& output : outputs_) output->commit();
}

std::string FrameOutputs::describe() const {
  std::string out;
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    if (k > 0) out += k + 1 == outputs_.size() ? " and " : ", ";
    out += outputs_[k]->describe();
  }
  return out;
}

std::string FrameOutputs::abandon() {
  std::string notes;
  for (auto& output : outputs_) {
    const std::string note = output->abandon();
    if (note.empty()) continue;
    notes += (notes.empty() ? "" : "; ") + note;
  }
  return notes;
}

}  // namespace fosssim
