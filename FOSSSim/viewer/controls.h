#pragma once
// The window's keys and mouse (docs/viewing.md), as plain functions the window calls.

#include "render/camera.h"
#include "render/scene_view.h"

namespace fosssim {

/// What a key asks the window to do.
enum class Command {
  kNone,
  kTogglePause,  ///< space
  kSingleStep,   ///< s: pause, then take one step
  kQuit,         ///< q, Esc
  kRecenter,     ///< c: fit the camera to the particles again
  kZoomOut,      ///< -
  kZoomIn,       ///< = (and +)
  kPanLeft,      ///< arrow keys
  kPanRight,
  kPanUp,
  kPanDown,
};

enum class ArrowKey { kLeft, kRight, kUp, kDown };

/// The command of an ordinary key; kNone for keys without one.
Command command_for_key(unsigned char key);
/// The command of an arrow key.
Command command_for_arrow(ArrowKey key);

/// One press of a zoom key scales the visible height by this factor (or its inverse).
inline constexpr double kZoomStep = 1.1;
/// One press of an arrow key moves the view by this fraction of its half height.
inline constexpr double kPanStep = 0.1;

/// Applies a zoom or pan command to the camera; returns false for other commands.
bool apply_camera_command(Command command, Camera& camera);

/// Mouse zoom (right button drag): the factor a drag of (dx, dy) pixels (y down) scales the
/// visible height by. Dragging down or left by a whole picture height or width zooms out by
/// e² ≈ 7.4; up or right zooms in. The larger relative movement wins, as in the course's window.
double zoom_factor_for_drag(double dx, double dy, int width, int height);

/// Applies a zoom or pan command to a view, 2D (exactly as apply_camera_command) or 3D (zoom
/// keys move the orbit camera nearer or farther by kZoomStep, arrows pan by kPanStep of the
/// half height); returns false for other commands.
bool apply_view_command(Command command, SceneView& view);

enum class MouseButton { kLeft, kMiddle, kRight };

/// Keys held while a mouse button goes down.
struct KeyModifiers {
  bool shift = false;
  bool ctrl = false;
};

/// What a drag with a mouse button does.
enum class MouseAction { kNone, kPan, kZoom, kOrbit, kGrab };

/// The mouse bindings (docs/viewing.md). 2D, as the course's window: left drag pans, right
/// drag zooms; middle drag pans too. 3D: left drag orbits, shift + left or middle drag pans,
/// right drag zooms. In both, ctrl + left drag grabs the particle under the cursor.
MouseAction mouse_action(MouseButton button, KeyModifiers modifiers, bool three_d);

}  // namespace fosssim
