#include <new>
#include <ostream>

#include "app/commands.h"
#include "cli/exit_codes.h"
#include "io/scene_error.h"

namespace fosssim {

int report_failure(std::ostream& out, const std::exception& failure, const std::string& kept) {
  const std::string note = kept.empty() ? "" : "; " + kept;
  if (dynamic_cast<const SceneError*>(&failure) != nullptr) {
    out << failure.what() << note << "\n";  // already "file:line: error: ..."
  } else if (dynamic_cast<const std::bad_alloc*>(&failure) != nullptr) {
    out << "FOSSSim: error: out of memory: the scene is too large for this machine (see "
           "docs/limits-and-failures.md for the limits on scenes, --max-particles and "
           "--max-file-size)"
        << note << "\n";
  } else {
    out << "FOSSSim: error: " << failure.what() << note << "\n";
  }
  if (const auto* error = dynamic_cast<const Error*>(&failure)) return exit_status(error->kind());
  return kExitBadInput;
}

}  // namespace fosssim
