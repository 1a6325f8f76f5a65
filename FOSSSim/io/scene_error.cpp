#include "io/scene_error.h"

namespace fosssim {

namespace {
std::string format_message(const std::string& file, int line, const std::string& element,
                           const std::string& problem) {
  std::string message = file;
  if (line > 0) message.append(":").append(std::to_string(line));
  message += ": error: ";
  if (!element.empty()) message += element + ": ";
  return message + problem;
}
}  // namespace

SceneError::SceneError(std::string file, int line, std::string element, std::string problem)
    : Error(ErrorKind::kBadInput, format_message(file, line, element, problem)),
      file_(std::move(file)),
      line_(line),
      element_(std::move(element)),
      problem_(std::move(problem)) {}

}  // namespace fosssim
