// The module fosssim._core, part one: errors, scenes, their forces and the integrator registry
// (docs/python.md).

#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "bindings.h"
#include "core/collisions/contact_registry.h"
#include "core/error.h"
#include "core/force_evaluation.h"
#include "core/integrators/integrator_registry.h"
#include "core/step_error.h"
#include "io/scene_loader.h"

namespace fosssim::python {

std::shared_ptr<ForceSet> PyScene::forces() {
  if (!forces_) forces_ = std::make_shared<ForceSet>(scene->model);
  return forces_;
}

Vector to_vector(const py::handle& object, Eigen::Index size, const char* what) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  if (!array) throw py::value_error(std::string(what) + " must be an array of numbers");
  if (array.size() != size) {
    throw py::value_error(std::string(what) + " must hold " + std::to_string(size) +
                          " numbers (dim × particles), found " + std::to_string(array.size()));
  }
  return Eigen::Map<const Vector>(array.data(), size);
}

py::array_t<double> to_array(const Vector& vector) {
  py::array_t<double> array(vector.size());
  std::copy(vector.data(), vector.data() + vector.size(), array.mutable_data());
  return array;
}

py::array_t<double> readonly_view(const double* data, Eigen::Index rows, int columns,
                                  const py::handle& owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(rows)};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(sizeof(double))};
  if (columns > 0) {
    shape = {static_cast<py::ssize_t>(rows / columns), columns};
    strides = {static_cast<py::ssize_t>(columns * sizeof(double)), sizeof(double)};
  }
  py::array_t<double> array(shape, strides, data, owner);
  // NumPy's flag, so that writing through the view fails instead of changing FOSSSim's data.
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

py::object to_scipy(const SparseMatrix& matrix) {
  SparseMatrix compressed = matrix;
  compressed.makeCompressed();
  const auto nonzeros = static_cast<py::ssize_t>(compressed.nonZeros());
  py::array_t<double> data(nonzeros);
  py::array_t<int> indices(nonzeros);
  py::array_t<int> pointers(compressed.cols() + 1);
  std::copy_n(compressed.valuePtr(), nonzeros, data.mutable_data());
  std::copy_n(compressed.innerIndexPtr(), nonzeros, indices.mutable_data());
  std::copy_n(compressed.outerIndexPtr(), compressed.cols() + 1, pointers.mutable_data());
  const py::object csc_matrix = py::module_::import("scipy.sparse").attr("csc_matrix");
  return csc_matrix(py::make_tuple(data, indices, pointers),
                    py::arg("shape") = py::make_tuple(compressed.rows(), compressed.cols()));
}

namespace {

// The Python classes of FOSSSim's errors. Created once with the module and never freed: the
// translator may run until the interpreter ends.
PyObject* error_type = nullptr;
PyObject* scene_error_type = nullptr;
PyObject* step_error_type = nullptr;

const char* kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kBadInput: return "bad-input";
    case ErrorKind::kStepFailed: return "step-failed";
    case ErrorKind::kCannotWrite: return "cannot-write";
    case ErrorKind::kUnavailable: return "unavailable";
  }
  return "unknown";
}

/// Raises `type` with the error's message and its details as attributes.
void raise(PyObject* type, const Error& error, const py::dict& details) {
  py::object instance = py::reinterpret_borrow<py::object>(type)(error.what());
  instance.attr("kind") = kind_name(error.kind());
  for (const auto& [key, value] : details) instance.attr(key) = value;
  PyErr_SetObject(type, instance.ptr());
}

PyObject* new_error_class(py::module_& module, const char* name, py::tuple bases,
                          const char* doc) {
  const std::string qualified = std::string("fosssim.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  module.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;
}

void add_errors(py::module_& module) {
  error_type = new_error_class(module, "Error", py::make_tuple(py::handle(PyExc_Exception)),
                               "A failure FOSSSim reports: its message is complete; `kind` is "
                               "'bad-input', 'step-failed', 'cannot-write' or 'unavailable'.");
  scene_error_type = new_error_class(
      module, "SceneError",
      py::make_tuple(py::handle(error_type), py::handle(PyExc_ValueError)),
      "A problem with a scene or mesh file, with `file`, `line` (0 when none), `element` and "
      "`problem`.");
  step_error_type = new_error_class(
      module, "StepError", py::make_tuple(py::handle(error_type), py::handle(PyExc_RuntimeError)),
      "A step that could not be taken; `step` is its 1-based number.");
  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const SceneError& error) {
      py::dict details;
      details["file"] = error.file();
      details["line"] = error.line();
      details["element"] = error.element();
      details["problem"] = error.problem();
      raise(scene_error_type, error, details);
    } catch (const StepError& error) {
      py::dict details;
      details["step"] = error.step();
      raise(step_error_type, error, details);
    } catch (const Error& error) {
      raise(error_type, error, py::dict());
    }
  });
}

