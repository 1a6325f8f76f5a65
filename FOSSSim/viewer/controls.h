#pragma once
// The window's keys and mouse (SPEC section 6), as plain functions the window calls.

#include "render/camera.h"

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

/// Mouse zoom (right button drag): dragging down or left by a whole picture height or width
/// zooms out by e² ≈ 7.4; up or right zooms in. The larger relative movement wins, as in the
/// course's window. dx, dy in pixels (y down).
void zoom_by_drag(Camera& camera, double dx, double dy, int width, int height);

}  // namespace fosssim
