#include "grading_run.h"

namespace fosssim {

Tally tally(const std::vector<SceneResult>& results) {
  Tally t;
  for (const SceneResult& r : results) {
    (r.extra_credit ? t.extra : t.regular) += 1;
    if (r.passed()) (r.extra_credit ? t.extra_passed : t.regular_passed) += 1;
  }
  return t;
}

std::vector<SceneListing> listing_of(const std::vector<SceneEntry>& scenes) {
  std::vector<SceneListing> listing;
  listing.reserve(scenes.size());
  for (const SceneEntry& entry : scenes) listing.push_back({entry.name, entry.extra_credit});
  return listing;
}

}  // namespace fosssim
