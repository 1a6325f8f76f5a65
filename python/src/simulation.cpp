// The module fosssim._core, part two: simulations, trajectory files, grading and pictures
// (docs/python.md).

#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.h"
#include "core/error.h"
#include "core/step/step_pipeline.h"
#include "grading/grader.h"
#include "grading/step_grader.h"
#include "io/trajectory_file.h"
#include "io/trajectory_steps.h"
#include "outputs/run_summary.h"
#include "pictures/cairo_painter.h"
#include "render/scene_view.h"
#include "scripting/step_hooks.h"

namespace fosssim::python {

namespace {

/// How long C++ works without the GIL before Python gets to see a Ctrl-C (and other threads
/// to run): long steps release the GIL, and check for signals between slices of this length.
constexpr std::chrono::milliseconds kSlice{50};

/// Pictures are 16 to 8192 pixels wide and high, as the program's --size.
constexpr int kMinPictureSide = 16;
constexpr int kMaxPictureSide = 8192;

void check_picture_size(int width, int height) {
  if (width < kMinPictureSide || height < kMinPictureSide || width > kMaxPictureSide ||
      height > kMaxPictureSide) {
    throw py::value_error("a picture's width and height must each be between 16 and 8192 pixels");
  }
}

/// Marks an object busy for the duration of a call that releases the GIL, so that a second
/// thread cannot step, reset or read it meanwhile.
class BusyGuard {
 public:
  explicit BusyGuard(std::atomic<bool>& busy) : busy_(busy) {
    if (busy_.exchange(true)) {
      throw py::value_error("the simulation is busy in another thread");
    }
  }
  ~BusyGuard() { busy_ = false; }
  BusyGuard(const BusyGuard&) = delete;
  BusyGuard& operator=(const BusyGuard&) = delete;

