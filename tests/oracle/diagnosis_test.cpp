// Tests of the diagnosis text of a scene (oracle/src/diagnosis.h): its first line names the scene,
// the verdict and the run in words that agree in number ("1 particle", "1 step").

#include "diagnosis.h"

#include <gtest/gtest.h>

namespace fosssim {
namespace {

SceneResult result_of(int particles, std::int64_t steps) {
  SceneResult result;
  result.name = "assets/t1m1/x.xml";
  result.integrator = "explicit-euler";
  result.dim = 2;
  result.particles = particles;
  result.steps = steps;
  result.dt = 0.01;
  result.verdict = Verdict::kFailed;
  return result;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(Diagnosis, FirstLineCountsParticlesAndStepsInWords) {
  EXPECT_NE(first_line(diagnosis_text(result_of(1, 1))).find("(explicit-euler, 1 particle in 2D, "
                                                               "1 step of 0.01 s)"),
            std::string::npos)
      << diagnosis_text(result_of(1, 1));
  EXPECT_NE(first_line(diagnosis_text(result_of(3, 100)))
                .find("(explicit-euler, 3 particles in 2D, 100 steps of 0.01 s)"),
            std::string::npos)
      << diagnosis_text(result_of(3, 100));
}

}  // namespace
}  // namespace fosssim
