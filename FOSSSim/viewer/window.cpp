#include "viewer/window.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <vector>

#include "core/step/cancellation.h"
#include "pictures/cairo_painter.h"
#include "viewer/controls.h"
#include "viewer/glut_library.h"
#include "viewer/mouse_control.h"
#include "viewer/throttle.h"

namespace fosssim {

namespace {

constexpr int kTickMilliseconds = 10;
/// Wall time the window may spend stepping between two pictures, so it stays responsive.
constexpr double kStepBudgetSeconds = 0.05;

double wall_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

/// The state of the open window; GLUT's C callbacks reach it through `g_window`.
class Window {
 public:
  Window(Stepper& stepper, SceneView& view, const WindowSettings& settings,
         const WindowEvents& events)
      : stepper_(stepper),
        view_(view),
        settings_(settings),
        events_(events),
        throttle_(settings.max_steps_per_second),
        mouse_(view, settings.grab),
        paused_(settings.screenshot_path.empty() && settings.start_paused) {
    throttle_.restart(wall_seconds());
  }

  void display();
  void tick();
  void key(unsigned char key);
  void arrow(ArrowKey key);
  void mouse(int button, int state, int x, int y);
  void motion(int x, int y);
  void reshape(int width, int height);

  WindowOutcome outcome() const { return {finished_, failed_}; }

 private:
  bool can_step() const { return !finished_ && !failed_ && !cancelled_; }
  void step_once();
  void set_paused(bool paused);
  std::vector<std::string> status() const;
  bool screenshot_due() const;
  void take_screenshot();

  Stepper& stepper_;
  SceneView& view_;
  const WindowSettings& settings_;
  const WindowEvents& events_;
  Throttle throttle_;
  MouseControl mouse_;
  bool paused_;
  bool finished_ = false, failed_ = false, cancelled_ = false;
};

Window* g_window = nullptr;

void Window::step_once() {
  try {
    stepper_.step();
  } catch (const StepError& error) {
    failed_ = true;
    if (events_.failed) events_.failed(error);
    return;
  } catch (const StepCancelled&) {
    // The caller asked a step in progress to stop (a signal): the step is abandoned unseen and
    // the window closes as it does when stop_requested says so between frames.
    cancelled_ = true;
    glut().glutLeaveMainLoop();
    return;
  }
  view_.record(stepper_.state());
  if (events_.stepped) events_.stepped(stepper_.state(), view_);
  if (stepper_.finished()) {
    finished_ = true;
    if (events_.finished) events_.finished();
  }
}

void Window::set_paused(bool paused) {
  paused_ = paused;
  if (!paused_) throttle_.restart(wall_seconds());
}

void Window::tick() {
  if (settings_.stop_requested && settings_.stop_requested()) {
    glut().glutLeaveMainLoop();
    return;
  }
  if (!paused_ && can_step() && !screenshot_due()) {
    const double start = wall_seconds();
    bool stepped = false;
    for (std::int64_t due = throttle_.take_due(start); due > 0 && can_step(); --due) {
      step_once();
      stepped = true;
      if (screenshot_due() || wall_seconds() - start > kStepBudgetSeconds) break;
    }
    // Only a step changes the picture here; keys, the mouse and resizing post their own redraw.
    if (stepped) glut().glutPostRedisplay();
  }
  glut().glutTimerFunc(
      kTickMilliseconds, [](int) { g_window->tick(); }, 0);
}

std::vector<std::string> Window::status() const {
  std::vector<std::string> lines;
  if (failed_) {
    lines.push_back("step failed (q: quit)");
  } else if (finished_) {
    lines.push_back("finished (q: quit)");
  } else if (paused_) {
    lines.push_back("paused (space: run, s: step)");
  }
  return lines;
}

bool Window::screenshot_due() const {
  return !settings_.screenshot_path.empty() &&
         (stepper_.state().step >= settings_.screenshot_step || !can_step());
}

void Window::display() {
  Overlay overlay = stepper_.overlay();
  for (std::string& line : status()) overlay.status.push_back(std::move(line));
  if (settings_.grab) overlay.drag = settings_.grab->guide();
  const Image image = render_image(view_.compose(stepper_.state(), overlay));
  // Cairo's rows run top to bottom, OpenGL's bottom to top.
  std::vector<std::uint32_t> flipped(image.pixels.size());
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&flipped[static_cast<std::size_t>(image.height - 1 - y) * image.width],
                &image.pixels[static_cast<std::size_t>(y) * image.width],
                sizeof(std::uint32_t) * image.width);
  }
  glut().glViewport(0, 0, image.width, image.height);
  glut().glMatrixMode(GL_PROJECTION);
  glut().glLoadIdentity();
  glut().glOrtho(0.0, image.width, 0.0, image.height, -1.0, 1.0);
  glut().glMatrixMode(GL_MODELVIEW);
  glut().glLoadIdentity();
  glut().glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glut().glRasterPos2i(0, 0);
  glut().glDrawPixels(image.width, image.height, GL_BGRA, GL_UNSIGNED_BYTE, flipped.data());
  if (screenshot_due()) take_screenshot();
  glut().glutSwapBuffers();
}