/// Integrator options given from Python (keyword arguments or a dict), read by
/// OptionValues::read like <integrator> attributes. Names may use '_' for '-'.
class PythonOptions final : public OptionSource {
 public:
  PythonOptions(const py::dict& given, const IntegratorMethod& method) {
    for (const auto& [key, value] : given) {
      std::string name = py::str(key);
      for (char& c : name) {
        if (c == '_') c = '-';
      }
      bool known = false;
      std::string names;
      for (const OptionSpec& spec : method.options) {
        known = known || spec.name == name;
        names += (names.empty() ? "" : ", ") + std::string(spec.name);
      }
      if (!known) {
        throw Error(ErrorKind::kBadInput, "integrator " + std::string(method.name) +
                                              " has no option '" + name +
                                              "' (its options: " + (names.empty() ? "none" : names) +
                                              ")");
      }
      values_.emplace_back(name, py::reinterpret_borrow<py::object>(value));
    }
  }

  bool has(std::string_view name) override { return find(name) != nullptr; }
  double number(std::string_view name) override {
    const py::object& value = *find(name);
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::float_>(value) ||
                                               py::isinstance<py::int_>(value))) {
      fail(name, "must be a number, found " + std::string(py::repr(value)));
    }
    const double number = value.cast<double>();
    if (!std::isfinite(number)) fail(name, "must be finite, found " + std::string(py::repr(value)));
    return number;
  }
  std::string text(std::string_view name) override {
    const py::object& value = *find(name);
    if (!py::isinstance<py::str>(value)) {
      fail(name, "must be a string, found " + std::string(py::repr(value)));
    }
    return value.cast<std::string>();
  }
  [[noreturn]] void fail(std::string_view name, const std::string& problem) override {
    throw Error(ErrorKind::kBadInput, "integrator option " + std::string(name) + ": " + problem);
  }

 private:
  const py::object* find(std::string_view name) const {
    for (const auto& [key, value] : values_) {
      if (key == name) return &value;
    }
    return nullptr;
  }
  std::vector<std::pair<std::string, py::object>> values_;
};

const char* energy_name(EnergyTrend trend) {
  switch (trend) {
    case EnergyTrend::kGrows: return "grows";
    case EnergyTrend::kBounded: return "bounded";
    case EnergyTrend::kDecays: return "decays";
  }
  return "unknown";
}

/// Options as dicts: name, help, values, type, default (and choices or range).
py::list describe_options(std::span<const OptionSpec> specs) {
  py::list options;
  for (const OptionSpec& spec : specs) {
    py::dict option;
    option["name"] = std::string(spec.name);
    option["help"] = std::string(spec.help);
    option["values"] = spec.describe_values();
    if (spec.type == OptionSpec::Type::kChoice) {
      option["type"] = "choice";
      py::list choices;
      for (std::string_view choice : spec.choices) choices.append(std::string(choice));
      option["choices"] = choices;
      option["default"] = std::string(spec.choices.empty() ? "" : spec.choices.front());
    } else {
      const bool integer = spec.type == OptionSpec::Type::kInteger;
      option["type"] = integer ? "integer" : "number";
      option["default"] = integer ? py::object(py::int_(static_cast<long long>(spec.default_value)))
                                  : py::object(py::float_(spec.default_value));
      option["lowest"] = spec.lowest;
      option["lowest_excluded"] = spec.lowest_excluded;
      option["highest"] = spec.highest;
    }
    options.append(option);
  }
  return options;
}

py::dict describe_method(const IntegratorMethod& method) {
  py::list aliases;
  for (std::string_view alias : method.aliases) aliases.append(std::string(alias));
  py::dict out;
  out["name"] = std::string(method.name);
  out["aliases"] = aliases;
  out["summary"] = std::string(method.summary);
  out["options"] = describe_options(method.options);
  out["order"] = method.properties.order;
  out["course_reference"] = method.properties.course_reference;
  out["runs_2d"] = method.properties.runs_2d;
  out["runs_3d"] = method.properties.runs_3d;
  out["implicit"] = method.properties.implicit;
  out["energy"] = energy_name(method.properties.energy);
  return out;
}