 private:
  std::atomic<bool>& busy_;
};

/// Runs `work(deadline)` without the GIL until it returns true (done), checking for Python
/// signals (Ctrl-C raises KeyboardInterrupt) between slices; `between` runs with the GIL
/// after each slice, whatever happened (it publishes results).
template <typename Work, typename Between>
void run_in_slices(Work&& work, Between&& between) {
  for (;;) {
    std::exception_ptr failure;
    bool done = false;
    {
      py::gil_scoped_release release;
      try {
        done = work(std::chrono::steady_clock::now() + kSlice);
      } catch (...) {
        failure = std::current_exception();
      }
    }
    between();
    if (failure) std::rethrow_exception(failure);
    if (done) return;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
}

struct PyCollision {
  std::string kind;
  int first, second;
  Vector normal;
  double time;
};

const char* collision_kind_name(CollisionKind kind) {
  switch (kind) {
    case CollisionKind::kParticleParticle: return "particle-particle";
    case CollisionKind::kParticleEdge: return "particle-edge";
    case CollisionKind::kParticleHalfPlane: return "particle-halfplane";
    case CollisionKind::kParticleSphere: return "particle-sphere";
  }
  return "unknown";
}

/// A simulation as Python holds it: the scene's step pipeline and a state, like
/// core/step/Simulation, plus stable buffers that Python's views of the state read.
class PySimulation {
 public:
  explicit PySimulation(std::shared_ptr<PyScene> scene)
      : owner_(std::move(scene)),
        scene_(owner_->scene),
        pipeline_(scene_->model, scripted_additions(*scene_)),
        state_(scene_->initial),
        q_(state_.q),
        v_(state_.v),
        view_(*scene_, state_, 512, 512) {
    restart_summary();
  }

  const Scene& scene() const { return *scene_; }
  const std::shared_ptr<PyScene>& scene_object() const { return owner_; }
  const State& state() const { return state_; }
  const Vector& q() const { return q_; }
  const Vector& v() const { return v_; }
  bool finished() const { return state_.step >= scene_->model.num_steps(); }
  const StepRecord& record() const { return record_; }
  std::atomic<bool>& busy() { return busy_; }

  /// Takes `steps` steps, writing each state to `writer` if given.
  void step(std::int64_t steps, std::optional<TrajectoryWriter>* writer = nullptr) {
    if (steps < 0) throw py::value_error("the number of steps must not be negative");
    BusyGuard guard(busy_);
    std::int64_t taken = 0;
    const TrajectoryLayout layout = trajectory_layout(scene_->model);
    run_in_slices(
        [&](std::chrono::steady_clock::time_point deadline) {
          while (taken < steps) {
            pipeline_.step(state_, &record_);
            ++taken;
            view_.record(state_);
            summary_->add(state_, &record_, &pipeline_.integrator());
            if (writer != nullptr) write_trajectory_state(**writer, layout, state_, &record_);
            if (std::chrono::steady_clock::now() >= deadline) break;
          }
          return taken == steps;
        },
        [&] { publish(); });
  }

  void set_state(const py::handle& q, const py::handle& v, std::optional<double> time,
                 std::optional<std::int64_t> step) {
    BusyGuard guard(busy_);
    const int dofs = scene_->model.num_dofs();
    if (!q.is_none()) state_.q = to_vector(q, dofs, "q");
    if (!v.is_none()) state_.v = to_vector(v, dofs, "v");
    if (time) state_.time = *time;
    if (step) {
      if (*step < 0) throw py::value_error("step must not be negative");
      state_.step = *step;
    }
    record_.clear();
    restart_summary();
    publish();
  }

  /// The run summary (outputs/run_summary.h) since the simulation was made or its state last
  /// set, as Python objects: json.loads of what FOSSSim --stats-json writes.
  py::object stats() const {
    return py::module_::import("json").attr("loads")(summary_->json());
  }

  Image render(int width, int height) {
    check_picture_size(width, height);
    BusyGuard guard(busy_);
    view_.resize(width, height);
    return render_image(view_.compose(state_));
  }

  void save_picture(const std::string& path, int width, int height) {
    check_picture_size(width, height);
    BusyGuard guard(busy_);
    view_.resize(width, height);
    const Drawing drawing = view_.compose(state_);
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".svg") == 0) {
      write_svg(drawing, path);
    } else {
      write_png(drawing, path);
    }
  }

  std::vector<std::string> notes() const { return pipeline_.integrator().notes(); }

 private:
  /// Starts the summary afresh at the current state.
  void restart_summary() {
    summary_.emplace(*scene_);
    summary_->add(state_, nullptr, &pipeline_.integrator());
  }

  /// Copies the state into the buffers Python's views read. The state's own vectors may be
  /// replaced by a step (collision passes swap buffers), so Python never sees them directly.
  void publish() {
    q_ = state_.q;
    v_ = state_.v;
  }

  std::shared_ptr<PyScene> owner_;
  std::shared_ptr<Scene> scene_;  // shared with owner_: the scene is in use
  StepPipeline pipeline_;
  State state_;
  Vector q_, v_;  // same size as state_'s, never reallocated
  StepRecord record_;
  SceneView view_;
  std::optional<RunSummary> summary_;
  std::atomic<bool> busy_{false};
};

py::array_t<std::uint8_t> to_rgb(const Image& image) {
  py::array_t<std::uint8_t> out({image.height, image.width, 3});
  auto pixels = out.mutable_unchecked<3>();
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t argb = image.at(x, y);
      pixels(y, x, 0) = static_cast<std::uint8_t>((argb >> 16) & 0xff);
      pixels(y, x, 1) = static_cast<std::uint8_t>((argb >> 8) & 0xff);
      pixels(y, x, 2) = static_cast<std::uint8_t>(argb & 0xff);
    }
  }
  return out;
}

/// A trajectory file being written: fosssim.TrajectoryWriter.
struct PyTrajectoryWriter {
  std::shared_ptr<Scene> scene;
  std::optional<TrajectoryWriter> writer;
  std::int64_t frames = 0;

  TrajectoryWriter& open_writer() {
    if (!writer) throw py::value_error("the trajectory writer is closed");
    return *writer;
  }
};

