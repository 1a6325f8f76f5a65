#pragma once
// The interface of every time-stepping method: precompute for one model, then step.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/force_set.h"
#include "core/integrators/integrator_method.h"
#include "core/integrators/solver_report.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "core/step/cancellation.h"

namespace fosssim {

/// Advances a state by one time step of the model it is bound to, in the style of libigl's
/// *_precompute / *_solve pairs: precompute() binds the integrator to one model (and the
/// interaction forces of whoever runs it) and does the work that depends on them alone (index
/// maps, constant matrices and their factorizations); step() then only does per-step work.
/// Integrators are made unbound by their registry entry (make_integrator does both).
class Integrator {
 public:
  virtual ~Integrator() = default;

  /// Binds to `model`, whose forces are summed first, then `interaction` (core/force_set.h).
  /// Both must outlive the integrator, and the model must not change while it is bound (its
  /// time step is checked at every step). Binding twice is a programming error
  /// (std::logic_error). Throws Error (kStepFailed) when the model cannot be integrated by
  /// this method (for example, a constant matrix that is not positive definite).
  void precompute(const SceneModel& model, std::vector<const Force*> interaction = {});

  /// Takes one step of h = model.integrator.dt: updates q and v, then step and time. Throws
  /// StepError when the step cannot be taken (a singular system, no convergence). Stepping an
  /// unbound integrator, a state of another size than the model's, or a model whose time step
  /// changed since precompute, is a programming error (std::logic_error).
  void step(State& state);

  bool is_bound() const { return forces_.has_value(); }
  /// The model it is bound to.
  const SceneModel& model() const { return forces_->model(); }
  /// The forces it sums: the model's, then the interaction forces.
  const ForceSet& forces() const { return *forces_; }

  /// Things the user should know about the run so far (for example, fallbacks taken), one
  /// sentence each; empty when there is nothing to say.
  virtual std::vector<std::string> notes() const { return {}; }

  /// What its solvers did: the last step's iterations and the totals so far (solver_report.h).
  virtual SolverReport solver_report() const { return {}; }

  /// What the iterations of step() ask once per iteration (core/step/cancellation.h); by
  /// default nothing cancels.
  void set_cancellation(Cancellation cancellation) { cancellation_ = cancellation; }

 protected:
  const Cancellation& cancellation() const { return cancellation_; }
  /// The method's precomputation; model() and forces() are set.
  virtual void prepare() {}
  /// Updates state.q and state.v from step state.step to state.step + 1.
  virtual void advance(State& state) = 0;

 private:
  std::optional<ForceSet> forces_;
  double dt_ = 0.0;  // the model's time step at precompute
  Cancellation cancellation_;
};

/// The model's integrator (model.integrator: method and options), bound to the model and
/// `interaction` and precomputed.
std::unique_ptr<Integrator> make_integrator(const SceneModel& model,
                                            std::vector<const Force*> interaction = {});

}  // namespace fosssim
