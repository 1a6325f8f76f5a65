#pragma once
// GLUT, OpenGL and Xlib, loaded when the window opens rather than when a program starts.
//
// Linking them made every FOSSSim run load GLUT, the GL dispatch libraries and the X11 client
// libraries, headless runs included (docs/limits-and-failures.md, "Start-up"). The window
// calls them through this table instead, filled with dlopen from GLUT's library, whose own
// dependencies bring OpenGL and Xlib.

#include <GL/freeglut.h>
#include <X11/Xlib.h>

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
#define FOSSSIM_GLUT_MEMBER(name) decltype(&::name) name = nullptr;
  FOSSSIM_GLUT_FUNCTIONS(FOSSSIM_GLUT_MEMBER)
#undef FOSSSIM_GLUT_MEMBER
};

/// GLUT with OpenGL and Xlib, loaded on the first call and kept for the life of the process.
/// Throws Error (kUnavailable) naming the library and the loader's reason when it cannot be
/// loaded or lacks one of the functions.
const GlutLibrary& glut();

}  // namespace fosssim
