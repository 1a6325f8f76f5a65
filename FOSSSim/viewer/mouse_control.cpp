#include "viewer/mouse_control.h"

namespace fosssim {

bool MouseControl::press(MouseButton button, KeyModifiers modifiers, int x, int y,
                         const State& state) {
  if (button_) return false;
  MouseAction action = mouse_action(button, modifiers, view_.is_3d());
  if (action == MouseAction::kGrab) {
    if (!grab_ || !grab_->press(view_, state, x, y)) return false;
  }
  button_ = button;
  action_ = action;
  last_x_ = x;
  last_y_ = y;
  return action == MouseAction::kGrab;
}

bool MouseControl::release(MouseButton button) {
  if (button_ != button) return false;
  const bool grabbing = action_ == MouseAction::kGrab;
  if (grabbing) grab_->release();
  button_.reset();
  action_ = MouseAction::kNone;
  return grabbing;
}

bool MouseControl::move(int x, int y) {
  const double dx = x - last_x_, dy = y - last_y_;
  last_x_ = x;
  last_y_ = y;
  switch (action_) {
    case MouseAction::kPan:
      view_.pan(dx, dy);
      return true;
    case MouseAction::kZoom:
      view_.zoom(zoom_factor_for_drag(dx, dy, view_.width(), view_.height()));
      return true;
    case MouseAction::kOrbit:
      view_.orbit(dx, dy);
      return true;
    case MouseAction::kGrab:
      grab_->move(view_, x, y);
      return true;
    case MouseAction::kNone:
      return false;
  }
  return false;
}

void MouseControl::wheel(bool up) { view_.zoom(up ? 1.0 / kZoomStep : kZoomStep); }

}  // namespace fosssim
