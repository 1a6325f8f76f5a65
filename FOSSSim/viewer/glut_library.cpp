#include "viewer/glut_library.h"

namespace fosssim {

const GlutLibrary& glut() {
  static const GlutLibrary table;  // a failed load is tried again next time
  return table;
}

}  // namespace fosssim
