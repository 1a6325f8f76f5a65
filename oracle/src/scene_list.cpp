#include "scene_list.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>

#include "core/error.h"
#include "printable_text.h"
#include "scene_result.h"

namespace fosssim {

namespace fs = std::filesystem;

namespace {

/// The name a folder argument contributes: its own last component, even for "." or "dir/".
std::string folder_label(const fs::path& folder) {
  std::error_code error;
  fs::path absolute = fs::weakly_canonical(fs::absolute(folder, error), error);
  if (absolute.filename().empty()) absolute = absolute.parent_path();
  return absolute.filename().string();
}

bool is_scene_file(const fs::directory_entry& entry) {
  std::error_code error;
  return entry.is_regular_file(error) && entry.path().extension() == ".xml";
}

[[noreturn]] void fail(const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); }

/// Appends the scenes under one folder argument; throws Error (kBadInput) when it cannot.
void collect(const std::string& argument, bool extra_credit, bool missing_is_empty,
             std::vector<SceneEntry>& out) {
  const fs::path folder(argument);
  std::error_code error;
  const fs::file_status status = fs::status(folder, error);
  if (!fs::exists(status)) {
    if (missing_is_empty) return;
    fail("the scene folder " + argument + " does not exist");
  }
  if (fs::is_regular_file(status)) {
    out.push_back({printable_text(folder.filename().string()),
                   fs::absolute(folder).lexically_normal().string(), extra_credit});
    return;
  }
  if (!fs::is_directory(status)) fail(argument + " is neither a folder nor a scene file");
  const std::string label = folder_label(folder);
  fs::recursive_directory_iterator it(folder, fs::directory_options::follow_directory_symlink,
                                      error);
  if (error) fail("cannot read the folder " + argument + ": " + error.message());
  for (const fs::recursive_directory_iterator end; it != end; it.increment(error)) {
    if (error) fail("cannot read the folder " + argument + ": " + error.message());
    if (!is_scene_file(*it)) continue;
    const fs::path relative = it->path().lexically_relative(folder);
    out.push_back({printable_text(label + "/" + relative.generic_string()),
                   fs::absolute(it->path()).lexically_normal().string(), extra_credit});
  }
  if (error) fail("cannot read the folder " + argument + ": " + error.message());
}

}  // namespace

std::string SceneEntry::suite() const { return suite_of_scene(name); }

std::vector<SceneEntry> discover_scenes(const std::vector<std::string>& folders,
                                        const std::vector<std::string>& extra_credit_folders,
                                        bool missing_folders_are_empty) {
  std::vector<SceneEntry> regular, extra;
  for (const std::string& folder : folders) {
    collect(folder, false, missing_folders_are_empty, regular);
  }
  for (const std::string& folder : extra_credit_folders) {
    collect(folder, true, missing_folders_are_empty, extra);
  }
  const auto by_name = [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; };
  std::sort(regular.begin(), regular.end(), by_name);
  std::sort(extra.begin(), extra.end(), by_name);
  std::vector<SceneEntry> all = std::move(regular);
  all.insert(all.end(), extra.begin(), extra.end());
  std::map<std::string, const SceneEntry*> seen;
  for (const SceneEntry& entry : all) {
    auto [it, inserted] = seen.emplace(entry.name, &entry);
    if (!inserted) {
      if (it->second->path == entry.path) {
        fail("the scene " + entry.path + " is listed twice (two folder arguments overlap)");
      }
      fail("two scenes would both be named " + entry.name + " (" + it->second->path + " and " +
           entry.path + "); give folders with different names");
    }
  }
  return all;
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard shard;
  const auto parse = [](std::string_view digits, int& value) {
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return result.ec == std::errc() && result.ptr == digits.data() + digits.size() &&
           !digits.empty();
  };
  if (slash == std::string::npos || !parse(std::string_view(text).substr(0, slash), shard.index) ||
      !parse(std::string_view(text).substr(slash + 1), shard.count)) {
    fail("--shard takes K/N with whole numbers, as in 2/8; found \"" + text + "\"");
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    fail("--shard K/N needs 1 <= K <= N; found \"" + text + "\"");
  }
  return shard;
}

std::vector<SceneEntry> select_shard(const std::vector<SceneEntry>& all, const Shard& shard) {
  std::vector<SceneEntry> selected;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (shard.contains(i)) selected.push_back(all[i]);
  }
  return selected;
}

}  // namespace fosssim
