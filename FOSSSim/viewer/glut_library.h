#pragma once
// GLUT, OpenGL and Xlib, loaded when the window opens rather than when a program starts.
//
// Linking them made every FOSSSim run load GLUT, the GL dispatch libraries and the X11 client
// libraries, headless runs included (docs/limits-and-failures.md, "Start-up"). The window
// calls them through this table instead, filled with dlopen from GLUT's library, whose own
// dependencies bring OpenGL and Xlib.

#include <GL/freeglut.h>
#include <X11/Xlib.h>

#include "core/shared_library.h"

namespace fosssim {

// The functions the window calls, by their own names.
#define FOSSSIM_GLUT_FUNCTIONS(X)                                                             \
  X(glutCreateWindow) X(glutDisplayFunc) X(glutGetModifiers) X(glutInit)                      \
  X(glutInitDisplayMode) X(glutInitWindowSize) X(glutKeyboardFunc) X(glutLeaveMainLoop)      \
  X(glutMainLoop) X(glutMotionFunc) X(glutMouseFunc) X(glutPostRedisplay) X(glutReshapeFunc) \
  X(glutSetOption) X(glutSpecialFunc) X(glutSwapBuffers) X(glutTimerFunc)                    \
  X(glDrawPixels) X(glFinish) X(glLoadIdentity) X(glMatrixMode) X(glOrtho) X(glPixelStorei)  \
  X(glRasterPos2i) X(glReadBuffer) X(glReadPixels) X(glViewport)                             \
  X(XOpenDisplay)

/// The window's GLUT, OpenGL and Xlib functions: `glut().glutPostRedisplay()`.
struct GlutLibrary {
  // freeglut's sonames: Debian 12's freeglut 3.4, then the older 3.x. The functions are found in
  // GLUT and its dependencies, OpenGL and Xlib.
  SharedLibrary library = SharedLibrary::open({"libglut.so.3.12", "libglut.so.3"},
                                              "the window needs GLUT", "libglut3.12");
  FOSSSIM_GLUT_FUNCTIONS(FOSSSIM_LIBRARY_FUNCTION)
};

/// GLUT with OpenGL and Xlib, loaded on the first call and kept for the life of the process.
/// Throws Error (kUnavailable) naming the library and the loader's reason when it cannot be
/// loaded or lacks one of the functions (core/shared_library.h).
const GlutLibrary& glut();

}  // namespace fosssim
