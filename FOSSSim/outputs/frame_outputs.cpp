#include "outputs/frame_outputs.h"

namespace fosssim {

FrameOutputs FrameOutputs::open(const Scene& scene, std::span<const OutputRequest> requests,
                                const OutputSettings& settings) {
  FrameOutputs outputs;
  const OutputContext context{scene, settings};
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
