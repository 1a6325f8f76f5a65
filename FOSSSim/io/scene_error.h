#pragma once

#include <string>

#include "core/error.h"

namespace fosssim {

/// A problem with an input file (scene, mesh), located as precisely as the file allows:
///   "scene.xml:7: error: <particle> 2: attribute "m" must be positive, found "-1""
/// An Error of kind kBadInput.
class SceneError : public Error {
 public:
  /// line 0 means "no line" (a missing or empty file); element may be empty.
  SceneError(std::string file, int line, std::string element, std::string problem);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& element() const { return element_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  int line_;
  std::string element_;
  std::string problem_;
};

}  // namespace fosssim
