// Grading of trajectories with collision records: a run passes its own grading; a file with a
// missing, a superfluous or a wrong-normal collision, wrong polynomial coefficients or a wrong
// sync record fails with the course's report lines.

#include "grading/collision_grading.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <sstream>

#include "core/step/simulation.h"
#include "grading/grader.h"
#include "io/scene_loader.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

/// Two balls meet at step 1 of 3; particle 2 rests on a half-plane boundary far away.
std::string scene_text(const char* type) {
  return std::string(R"(<scene>
  <duration time="0.03"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="-0.39" py="0" vx="1" vy="0" fixed="0" radius="0.2"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0" radius="0.2"/>
  <particle m="1" px="5" py="0" vx="0" vy="0" fixed="0" radius="0.2"/>
  <halfplane px="0" py="-3" nx="0" ny="1"/>
  <collision type=")") +
         type + R"("/>
</scene>)";
}

/// How a test changes step k's record before it is written (sync = the sync record).
using Edit = std::function<void(std::int64_t step, bool sync, TrajectoryRecord& record)>;

class CollisionGrading : public ::testing::Test {
 protected:
  void load(const char* type) {
    scene_ = std::make_unique<Scene>(load_scene_text(scene_text(type), "collide.xml"));
    path_ = (fs::temp_directory_path() /
             ("fosssim_collision_grading_" +
              std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())))
                .string();
  }
  void TearDown() override { fs::remove(path_); }

  /// Writes the scene's own run, edited, and grades it; returns the printed report.
  std::string grade(const Edit& edit, bool& passed) {
    const TrajectoryLayout layout = trajectory_layout(scene_->model);
    TrajectoryWriter writer = TrajectoryWriter::open(path_);
    Simulation simulation(scene_->model, scene_->initial);
    writer.write_record(layout, scene_->initial.q, scene_->initial.v, {}, {});
    while (!simulation.finished()) {
      simulation.step();
      const StepRecord& r = simulation.last_record();
      const std::int64_t k = simulation.state().step;
      if (layout == TrajectoryLayout::kCollisionsAndPolynomials) {
        TrajectoryRecord sync{r.sync->q, r.sync->v, r.collisions, r.polynomials};
        sync.polynomials.resize(r.sync->polynomials_logged);
        edit(k, true, sync);
        writer.write_record(layout, sync.q, sync.v, sync.collisions, sync.polynomials);
      }
      TrajectoryRecord end{simulation.state().q, simulation.state().v, r.collisions, r.polynomials};
      edit(k, false, end);
      writer.write_record(layout, end.q, end.v, end.collisions, end.polynomials);
    }
    writer.commit();
    TrajectoryReader file = open_trajectory(path_, scene_->model);
    const GradeReport report = grade_trajectory(*scene_, file);
    std::ostringstream out;
    print_grade_report(out, report);
    passed = report.passed();
    return out.str();
  }

  std::unique_ptr<Scene> scene_;
  std::string path_;
};

const Edit kNoEdit = [](std::int64_t, bool, TrajectoryRecord&) {};

TEST_F(CollisionGrading, ARunPassesItsOwnGrading) {
  for (const char* type : {"simple", "continuous-time", "hybrid"}) {
    load(type);
    bool passed = false;
    const std::string report = grade(kNoEdit, passed);
    EXPECT_TRUE(passed) << type << "\n" << report;
    EXPECT_NE(report.find("Collisions Passed: Yes.\nOverall success: Passed.\n"), std::string::npos)
        << report;
  }
}

