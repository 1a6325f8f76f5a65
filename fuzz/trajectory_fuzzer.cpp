// Fuzz target: grading a trajectory (io/trajectory_file.h, grading/), as FOSSSim -i does. The
// first byte picks one of nine tiny scenes: one per integrator, then one per trajectory layout
// with collisions (simple, continuous-time, hybrid: collision records, polynomial logs and sync
// records); the rest is the trajectory, read from memory in the scene's layout. Scenes are loaded
// once; each input grades at most four steps of three or four particles.
//
// What an input costs is what grading its steps costs, and a fuzzed frame is rarely a state any
// integrator converges from: the scenes are kept cheap to step from anywhere, so that the target
// runs well over a thousand inputs a second on a grown corpus too. Newton takes at most 5
// iterations (a valid trajectory needs 3; a state it does not converge from costs 10 instead of
// the default 400, plain and then with line search), the collision scenes take 2 steps and
// hybrid handling 2 impulse passes before its impact zones.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "grading/grader.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"

namespace {

using namespace fosssim;

/// Two balls that meet each other and the floor, with a fixed bar above them, under collision
/// handling `type` (2D, 2 steps; hybrid handling with 2 impulse passes): frames of 2 × 8 doubles
/// with the steps' records.
std::string collision_scene(const std::string& type) {
  return R"(<scene>
  <duration time="0.02"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0.025" vx="1" vy="-1" fixed="0" radius="0.02"/>
  <particle m="2" px="0.045" py="0.025" vx="-1" vy="-1" fixed="0" radius="0.02"/>
  <particle m="1" px="-0.3" py="0.06" vx="0" vy="0" fixed="1" radius="0.02"/>
  <particle m="1" px="0.3" py="0.06" vx="0" vy="0" fixed="1" radius="0.02"/>
  <edge i="2" j="3" radius="0.01"/>
  <halfplane px="0" py="0" nx="0" ny="1"/>
  <simplegravity fx="0" fy="-9.81"/>
  <collision type=")" +
         type + (type == "hybrid" ? R"(" maxiters="2"/>)" : R"("/>)") + R"(
</scene>)";
}

/// Three particles (one fixed) on damped springs under gravity and drag, 4 steps, with
/// `integrator` (and its attributes): frames of 2 × 6 doubles, 5 frames in a complete file.
std::string spring_scene(const std::string& integrator) {
  return R"(<scene>
  <duration time="0.04"/>
  <integrator type=)" +
         integrator + R"( dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="2" px="1" py="0.2" vx="0" vy="1" fixed="0"/>
  <particle m="0.5" px="1.5" py="-0.5" vx="-1" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="50" l0="0.9" b="0.5"/>
  <springforce edge="1" k="20" l0="0.7"/>
  <simplegravity fx="0" fy="-9.81"/>
  <dragdamping b="0.05"/>
</scene>)";
}

const std::vector<std::unique_ptr<Scene>>& scenes() {
  static const std::vector<std::unique_ptr<Scene>> loaded = [] {
    std::vector<std::unique_ptr<Scene>> out;
    for (const char* integrator :
         {R"("explicit-euler")", R"("symplectic-euler")", R"("linearized-implicit-euler")",
          R"("implicit-euler" newton-max-iterations="5")", R"("linearly-implicit-euler")"}) {
      out.push_back(std::make_unique<Scene>(load_scene_text(spring_scene(integrator), "fuzz.xml")));
    }
    // A 3D scene: a vortex between three particles, one fixed.
    out.push_back(std::make_unique<Scene>(load_scene_text(R"(<scene dim="3">
  <duration time="0.03"/>
  <integrator type="implicit-euler" dt="0.01" newton-max-iterations="5"/>
  <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="1"/>
  <particle m="1" px="1" py="0" pz="0.5" vx="0" vy="1" vz="0" fixed="0"/>
  <particle m="1" px="0" py="1" pz="-0.5" vx="1" vy="0" vz="0.5" fixed="0"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="10" l0="1"/>
  <gravitationalforce i="0" j="1" G="1"/>
</scene>)",
                                                          "fuzz3d.xml")));
    for (const char* type : {"simple", "continuous-time", "hybrid"}) {
      out.push_back(std::make_unique<Scene>(
          load_scene_text(collision_scene(type), std::string(type) + ".xml")));
    }
    return out;
  }();
  return loaded;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto& all = scenes();
  const Scene& scene = *all[data[0] % all.size()];
  try {
    TrajectoryReader file = TrajectoryReader::from_bytes(
        std::string(reinterpret_cast<const char*>(data + 1), size - 1), scene.model.num_dofs(),
        "fuzz.bin", scene.model.dim, trajectory_layout(scene.model));
    const GradeReport report = grade_trajectory(scene, file);
    std::ostringstream out;
    print_grade_report(out, report);
    out << describe_failure(report, scene.model.dim);
  } catch (const Error&) {
  }
  return 0;
}
