#pragma once
// What the two files of the Python module share: the scene object Python holds, conversions
// between NumPy arrays and Eigen vectors, and the functions that add each part to the module.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "core/force_set.h"
#include "core/scene.h"

namespace fosssim::python {

namespace py = pybind11;

/// A loaded scene as Python holds it. Simulations, force handles and gradings share it, and
/// while one of them holds it the scene's model may not change (the integrator binds to it):
/// in_use() says so.
struct PyScene {
  explicit PyScene(Scene loaded) : scene(std::make_shared<Scene>(std::move(loaded))) {}

  std::shared_ptr<Scene> scene;
  /// The model's forces with its contact force (ForceSet), made on first use. It depends on the
  /// forces and the collision settings only, which Python cannot change.
  std::shared_ptr<ForceSet> forces();
  /// True while a simulation or a grading holds the scene.
  bool in_use() const { return scene.use_count() > 1; }

 private:
  std::shared_ptr<ForceSet> forces_;
};

/// A copy of `array` as a vector of `size` values: any array of that many numbers (flat, or
/// (particles, dim)). Throws ValueError naming `what` otherwise.
Vector to_vector(const py::handle& array, Eigen::Index size, const char* what);
/// A new NumPy array holding a copy of `vector`.
py::array_t<double> to_array(const Vector& vector);
/// A read-only NumPy array over `data` (`rows` × `columns`, or flat when columns is 0) that
/// keeps `owner` alive.
py::array_t<double> readonly_view(const double* data, Eigen::Index rows, int columns,
                                  const py::handle& owner);
/// A SciPy sparse CSC matrix holding a copy of `matrix`.
py::object to_scipy(const SparseMatrix& matrix);

/// Error classes, forces, integrators and scenes (scene.cpp).
void add_scene_bindings(py::module_& module);
/// Simulations, trajectories, grading and pictures (simulation.cpp).
void add_simulation_bindings(py::module_& module);

}  // namespace fosssim::python
