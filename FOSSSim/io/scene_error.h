#pragma once

#include <cstddef>
#include <string>
#include <vector>

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

 protected:
  /// The located parts of `first`, with `message` as the whole text.
  SceneError(const SceneError& first, const std::string& message);

 private:
  std::string file_;
  int line_;
  std::string element_;
  std::string problem_;
};

/// Several problems of one scene file, reported at once: what() holds one line per problem,
/// "file:line: error: ...", in the order of their lines, then "and N more errors" when more
/// than SceneErrorList::kMaxReported were found. file(), line() and problem() are those of the
/// first line.
class SceneErrors final : public SceneError {
 public:
  SceneErrors(std::vector<SceneError> errors, std::size_t total);
  const std::vector<SceneError>& errors() const { return errors_; }
  /// How many problems were found, those left out included.
  std::size_t total() const { return total_; }

 private:
  std::vector<SceneError> errors_;
  std::size_t total_;
};

/// Thrown by a reader for an element that refers to another element that had an error itself
/// (a spring on an edge that could not be read): the element is skipped without a report of
/// its own, since the first report names the cause.
struct DependsOnBrokenElement {};

/// Collects the problems of a scene so that one run reports all of them (docs/scene-format.md).
/// A reader runs each element in attempt(): a SceneError is kept and reading goes on with the
/// next element; at the end throw_if_any() throws the one error alone, or SceneErrors. Only the
/// first kMaxReported problems are kept (a generated file with an error on every line would
/// otherwise print a million lines); the rest are counted.
class SceneErrorList {
 public:
  static constexpr std::size_t kMaxReported = 20;

  /// Runs `read()`; returns false when it threw a SceneError (kept) or DependsOnBrokenElement.
  template <class Read>
  bool attempt(Read&& read) {
    try {
      read();
      return true;
    } catch (const SceneError& error) {
      add(error);
    } catch (const DependsOnBrokenElement&) {
    }
    return false;
  }

  void add(const SceneError& error);
  bool empty() const { return total_ == 0; }
  /// Throws the collected problems, if any.
  void throw_if_any() const;

 private:
  std::vector<SceneError> kept_;
  std::size_t total_ = 0;
};

}  // namespace fosssim
