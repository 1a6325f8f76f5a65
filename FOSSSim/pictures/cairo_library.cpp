#include "pictures/cairo_library.h"

namespace fosssim {

const CairoLibrary& cairo() {
  static const CairoLibrary table;  // a failed load is tried again next time
  return table;
}

}  // namespace fosssim
