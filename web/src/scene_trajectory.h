#pragma once
// One scene's whole run written as its trajectory file: what `FOSSSim -s SCENE -d 0 -o OUT`
// writes natively, shared by the Node driver (run_scene.cpp) and the page's download
// (web_session.cpp), so that both give the native bytes.

#include <string>

#include "core/scene.h"

namespace fosssim {

/// Runs `scene` from its initial state to its end and writes every state to `path` (particle
/// scenes: io/trajectory_steps.h; rigid bodies: io/rigid_trajectory.h), committed only when the
/// run completes. Returns the final time. Throws what loading and stepping throw.
double write_scene_trajectory(const Scene& scene, const std::string& path);

}  // namespace fosssim
