#pragma once
// Scene tags that select scripted behaviour (`<scenetag>`, docs/scene-format.md).

#include <memory>
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/step/step_pipeline.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// The hook a scene's tag selects, or null when the scene has no tag or a tag without scripted
/// behaviour (the course ignores such tags too; see known_scene_tags).
/// The hook is a kScript stage of the step pipeline (core/step/step_stage.h).
std::unique_ptr<StepStage> make_step_hook(const Scene& scene);

/// The scene's scripted behaviour as additions to its step: its hook, if it has one.
StepAdditions scripted_additions(const Scene& scene);

/// The scene tags FOSSSim gives behaviour to ("ParticleFountain").
std::vector<std::string> known_scene_tags();

}  // namespace fosssim