/// The Python view of a grading report.
py::dict report_dict(const GradeReport& report) {
  py::dict out;
  out["passed"] = report.passed();
  out["steps"] = report.steps;
  out["steps_graded"] = report.steps_graded;
  out["accumulated_position"] = report.accumulated_position;
  out["accumulated_velocity"] = report.accumulated_velocity;
  out["max_position"] = report.max_position;
  out["max_velocity"] = report.max_velocity;
  out["reference_failure"] =
      report.reference_failure ? py::object(py::str(*report.reference_failure)) : py::none();
  out["collisions_passed"] =
      report.collisions ? py::object(py::bool_(report.collisions->passed())) : py::none();
  if (report.first_divergence) {
    py::dict divergence;
    divergence["step"] = report.first_divergence->step;
    divergence["particle"] = report.first_divergence->particle;
    divergence["position_residual"] = report.first_divergence->position_residual;
    divergence["velocity_residual"] = report.first_divergence->velocity_residual;
    out["first_divergence"] = divergence;
  } else {
    out["first_divergence"] = py::none();
  }
  std::ostringstream text;
  print_grade_report(text, report);
  out["report"] = text.str();
  return out;
}

py::dict grade(const std::shared_ptr<PyScene>& owner, const std::string& path) {
  const std::shared_ptr<Scene> scene = owner->scene;  // in use while grading
  std::optional<TrajectoryReader> file;
  std::optional<StepGrader> grader;
  {
    py::gil_scoped_release release;
    file.emplace(open_trajectory(path, scene->model));
    grader.emplace(StepGrader::open(*scene, *file));
  }
  run_in_slices(
      [&](std::chrono::steady_clock::time_point deadline) {
        while (grader->grade_next_step()) {
          if (std::chrono::steady_clock::now() >= deadline) return false;
        }
        return true;
      },
      [] {});
  return report_dict(grader->report());
}

/// Every record of a trajectory file as arrays: q and v of shape (frames, dofs), and for
/// layouts with collisions the collisions of each frame.
py::dict read_trajectory(const std::shared_ptr<PyScene>& owner, const std::string& path) {
  const Scene& scene = *owner->scene;
  TrajectoryReader file = open_trajectory(path, scene.model);
  const std::int64_t frames = file.num_frames();
  const int dofs = scene.model.num_dofs();
  py::array_t<double> q({static_cast<py::ssize_t>(frames), static_cast<py::ssize_t>(dofs)});
  py::array_t<double> v({static_cast<py::ssize_t>(frames), static_cast<py::ssize_t>(dofs)});
  py::list collisions;
  TrajectoryRecord record;
  for (std::int64_t k = 0; k < frames; ++k) {
    file.read_record(k, record);
    std::copy_n(record.q.data(), dofs, q.mutable_data(k, 0));
    std::copy_n(record.v.data(), dofs, v.mutable_data(k, 0));
    if (file.layout() != TrajectoryLayout::kFrames) {
      std::vector<PyCollision> frame;
      for (const CollisionRecord& c : record.collisions) {
        frame.push_back({collision_kind_name(c.kind), c.first, c.second, c.normal, c.time});
      }
      collisions.append(py::cast(frame));
    }
  }
  py::dict out;
  out["q"] = q;
  out["v"] = v;
  out["collisions"] = file.layout() == TrajectoryLayout::kFrames ? py::object(py::none())
                                                                  : py::object(collisions);
  return out;
}

}  // namespace