void Window::take_screenshot() {
  glut().glFinish();
  Image shot;
  shot.width = view_.width();
  shot.height = view_.height();
  std::vector<std::uint32_t> rows(static_cast<std::size_t>(shot.width) * shot.height);
  glut().glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glut().glReadBuffer(GL_BACK);
  glut().glReadPixels(0, 0, shot.width, shot.height, GL_BGRA, GL_UNSIGNED_BYTE, rows.data());
  shot.pixels.resize(rows.size());
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < shot.width; ++x) {
      shot.pixels[static_cast<std::size_t>(y) * shot.width + x] =
          rows[static_cast<std::size_t>(shot.height - 1 - y) * shot.width + x] | 0xff000000u;
    }
  }
  try {
    write_png(shot, settings_.screenshot_path);
  } catch (const Error& error) {
    std::cerr << "FOSSSim: error: " << error.what() << "\n";
  }
  glut().glutLeaveMainLoop();
}

void Window::key(unsigned char key) {
  const Command command = command_for_key(key);
  switch (command) {
    case Command::kTogglePause:
      set_paused(!paused_);
      break;
    case Command::kSingleStep:
      set_paused(true);
      if (can_step()) step_once();
      break;
    case Command::kQuit:
      glut().glutLeaveMainLoop();
      return;
    case Command::kRecenter:
      view_.recenter(stepper_.state());
      break;
    default:
      if (!apply_view_command(command, view_)) return;
  }
  glut().glutPostRedisplay();
}

void Window::arrow(ArrowKey key) {
  apply_view_command(command_for_arrow(key), view_);
  glut().glutPostRedisplay();
}

void Window::mouse(int button, int state, int x, int y) {
  constexpr int kWheelUp = 3, kWheelDown = 4;  // freeglut reports the wheel as buttons
  if (button == kWheelUp || button == kWheelDown) {
    if (state == GLUT_DOWN) {
      mouse_.wheel(button == kWheelUp);
      glut().glutPostRedisplay();
    }
    return;
  }
  MouseButton which;
  switch (button) {
    case GLUT_LEFT_BUTTON:
      which = MouseButton::kLeft;
      break;
    case GLUT_MIDDLE_BUTTON:
      which = MouseButton::kMiddle;
      break;
    case GLUT_RIGHT_BUTTON:
      which = MouseButton::kRight;
      break;
    default:
      return;
  }
  const int held = glut().glutGetModifiers();
  const KeyModifiers modifiers{(held & GLUT_ACTIVE_SHIFT) != 0, (held & GLUT_ACTIVE_CTRL) != 0};
  const bool changed = state == GLUT_DOWN ? mouse_.press(which, modifiers, x, y, stepper_.state())
                                          : mouse_.release(which);
  if (changed) glut().glutPostRedisplay();
}

void Window::motion(int x, int y) {
  if (mouse_.move(x, y)) glut().glutPostRedisplay();
}

void Window::reshape(int width, int height) {
  if (width > 0 && height > 0) view_.resize(width, height);
  glut().glutPostRedisplay();
}

}  // namespace

void check_display() {
  // The connection stays open for the life of the process: an X server whose last client
  // leaves resets itself, and connections attempted during the reset (GLUT's own, moments
  // later) fail.
  static Display* const connection = glut().XOpenDisplay(nullptr);
  if (connection != nullptr) return;
  const char* name = std::getenv("DISPLAY");
  throw Error(
      ErrorKind::kUnavailable,
      std::string("cannot open the window: ") +
          (name == nullptr || *name == '\0' ? "there is no display (DISPLAY is not set)"
                                            : "cannot connect to display " + std::string(name)) +
          "; run headless with -d 0 (pictures: -g 1, -m DIR, --movie FILE.mp4) or "
          "under xvfb-run");
}

WindowOutcome run_window(Stepper& stepper, SceneView& view, const WindowSettings& settings,
                         const WindowEvents& events) {
  check_display();
  int argc = 1;
  char program[] = "FOSSSim";
  char* argv[] = {program, nullptr};
  glut().glutInit(&argc, argv);
  glut().glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glut().glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
  glut().glutInitWindowSize(view.width(), view.height());
  Window window(stepper, view, settings, events);
  g_window = &window;
  glut().glutCreateWindow(settings.title.c_str());
  glut().glutDisplayFunc([] { g_window->display(); });
  glut().glutReshapeFunc([](int w, int h) { g_window->reshape(w, h); });
  glut().glutKeyboardFunc([](unsigned char key, int, int) { g_window->key(key); });
  glut().glutSpecialFunc([](int key, int, int) {
    switch (key) {
      case GLUT_KEY_LEFT:
        return g_window->arrow(ArrowKey::kLeft);
      case GLUT_KEY_RIGHT:
        return g_window->arrow(ArrowKey::kRight);
      case GLUT_KEY_UP:
        return g_window->arrow(ArrowKey::kUp);
      case GLUT_KEY_DOWN:
        return g_window->arrow(ArrowKey::kDown);
    }
  });
  glut().glutMouseFunc([](int button, int state, int x, int y) { g_window->mouse(button, state, x, y); });
  glut().glutMotionFunc([](int x, int y) { g_window->motion(x, y); });
  glut().glutTimerFunc(
      kTickMilliseconds, [](int) { g_window->tick(); }, 0);
  if (!settings.screenshot_path.empty()) glut().glutPostRedisplay();
  glut().glutMainLoop();  // returns after glutLeaveMainLoop or when the window is closed
  g_window = nullptr;
  return window.outcome();
}

}  // namespace fosssim
