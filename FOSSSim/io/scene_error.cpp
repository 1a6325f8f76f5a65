#include "io/scene_error.h"

#include <algorithm>

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

/// The errors sorted by line (stable: one line's errors keep the order they were found in).
std::vector<SceneError> by_line(std::vector<SceneError> errors) {
  std::stable_sort(errors.begin(), errors.end(),
                   [](const SceneError& a, const SceneError& b) { return a.line() < b.line(); });
  return errors;
}

std::string join(const std::vector<SceneError>& errors, std::size_t total) {
  std::string message;
  for (const SceneError& error : errors) {
    if (!message.empty()) message += "\n";
    message += error.what();
  }
  if (total > errors.size()) {
    const std::size_t more = total - errors.size();
    message += "\n... and " + std::to_string(more) + " more error" + (more == 1 ? "" : "s") +
               " (only the first " + std::to_string(errors.size()) + " are shown)";
  }
  return message;
}
}  // namespace

SceneError::SceneError(std::string file, int line, std::string element, std::string problem)
    : Error(ErrorKind::kBadInput, format_message(file, line, element, problem)),
      file_(std::move(file)),
      line_(line),
      element_(std::move(element)),
      problem_(std::move(problem)) {}

SceneError::SceneError(const SceneError& first, const std::string& message)
    : Error(ErrorKind::kBadInput, message),
      file_(first.file_),
      line_(first.line_),
      element_(first.element_),
      problem_(first.problem_) {}

SceneErrors::SceneErrors(std::vector<SceneError> errors, std::size_t total)
    : SceneError(errors.front(), join(errors, total)), errors_(std::move(errors)), total_(total) {}

void SceneErrorList::add(const SceneError& error) {
  ++total_;
  if (kept_.size() < kMaxReported) kept_.push_back(error);
}

void SceneErrorList::throw_if_any() const {
  if (total_ == 0) return;
  if (total_ == 1) throw kept_.front();
  std::vector<SceneError> sorted = by_line(kept_);
  throw SceneErrors(std::move(sorted), total_);
}

}  // namespace fosssim
