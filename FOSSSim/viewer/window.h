#pragma once
// The interactive GLUT window (docs/viewing.md).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/step_error.h"
#include "render/scene_view.h"
#include "viewer/particle_grab.h"
#include "viewer/stepper.h"

namespace fosssim {

struct WindowSettings {
  std::string title = "FOSSSim";
  bool start_paused = true;
  double max_steps_per_second = 100.0;  ///< the scene's maxsimfreq
  /// When not empty: run (ignoring start_paused) until state().step reaches screenshot_step or
  /// the run ends, write the window's framebuffer there as a PNG, and close. For tests.
  std::string screenshot_path;
  std::int64_t screenshot_step = 0;
  /// Polled between steps; true closes the window (Ctrl-C in the terminal, say).
  std::function<bool()> stop_requested;
  /// Pulls particles for the mouse's ctrl + left drag; null: particles cannot be pulled.
  ParticleGrab* grab = nullptr;
};

/// What the window reports to its owner while it runs.
struct WindowEvents {
  /// After every step, with the new state and the view it is shown in.
  std::function<void(const State&, const SceneView&)> stepped;
  /// Once, when the last step has been taken.
  std::function<void()> finished;
  /// When a step fails; the window then stops stepping and keeps showing the last state.
  std::function<void(const StepError&)> failed;
};

/// How the window closed.
struct WindowOutcome {
  bool finished = false;  ///< the run reached its end
  bool failed = false;    ///< a step failed
};

/// Returns when an X display can be opened, else throws Error (kUnavailable) saying why (GLUT
/// itself would end the process).
void check_display();

/// Opens a window of view.width() × view.height() pixels showing `stepper`'s state through
/// `view`, and handles keys and mouse (controls.h, mouse_control.h; docs/viewing.md) until the
/// user quits (q, Esc or closing the window).
/// Steps at most settings.max_steps_per_second per wall second while running. Each picture is
/// the view's drawing painted by Cairo (pictures/cairo_painter.h) and copied to the window, so
/// the window shows exactly what the PNG, SVG and movie outputs show. Throws Error
/// (kUnavailable) when there is no X display to open the window on.
WindowOutcome run_window(Stepper& stepper, SceneView& view, const WindowSettings& settings,
                         const WindowEvents& events);

}  // namespace fosssim
