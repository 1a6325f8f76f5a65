#include <ostream>

#include "app/commands.h"
#include "io/scene_error.h"

namespace fosssim {

void print_error(std::ostream& out, const Error& error) {
  if (dynamic_cast<const SceneError*>(&error) != nullptr) {
    out << error.what() << "\n";  // already "file:line: error: ..."
  } else {
    out << "FOSSSim: error: " << error.what() << "\n";
  }
}

}  // namespace fosssim
