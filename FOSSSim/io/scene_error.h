#pragma once

#include <stdexcept>
#include <string>

namespace fosssim {

/// A problem with a scene file, located as precisely as the file allows:
///   "scene.xml:7: error: <particle> 2: attribute "m" must be positive, found "-1""
class SceneError : public std::runtime_error {
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
