#pragma once
// The window's mouse, without the window: drags turn, pan and zoom the view or pull a particle.

#include <optional>

#include "core/state.h"
#include "render/scene_view.h"
#include "viewer/controls.h"
#include "viewer/particle_grab.h"

namespace fosssim {

/// Follows one mouse drag at a time and applies it (mouse_action) to a view and a particle grab.
class MouseControl {
 public:
  /// view: what the window shows; grab: pulls particles, or null where they cannot be pulled
  /// (grading replays). Both must outlive this.
  MouseControl(SceneView& view, ParticleGrab* grab) : view_(view), grab_(grab) {}

  /// A button went down at pixel (x, y) while the window shows `state`. A press during another
  /// drag is ignored. Returns true when the picture changes (a particle was grabbed).
  bool press(MouseButton button, KeyModifiers modifiers, int x, int y, const State& state);
  /// A button went up: ends its drag, letting go of a grabbed particle. Returns true when the
  /// picture changes.
  bool release(MouseButton button);
  /// The mouse moved to (x, y) with a button down; returns true when the picture changes.
  bool move(int x, int y);
  /// One click of the wheel: up zooms in by kZoomStep, down out.
  void wheel(bool up);

  /// What the current drag does (kNone between drags).
  MouseAction action() const { return action_; }

 private:
  SceneView& view_;
  ParticleGrab* grab_;
  std::optional<MouseButton> button_;
  MouseAction action_ = MouseAction::kNone;
  int last_x_ = 0, last_y_ = 0;
};

}  // namespace fosssim