TEST_F(CollisionGrading, MissingSuperfluousAndWrongNormalCollisionsFail) {
  load("simple");
  bool passed = true;
  std::string report =
      grade([](std::int64_t, bool, TrajectoryRecord& r) { r.collisions.clear(); }, passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Missed collision: Particle 0 - Particle 1 with normal = 0.38 0\n"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("Collisions Passed: No.\nOverall success: Failed.\n"), std::string::npos);

  report = grade(
      [](std::int64_t k, bool, TrajectoryRecord& r) {
        if (k == 2)
          r.collisions.push_back(
              {CollisionKind::kParticleHalfPlane, 2, 0, Eigen::Vector2d(0, -3), 0.0});
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Superfluous collision: Particle 2 - Halfplane 0 with normal = 0 -3\n"),
            std::string::npos)
      << report;

  // 1.01e-9 off fails; 0.99e-9 passes (the course's tolerance, 1e-9 in the 2-norm).
  for (const double off : {1.01e-9, 0.99e-9}) {
    report = grade(
        [off](std::int64_t, bool, TrajectoryRecord& r) {
          for (CollisionRecord& c : r.collisions) c.normal[1] += off;
        },
        passed);
    EXPECT_EQ(passed, off < 1e-9) << report;
    EXPECT_EQ(
        report.find("  Collision with wrong normal: Particle 0 - Particle 1") != std::string::npos,
        off > 1e-9)
        << report;
  }
  // The pair's order matters: (1, 0) is not (0, 1).
  report = grade(
      [](std::int64_t, bool, TrajectoryRecord& r) {
        for (CollisionRecord& c : r.collisions) std::swap(c.first, c.second);
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("Superfluous collision: Particle 1 - Particle 0"), std::string::npos);
}

TEST(CollisionDescription, NamesTheKindOfEveryPairSpheresIncluded) {
  EXPECT_EQ(describe_collision(
                {CollisionKind::kParticleSphere, 4, 1, Eigen::Vector3d(0, -1.5, 0.25), 0.6}),
            "Particle 4 - Sphere 1 with normal = 0 -1.5 0.25");
  EXPECT_EQ(describe_collision({CollisionKind::kParticleEdge, 0, 2, Eigen::Vector2d(1, 0), 0.0}),
            "Particle 0 - Edge 2 with normal = 1 0");
}

TEST_F(CollisionGrading, PolynomialsAreComparedUpToAPositiveFactor) {
  load("continuous-time");
  bool passed = false;
  grade(
      [](std::int64_t, bool, TrajectoryRecord& r) {
        for (Polynomial& p : r.polynomials) {
          std::vector<double> c = p.coefficients();
          for (double& x : c) x *= 3.0;
          p = Polynomial::as_written(c);
        }
      },
      passed);
  EXPECT_TRUE(passed);
  std::string report = grade(
      [](std::int64_t k, bool, TrajectoryRecord& r) {
        if (k == 2) {
          std::vector<double> c = r.polynomials[0].coefficients();
          c.back() += 1e-6;
          r.polynomials[0] = Polynomial::as_written(c);
        }
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("Wrong polynomial coefficients!\n"), std::string::npos) << report;
  report = grade(
      [](std::int64_t, bool, TrajectoryRecord& r) {
        std::vector<double> c = r.polynomials[0].coefficients();
        for (double& x : c) x = -x;  // a sign flip is not a positive factor
        r.polynomials[0] = Polynomial::as_written(c);
      },
      passed);
  EXPECT_FALSE(passed);
  report = grade([](std::int64_t, bool, TrajectoryRecord& r) { r.polynomials.pop_back(); }, passed);
  EXPECT_NE(report.find("Wrong number of polynomials!\n"), std::string::npos) << report;
  report = grade(
      [](std::int64_t, bool, TrajectoryRecord& r) {
        std::vector<double> c = r.polynomials[0].coefficients();
        c.push_back(0.0);
        r.polynomials[0] = Polynomial::as_written(c);
      },
      passed);
  EXPECT_NE(report.find("Wrong polynomial degree!\n"), std::string::npos) << report;
}

TEST_F(CollisionGrading, ASyncRecordThatDiffersFromFosssimsFails) {
  // The course's grader adopts the file's sync record; FOSSSim checks it.
  load("continuous-time");
  bool passed = true;
  const std::string report = grade(
      [](std::int64_t k, bool sync, TrajectoryRecord& r) {
        if (sync && k == 1) r.q[0] += 1e-6;
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Sync record of step 1 differs from FOSSSim's by 9.99999"),
            std::string::npos)
      << report;
}

TEST_F(CollisionGrading, SyncRecordPolynomialsAreCompared) {
  // Wrong coefficients, a missing polynomial and a record padded with 100,000 extra ones, each
  // in the sync record only: the end-of-step records are right, and each run fails.
  load("continuous-time");
  bool passed = true;
  std::string report = grade(
      [](std::int64_t k, bool sync, TrajectoryRecord& r) {
        if (sync && k == 1) {
          std::vector<double> c = r.polynomials[0].coefficients();
          c.back() += 1e-6;
          r.polynomials[0] = Polynomial::as_written(c);
        }
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Sync record of step 1: Wrong polynomial coefficients!\n"),
            std::string::npos)
      << report;
  report = grade(
      [](std::int64_t k, bool sync, TrajectoryRecord& r) {
        if (sync && k == 2) r.polynomials.pop_back();
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Sync record of step 2: Wrong number of polynomials!\n"),
            std::string::npos)
      << report;
  report = grade(
      [](std::int64_t k, bool sync, TrajectoryRecord& r) {
        if (sync && k == 1) {
          r.polynomials.insert(r.polynomials.end(), 100000, r.polynomials[0]);
        }
      },
      passed);
  EXPECT_FALSE(passed);
  EXPECT_NE(report.find("  Sync record of step 1: Wrong number of polynomials!\n"),
            std::string::npos)
      << report;
}

TEST(TrajectoryReaderCap, ARecordIsReadUpToOnePolynomialMoreThanTheCap) {
  const std::string path =
      (fs::temp_directory_path() / "fosssim_collision_grading_reader_cap.bin").string();
  Vector q = Vector::Zero(2), v = Vector::Zero(2);
  const std::vector<Polynomial> many(1000, Polynomial::as_written({1.0, 2.0, 3.0}));
  TrajectoryWriter writer = TrajectoryWriter::open(path);
  for (int k = 0; k < 3; ++k) {
    writer.write_record(TrajectoryLayout::kCollisionsAndPolynomials, q, v, {}, many);
  }
  writer.commit();
  TrajectoryReader file =
      TrajectoryReader::open(path, 2, 2, TrajectoryLayout::kCollisionsAndPolynomials);
  TrajectoryRecord record;
  file.read_record(1, record, 10);
  EXPECT_EQ(record.polynomials.size(), 11u);
  file.read_sync_record(1, record, 0);
  EXPECT_EQ(record.polynomials.size(), 1u);
  file.read_record(1, record);
  EXPECT_EQ(record.polynomials.size(), 1000u);
  fs::remove(path);
}

}  // namespace
}  // namespace fosssim