py::dict describe_contact_method(const ContactMethod& method) {
  py::list bodies;
  if (method.scope.particles) bodies.append("particles");
  if (method.scope.planar_rigid_bodies) bodies.append("planar rigid bodies");
  const char* records = "frames";
  if (method.records == StepRecordLayout::kCollisions) records = "collisions";
  if (method.records == StepRecordLayout::kCollisionsAndPolynomials) {
    records = "collisions and polynomials";
  }
  py::dict out;
  out["name"] = std::string(method.name);
  out["summary"] = std::string(method.summary);
  out["options"] = describe_options(method.options);
  out["bodies"] = bodies;
  out["runs_2d"] = method.scope.runs_2d;
  out["runs_3d"] = method.scope.runs_3d;
  out["records"] = records;
  out["has_stage"] = method.make_stage != nullptr;
  out["has_force"] = method.make_force != nullptr;
  return out;
}

/// The values of the model's integrator options, by name.
py::dict option_values(const IntegratorSettings& settings) {
  py::dict out;
  for (const OptionSpec& spec : settings.options.specs()) {
    const std::string name(spec.name);
    switch (spec.type) {
      case OptionSpec::Type::kChoice:
        out[name.c_str()] = std::string(settings.options.choice(spec.name));
        break;
      case OptionSpec::Type::kInteger:
        out[name.c_str()] = settings.options.integer(spec.name);
        break;
      case OptionSpec::Type::kNumber:
        out[name.c_str()] = settings.options.number(spec.name);
        break;
    }
  }
  return out;
}

void refuse_change_in_use(const PyScene& scene) {
  if (scene.in_use()) {
    throw py::value_error(
        "the scene is in use by a simulation or grading: configure its integrator before "
        "making one, or load the scene again");
  }
}

/// One of the scene's forces, kept alive with the scene. It holds the Python scene object, not
/// its Scene, so that holding a force does not count as using the scene (forces do not depend
/// on the integrator).
struct PyForce {
  std::shared_ptr<PyScene> owner;
  std::shared_ptr<ForceSet> set;
  const Force* force;

  const Scene& scene() const { return *owner->scene; }
  ForceInput input(const Vector& q, const Vector& v, bool definite) const {
    return ForceInput{q, v, scene().model.mass, definite};
  }
};

/// q and v from Python: v defaults to zero.
std::pair<Vector, Vector> point(const Scene& scene, const py::handle& q, const py::handle& v) {
  const int dofs = scene.model.num_dofs();
  Vector qv = to_vector(q, dofs, "q");
  Vector vv = v.is_none() ? Vector(Vector::Zero(dofs)) : to_vector(v, dofs, "v");
  return {std::move(qv), std::move(vv)};
}

void add_forces(py::module_& module) {
  py::class_<PyForce>(module, "Force",
                      "One force of a scene (docs/forces.md): its energy U, gradient dU/dq = -F "
                      "and Hessians -dF/dq, -dF/dv at any point. Arrays are flat, "
                      "[x0, y0, x1, y1, ...].")
      .def_property_readonly("label", [](const PyForce& f) { return f.force->label(); })
      .def_property_readonly("conservative",
                             [](const PyForce& f) { return f.force->is_conservative(); })
      .def_property_readonly("symmetric_jacobians",
                             [](const PyForce& f) { return f.force->has_symmetric_jacobians(); })
      .def(
          "energy",
          [](const PyForce& f, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(f.scene(), q, v);
            return energy_of(*f.force, qv, vv, f.scene().model.mass);
          },
          py::arg("q"), py::arg("v") = py::none(), "Potential energy U(q) (0 if non-conservative).")
      .def(
          "gradient",
          [](const PyForce& f, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(f.scene(), q, v);
            return to_array(gradient_of(*f.force, qv, vv, f.scene().model.mass));
          },
          py::arg("q"), py::arg("v") = py::none(), "-F(q, v), a new flat array.")
      .def(
          "hessian_x",
          [](const PyForce& f, const py::handle& q, const py::handle& v, bool definite) {
            auto [qv, vv] = point(f.scene(), q, v);
            HessianBuilder builder;
            f.force->add_hessian_x(f.input(qv, vv, definite), builder);
            return to_scipy(builder.build(static_cast<int>(qv.size())));
          },
          py::arg("q"), py::arg("v") = py::none(), py::arg("definite") = false,
          "-dF/dq as a scipy.sparse.csc_matrix; definite=True projects each element's block "
          "onto the positive semi-definite matrices where the force can.")
      .def(
          "hessian_v",
          [](const PyForce& f, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(f.scene(), q, v);
            HessianBuilder builder;
            f.force->add_hessian_v(f.input(qv, vv, false), builder);
            return to_scipy(builder.build(static_cast<int>(qv.size())));
          },
          py::arg("q"), py::arg("v") = py::none(), "-dF/dv as a scipy.sparse.csc_matrix.")
      .def("__repr__", [](const PyForce& f) { return "<fosssim.Force " + f.force->label() + ">"; });
}

