#include "scene_result.h"

#include <array>
#include <utility>

namespace fosssim {

namespace {

struct VerdictNames {
  Verdict verdict;
  const char* label;
  const char* id;
};

constexpr std::array<VerdictNames, 12> kNames = {{
    {Verdict::kPassed, "PASS", "passed"},
    {Verdict::kFailed, "FAIL", "failed"},
    {Verdict::kCrashed, "CRASH", "crashed"},
    {Verdict::kTimedOut, "TIMEOUT", "timeout"},
    {Verdict::kExitStatus, "EXIT", "exit-status"},
    {Verdict::kNoOutput, "NO-OUTPUT", "no-output"},
    {Verdict::kShort, "SHORT", "short"},
    {Verdict::kOversized, "OVERSIZED", "oversized"},
    {Verdict::kGarbage, "GARBAGE", "garbage"},
    {Verdict::kCannotRun, "CANNOT-RUN", "cannot-run"},
    {Verdict::kSceneError, "SCENE-ERROR", "scene-error"},
    {Verdict::kInterrupted, "INTERRUPTED", "interrupted"},
}};

const VerdictNames& names_of(Verdict verdict) {
  for (const VerdictNames& names : kNames) {
    if (names.verdict == verdict) return names;
  }
  return kNames[1];
}

}  // namespace

const char* verdict_label(Verdict verdict) { return names_of(verdict).label; }
const char* verdict_id(Verdict verdict) { return names_of(verdict).id; }

std::optional<Verdict> verdict_from_id(std::string_view id) {
  for (const VerdictNames& names : kNames) {
    if (id == names.id) return names.verdict;
  }
  return std::nullopt;
}

std::string suite_of_scene(const std::string& name) {
  const std::size_t slash = name.rfind('/');
  return slash == std::string::npos ? "." : name.substr(0, slash);
}

std::string SceneResult::suite() const { return suite_of_scene(name); }

}  // namespace fosssim
