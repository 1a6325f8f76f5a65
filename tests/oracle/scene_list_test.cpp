#include "scene_list.h"

#include <gtest/gtest.h>

#include "support/thrown.h"
#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;

std::vector<std::string> names(const std::vector<SceneEntry>& entries) {
  std::vector<std::string> out;
  for (const SceneEntry& e : entries) out.push_back(e.name);
  return out;
}

TEST(DiscoverScenes, NamesScenesByFolderNameAndSortsRegularBeforeExtraCredit) {
  auto scenes = discover_scenes({testing::kAssets}, {testing::kExtraCredit});
  EXPECT_EQ(
      names(scenes),
      (std::vector<std::string>{
          "assets/basics/spring_chain_explicit.xml", "assets/basics/spring_chain_symplectic.xml",
          "assets/implicit/damped_spring_linearized.xml", "assets/implicit/orbit_implicit.xml",
          "extracreditassets/vortex/vortex_symplectic.xml"}));
  EXPECT_FALSE(scenes[3].extra_credit);
  EXPECT_TRUE(scenes[4].extra_credit);
  EXPECT_EQ(scenes[0].suite(), "assets/basics");
  EXPECT_EQ(scenes[0].path, testing::kChainScene);
}

TEST(DiscoverScenes, NameDoesNotDependOnHowTheFolderIsWritten) {
  const auto plain = discover_scenes({testing::kAssets}, {});
  const auto slashed = discover_scenes({testing::kAssets + "/basics/../"}, {});
  EXPECT_EQ(names(plain), names(slashed));
}

TEST(DiscoverScenes, ReportsMissingFoldersAndDuplicateNames) {
  const Error missing_error = thrown_by<Error>([&] { discover_scenes({"/no/such/folder"}, {}); });
  EXPECT_NE(std::string(missing_error.what()).find("/no/such/folder does not exist"),
            std::string::npos);
  auto tolerated = discover_scenes({"/no/such/folder"}, {}, true);
  EXPECT_TRUE(tolerated.empty());

  TemporaryFolder a, b;
  testing::write_bytes(a / "assets/x.xml", "<scene/>");
  testing::write_bytes(b / "assets/x.xml", "<scene/>");
  testing::write_bytes(b / "assets/notes.txt", "not a scene");
  const Error clash_error =
      thrown_by<Error>([&] { discover_scenes({a / "assets"}, {b / "assets"}); });
  EXPECT_NE(std::string(clash_error.what()).find("both be named assets/x.xml"), std::string::npos);
  const Error twice_error = thrown_by<Error>([&] {
    discover_scenes({a / "assets", a / "assets"}, {});
  });
  EXPECT_NE(std::string(twice_error.what()).find("listed twice"), std::string::npos);
}

TEST(Shards, ParseAndPartitionRoundRobin) {
  for (const char* bad : {"0/3", "4/3", "1/0", "a/b", "2", "1/2/3"}) {
    EXPECT_THROW(parse_shard(bad), Error) << bad;
  }
  auto shard = parse_shard("2/3");
  EXPECT_EQ(shard.index, 2);
  EXPECT_EQ(shard.count, 3);

  std::vector<SceneEntry> all;
  for (char k = 0; k < 10; ++k) all.push_back({std::string("s") + char('0' + k), "", false});
  std::vector<std::string> covered;
  for (int k = 1; k <= 3; ++k) {
    for (const SceneEntry& e : select_shard(all, Shard{k, 3})) covered.push_back(e.name);
  }
  EXPECT_EQ(names(select_shard(all, Shard{2, 3})), (std::vector<std::string>{"s1", "s4", "s7"}));
  std::sort(covered.begin(), covered.end());
  std::vector<std::string> expected = names(all);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(covered, expected);  // every scene in exactly one shard
  EXPECT_EQ(names(select_shard(all, Shard{5, 20})), std::vector<std::string>{"s4"});
  EXPECT_TRUE(select_shard(all, Shard{15, 20}).empty());  // more shards than scenes
}

}  // namespace
}  // namespace fosssim
