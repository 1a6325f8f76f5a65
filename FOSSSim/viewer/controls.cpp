#include "viewer/controls.h"

#include <cmath>

namespace fosssim {

Command command_for_key(unsigned char key) {
  switch (key) {
    case ' ':
      return Command::kTogglePause;
    case 's':
    case 'S':
      return Command::kSingleStep;
    case 'q':
    case 'Q':
    case 27:  // Esc
      return Command::kQuit;
    case 'c':
    case 'C':
      return Command::kRecenter;
    case '-':
    case '_':
      return Command::kZoomOut;
    case '=':
    case '+':
      return Command::kZoomIn;
    default:
      return Command::kNone;
  }
}

Command command_for_arrow(ArrowKey key) {
  switch (key) {
    case ArrowKey::kLeft:
      return Command::kPanLeft;
    case ArrowKey::kRight:
      return Command::kPanRight;
    case ArrowKey::kUp:
      return Command::kPanUp;
    case ArrowKey::kDown:
      return Command::kPanDown;
  }
  return Command::kNone;
}

bool apply_camera_command(Command command, Camera& camera) {
  const double step = kPanStep * camera.scale;
  switch (command) {
    case Command::kZoomOut:
      zoom_camera(camera, kZoomStep);
      return true;
    case Command::kZoomIn:
      zoom_camera(camera, 1.0 / kZoomStep);
      return true;
    case Command::kPanLeft:
      camera.cx -= step;
      return true;
    case Command::kPanRight:
      camera.cx += step;
      return true;
    case Command::kPanUp:
      camera.cy += step;
      return true;
    case Command::kPanDown:
      camera.cy -= step;
      return true;
    default:
      return false;
  }
}

double zoom_factor_for_drag(double dx, double dy, int width, int height) {
  const double across = -dx / width, down = dy / height;
  const double amount = std::abs(across) > std::abs(down) ? across : down;
  return std::exp(2.0 * amount);
}

bool apply_view_command(Command command, SceneView& view) {
  if (!view.is_3d()) return apply_camera_command(command, view.camera());
  const double step = kPanStep * 0.5 * view.height();  // pixels
  switch (command) {
    case Command::kZoomOut:
      view.zoom(kZoomStep);
      return true;
    case Command::kZoomIn:
      view.zoom(1.0 / kZoomStep);
      return true;
    case Command::kPanLeft:  // the view moves left: the picture moves right
      view.pan(step, 0.0);
      return true;
    case Command::kPanRight:
      view.pan(-step, 0.0);
      return true;
    case Command::kPanUp:
      view.pan(0.0, step);
      return true;
    case Command::kPanDown:
      view.pan(0.0, -step);
      return true;
    default:
      return false;
  }
}

MouseAction mouse_action(MouseButton button, KeyModifiers modifiers, bool three_d) {
  switch (button) {
    case MouseButton::kLeft:
      if (modifiers.ctrl) return MouseAction::kGrab;
      if (three_d && !modifiers.shift) return MouseAction::kOrbit;
      return MouseAction::kPan;
    case MouseButton::kMiddle:
      return MouseAction::kPan;
    case MouseButton::kRight:
      return MouseAction::kZoom;
  }
  return MouseAction::kNone;
}

}  // namespace fosssim
