#include "scripting/step_hooks.h"

#include <string_view>

#include "scripting/particle_fountain.h"

namespace fosssim {

namespace {

std::unique_ptr<StepStage> make_particle_fountain(const Scene& scene) {
  std::vector<int> teleported;
  for (int p = 0; p < static_cast<int>(scene.particle_tags.size()); ++p) {
    if (scene.particle_tags[p] == ParticleFountain::kParticleTag) teleported.push_back(p);
  }
  return std::make_unique<ParticleFountain>(std::move(teleported));
}

struct HookEntry {
  std::string_view tag;
  std::unique_ptr<StepStage> (*make)(const Scene&);
};

/// One line per scene tag with scripted behaviour.
constexpr HookEntry kHooks[] = {
    {ParticleFountain::kTag, &make_particle_fountain},
};

}  // namespace

std::unique_ptr<StepStage> make_step_hook(const Scene& scene) {
  for (const HookEntry& entry : kHooks) {
    if (entry.tag == scene.tag) return entry.make(scene);
  }
  return nullptr;
}

StepAdditions scripted_additions(const Scene& scene) {
  StepAdditions additions;
  if (auto hook = make_step_hook(scene)) {
    additions.stages.emplace_back(StagePhase::kScript, std::move(hook));
  }
  return additions;
}

std::vector<std::string> known_scene_tags() {
  std::vector<std::string> tags;
  for (const HookEntry& entry : kHooks) tags.emplace_back(entry.tag);
  return tags;
}

}  // namespace fosssim