std::string dash_name(std::string name) {
  for (char& c : name) {
    if (c == '_') c = '-';
  }
  return name;
}

void set_integrator(PyScene& self, const std::string& name, std::optional<double> dt,
                    const py::kwargs& options) {
  refuse_change_in_use(self);
  const IntegratorMethod* method = find_integrator_method(dash_name(name));
  if (method == nullptr) {
    throw Error(ErrorKind::kBadInput, "unknown integrator '" + name +
                                          "' (known: " + describe_integrator_names() + ")");
  }
  SceneModel& model = self.scene->model;
  if ((model.dim == 2 && !method->properties.runs_2d) ||
      (model.dim == 3 && !method->properties.runs_3d)) {
    throw Error(ErrorKind::kBadInput, "integrator " + std::string(method->name) +
                                          " does not run scenes of dimension " +
                                          std::to_string(model.dim));
  }
  if (dt && !(std::isfinite(*dt) && *dt > 0.0)) {
    throw py::value_error("dt must be a positive finite number of seconds");
  }
  IntegratorSettings settings = model.integrator;
  settings.use(*method);
  if (dt) settings.dt = *dt;
  PythonOptions given(options, *method);
  settings.options.read(given);
  model.integrator = settings;
}

void add_scene(py::module_& module) {
  py::class_<PyScene, std::shared_ptr<PyScene>>(
      module, "Scene",
      "A loaded scene: its model (masses, forces, integrator, duration) and initial state. "
      "Arrays it returns are read-only views of the scene (docs/python.md).")
      .def_property_readonly("source", [](const PyScene& s) { return s.scene->source; })
      .def_property_readonly("dim", [](const PyScene& s) { return s.scene->model.dim; })
      .def_property_readonly("num_particles",
                             [](const PyScene& s) { return s.scene->model.num_particles(); })
      .def_property_readonly("num_dofs", [](const PyScene& s) { return s.scene->model.num_dofs(); })
      .def_property_readonly("dt", [](const PyScene& s) { return s.scene->model.integrator.dt; })
      .def_property_readonly("duration", [](const PyScene& s) { return s.scene->model.duration; })
      .def_property_readonly("num_steps", [](const PyScene& s) { return s.scene->model.num_steps(); })
      .def_property_readonly("warnings", [](const PyScene& s) { return s.scene->warnings; })
      .def_property_readonly("description", [](const PyScene& s) { return s.scene->description; })
      .def_property_readonly("tag", [](const PyScene& s) { return s.scene->tag; })
      .def_property_readonly(
          "collisions",
          [](const PyScene& s) { return std::string(s.scene->model.collisions.method->name); })
      .def_property_readonly(
          "mass",
          [](py::object self) {
            const Vector& mass = self.cast<PyScene&>().scene->model.mass;
            return readonly_view(mass.data(), mass.size(), 0, self);
          },
          "Per degree of freedom, [m0, m0, m1, m1, ...] in 2D: a read-only view.")
      .def_property_readonly(
          "fixed",
          [](const PyScene& s) {
            py::array_t<bool> out(static_cast<py::ssize_t>(s.scene->model.fixed.size()));
            for (std::size_t p = 0; p < s.scene->model.fixed.size(); ++p) {
              out.mutable_at(static_cast<py::ssize_t>(p)) = s.scene->model.fixed[p];
            }
            return out;
          },
          "Per particle, True when fixed: a new array.")
      .def_property_readonly(
          "initial_q",
          [](py::object self) {
            const Vector& q = self.cast<PyScene&>().scene->initial.q;
            return readonly_view(q.data(), q.size(), 0, self);
          },
          "Initial positions, flat: a read-only view.")
      .def_property_readonly(
          "initial_v",
          [](py::object self) {
            const Vector& v = self.cast<PyScene&>().scene->initial.v;
            return readonly_view(v.data(), v.size(), 0, self);
          },
          "Initial velocities, flat: a read-only view.")
      .def_property_readonly("edges",
                             [](const PyScene& s) {
                               std::vector<std::pair<int, int>> edges;
                               for (const Edge& e : s.scene->model.edges) edges.emplace_back(e.i, e.j);
                               return edges;
                             })
      .def_property_readonly(
          "integrator",
          [](const PyScene& s) { return std::string(s.scene->model.integrator.method->name); })
      .def_property_readonly(
          "integrator_options",
          [](const PyScene& s) { return option_values(s.scene->model.integrator); },
          "The integrator's option values by name (a new dict).")
      .def("set_integrator", &set_integrator, py::arg("name"), py::arg("dt") = py::none(),
           "Switches to the registry's method `name` (aliases too) with its default options, "
           "then sets `dt` and the options given as keywords ('_' stands for '-'). Refused "
           "while a simulation of the scene exists.")
      .def_property_readonly(
          "forces",
          [](const std::shared_ptr<PyScene>& s) {
            std::vector<PyForce> out;
            const std::shared_ptr<ForceSet> set = s->forces();
            for (const Force* force : *set) out.push_back(PyForce{s, set, force});
            return out;
          },
          "The forces summed, in order: the scene's, then its contact (penalty) force.")
      .def(
          "potential_energy",
          [](PyScene& s, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(*s.scene, q, v);
            return compute_potential_energy(*s.forces(), qv, vv);
          },
          py::arg("q"), py::arg("v") = py::none())
      .def(
          "kinetic_energy",
          [](PyScene& s, const py::handle& v) {
            return compute_kinetic_energy(s.scene->model,
                                          to_vector(v, s.scene->model.num_dofs(), "v"));
          },
          py::arg("v"))
      .def(
          "gradient",
          [](PyScene& s, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(*s.scene, q, v);
            return to_array(compute_gradient(*s.forces(), qv, vv));
          },
          py::arg("q"), py::arg("v") = py::none(), "Sum of the forces' gradients, -F (new array).")
      .def(
          "force",
          [](PyScene& s, const py::handle& q, const py::handle& v, bool zero_fixed_particles) {
            auto [qv, vv] = point(*s.scene, q, v);
            Vector force = compute_force(*s.forces(), qv, vv);
            if (zero_fixed_particles) zero_fixed(s.scene->model, force);
            return to_array(force);
          },
          py::arg("q"), py::arg("v") = py::none(), py::arg("zero_fixed") = false,
          "F(q, v) summed over the forces in order (new array); zero_fixed=True zeroes the "
          "fixed particles' rows, as integrators do.")
      .def(
          "hessian_x",
          [](PyScene& s, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(*s.scene, q, v);
            return to_scipy(compute_hessian_x(*s.forces(), qv, vv));
          },
          py::arg("q"), py::arg("v") = py::none())
      .def(
          "hessian_v",
          [](PyScene& s, const py::handle& q, const py::handle& v) {
            auto [qv, vv] = point(*s.scene, q, v);
            return to_scipy(compute_hessian_v(*s.forces(), qv, vv));
          },
          py::arg("q"), py::arg("v") = py::none())
      .def("__repr__", [](const PyScene& s) {
        return "<fosssim.Scene " + s.scene->source + ": " +
               std::to_string(s.scene->model.num_particles()) + " particles, " +
               std::to_string(s.scene->model.dim) + "D>";
      });

  module.def(
      "load_scene",
      [](const std::string& path) {
        Scene scene;
        {
          py::gil_scoped_release release;
          scene = load_scene_file(path);
        }
        return std::make_shared<PyScene>(std::move(scene));
      },
      py::arg("path"),
      "Reads a scene file (XML, or JSON by its .json name). Raises fosssim.SceneError with "
      "file, line and problem.");
  module.def(
      "load_scene_text",
      [](const std::string& text, const std::string& name) {
        return std::make_shared<PyScene>(load_scene_text(text, name));
      },
      py::arg("text"), py::arg("name") = "<string>",
      "Reads a scene from XML text; `name` stands for the file in messages. Mesh files it names "
      "are read relative to the current folder.");
}

}  // namespace

void add_scene_bindings(py::module_& module) {
  add_errors(module);
  add_forces(module);
  add_scene(module);
  module.def(
      "integrators",
      []() {
        py::list out;
        for (const IntegratorMethod* method : integrator_methods()) out.append(describe_method(*method));
        return out;
      },
      "Every integrator of the registry: name, aliases, summary, options, properties.");
  module.def(
      "contact_methods",
      []() {
        py::list out;
        for (const ContactMethod* method : contact_methods()) {
          out.append(describe_contact_method(*method));
        }
        return out;
      },
      "Every contact method of the registry (<collision type>): name, summary, options, the "
      "bodies and dimensions it handles, what its steps record.");
}

}  // namespace fosssim::python

PYBIND11_MODULE(_core, module) {
  module.doc() = "FOSSSim's simulator as a Python module (docs/python.md)";
  fosssim::python::add_scene_bindings(module);
  fosssim::python::add_simulation_bindings(module);
}