void add_simulation_bindings(py::module_& module) {
  py::class_<PyCollision>(module, "Collision", "A collision the last step handled.")
      .def_readonly("kind", &PyCollision::kind,
                    "'particle-particle', 'particle-edge', 'particle-halfplane' or "
                    "'particle-sphere'")
      .def_readonly("first", &PyCollision::first, "the particle (the lower one of two)")
      .def_readonly("second", &PyCollision::second, "the other particle, edge, half-plane or sphere")
      .def_property_readonly("normal", [](const PyCollision& c) { return to_array(c.normal); },
                             "the separation as the trajectory file records it (new array)")
      .def_readonly("time", &PyCollision::time, "fraction of the step, 0 for discrete detection")
      .def("__repr__", [](const PyCollision& c) {
        return "<fosssim.Collision " + c.kind + " " + std::to_string(c.first) + " " +
               std::to_string(c.second) + ">";
      });

  py::class_<PySimulation>(
      module, "Simulation",
      "Runs a scene with its integrator and collision handling, as the FOSSSim program does. "
      "q, v, positions and velocities are read-only views that follow the simulation "
      "(docs/python.md); copy them to keep a state.")
      .def(py::init([](std::shared_ptr<PyScene> scene) {
             // Binding the integrator may factorize large matrices: other threads run meanwhile.
             py::gil_scoped_release release;
             return std::make_unique<PySimulation>(std::move(scene));
           }),
           py::arg("scene"))
      .def_property_readonly("scene", &PySimulation::scene_object)
      .def("step", [](PySimulation& s, std::int64_t n) { s.step(n); }, py::arg("n") = 1,
           "Takes n steps (the GIL is released; Ctrl-C stops between steps). Raises "
           "fosssim.StepError when a step fails; the state is then the failed step's.")
      .def(
          "run",
          [](PySimulation& s, const std::optional<std::string>& trajectory) {
            const std::int64_t remaining =
                std::max<std::int64_t>(0, s.scene().model.num_steps() - s.state().step);
            if (!trajectory) return s.step(remaining);
            std::optional<TrajectoryWriter> writer = TrajectoryWriter::open(*trajectory);
            write_trajectory_state(*writer, trajectory_layout(s.scene().model), s.state(),
                                   s.state().step == 0 ? nullptr : &s.record());
            s.step(remaining, &writer);
            writer->commit();
          },
          py::arg("trajectory") = py::none(),
          "Steps to the end of the scene's duration; with `trajectory`, writes the current "
          "state and every step to that file in the course's format, byte for byte what "
          "`FOSSSim -s SCENE -o FILE` writes. A run that fails or is interrupted leaves "
          "FILE.incomplete.")
      .def_property_readonly("time", [](const PySimulation& s) { return s.state().time; })
      .def_property_readonly("step_count", [](const PySimulation& s) { return s.state().step; })
      .def_property_readonly("num_steps",
                             [](const PySimulation& s) { return s.scene().model.num_steps(); })
      .def_property_readonly("dt", [](const PySimulation& s) { return s.scene().model.integrator.dt; })
      .def_property_readonly("finished", &PySimulation::finished)
      .def_property_readonly(
          "q",
          [](py::object self) {
            const Vector& q = self.cast<PySimulation&>().q();
            return readonly_view(q.data(), q.size(), 0, self);
          },
          "Positions, flat [x0, y0, x1, ...]: a read-only view that follows the simulation.")
      .def_property_readonly(
          "v",
          [](py::object self) {
            const Vector& v = self.cast<PySimulation&>().v();
            return readonly_view(v.data(), v.size(), 0, self);
          },
          "Velocities, flat: a read-only view that follows the simulation.")
      .def_property_readonly(
          "positions",
          [](py::object self) {
            PySimulation& s = self.cast<PySimulation&>();
            return readonly_view(s.q().data(), s.q().size(), s.scene().model.dim, self);
          },
          "Positions as (particles, dim): a read-only view of q.")
      .def_property_readonly(
          "velocities",
          [](py::object self) {
            PySimulation& s = self.cast<PySimulation&>();
            return readonly_view(s.v().data(), s.v().size(), s.scene().model.dim, self);
          },
          "Velocities as (particles, dim): a read-only view of v.")
      .def_property_readonly(
          "mass",
          [](py::object self) {
            const Vector& mass = self.cast<PySimulation&>().scene().model.mass;
            return readonly_view(mass.data(), mass.size(), 0, self);
          },
          "Per degree of freedom: a read-only view.")
      .def("set_state", &PySimulation::set_state, py::arg("q") = py::none(),
           py::arg("v") = py::none(), py::arg("time") = py::none(), py::arg("step") = py::none(),
           "Replaces positions, velocities, time or step count (copied in).")
      .def_property_readonly(
          "collisions",
          [](const PySimulation& s) {
            std::vector<PyCollision> out;
            for (const CollisionRecord& c : s.record().collisions) {
              out.push_back({collision_kind_name(c.kind), c.first, c.second, c.normal, c.time});
            }
            return out;
          },
          "The collisions the last step handled, in the order found (a new list).")
      .def("stats", &PySimulation::stats,
           "The run's summary as a dict, the same as FOSSSim --stats-json writes "
           "(docs/command-line.md, 'Run summaries'): steps, solver statistics, collisions per "
           "step, energy drift and timings, since the simulation was made or set_state.")
      .def_property_readonly("notes", &PySimulation::notes,
                             "What the integrator has to say about the run so far.")
      .def(
          "render",
          [](PySimulation& s, int width, int height) { return to_rgb(s.render(width, height)); },
          py::arg("width") = 512, py::arg("height") = 512,
          "The current state drawn as the program's pictures draw it: a new uint8 array of "
          "shape (height, width, 3), RGB.")
      .def("save_picture", &PySimulation::save_picture, py::arg("path"), py::arg("width") = 512,
           py::arg("height") = 512, "Writes the current state's picture, SVG for *.svg, else PNG.");

  py::class_<PyTrajectoryWriter>(
      module, "TrajectoryWriter",
      "Writes a trajectory file in the course's format for a scene, in the layout of its "
      "collision method. The file appears under its name only on close() (or leaving a `with` "
      "block normally); otherwise its frames are kept as PATH.incomplete.")
      .def(py::init([](const std::shared_ptr<PyScene>& scene, const std::string& path) {
             auto out = std::make_unique<PyTrajectoryWriter>();
             out->scene = scene->scene;
             out->writer.emplace(TrajectoryWriter::open(path));
             return out;
           }),
           py::arg("scene"), py::arg("path"))
      .def(
          "write",
          [](PyTrajectoryWriter& w, PySimulation& s) {
            if (&s.scene() != w.scene.get()) {
              throw py::value_error("the simulation runs another scene than the writer's");
            }
            const State& state = s.state();
            write_trajectory_state(w.open_writer(), trajectory_layout(w.scene->model), state,
                                   state.step == 0 ? nullptr : &s.record());
            ++w.frames;
          },
          py::arg("simulation"),
          "Appends the simulation's state, with the last step's collisions (none at step 0).")
      .def_readonly("frames", &PyTrajectoryWriter::frames)
      .def("close",
           [](PyTrajectoryWriter& w) {
             w.open_writer().commit();
             w.writer.reset();
           })
      .def("abandon",
           [](PyTrajectoryWriter& w) {
             const std::string kept = w.open_writer().abandon();
             w.writer.reset();
             return kept;
           })
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PyTrajectoryWriter& w, const py::handle& type, const py::handle&,
                          const py::handle&) {
        if (!w.writer) return false;
        if (type.is_none()) {
          w.writer->commit();
        } else {
          w.writer->abandon();
        }
        w.writer.reset();
        return false;
      });

  module.def("grade", &grade, py::arg("scene"), py::arg("path"),
             "Grades a trajectory file against the scene as `FOSSSim -s SCENE -i FILE` does: a "
             "dict with 'passed', the four residuals, 'first_divergence' and the printed "
             "'report'. The GIL is released; Ctrl-C stops it.");
  module.def("read_trajectory", &read_trajectory, py::arg("scene"), py::arg("path"),
             "A trajectory file as new arrays: 'q' and 'v' of shape (frames, dofs), and "
             "'collisions' per record for layouts that have them (else None).");
}

}  // namespace fosssim::python
