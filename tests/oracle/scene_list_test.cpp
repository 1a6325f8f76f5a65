#include "scene_list.h"

#include <gtest/gtest.h>

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
  ASSERT_TRUE(scenes) << scenes.error();
  EXPECT_EQ(
      names(*scenes),
      (std::vector<std::string>{
          "assets/basics/spring_chain_explicit.xml", "assets/basics/spring_chain_symplectic.xml",
          "assets/implicit/damped_spring_linearized.xml", "assets/implicit/orbit_implicit.xml",
          "extracreditassets/vortex/vortex_symplectic.xml"}));
  EXPECT_FALSE((*scenes)[3].extra_credit);
  EXPECT_TRUE((*scenes)[4].extra_credit);
  EXPECT_EQ((*scenes)[0].suite(), "assets/basics");
  EXPECT_EQ((*scenes)[0].path, testing::kChainScene);
}

TEST(DiscoverScenes, NameDoesNotDependOnHowTheFolderIsWritten) {
  auto plain = discover_scenes({testing::kAssets}, {});
  auto slashed = discover_scenes({testing::kAssets + "/basics/../"}, {});
  ASSERT_TRUE(plain && slashed);
  EXPECT_EQ(names(*plain), names(*slashed));
}

TEST(DiscoverScenes, ReportsMissingFoldersAndDuplicateNames) {
  auto missing = discover_scenes({"/no/such/folder"}, {});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/no/such/folder does not exist"), std::string::npos);
  auto tolerated = discover_scenes({"/no/such/folder"}, {}, true);
  ASSERT_TRUE(tolerated);
  EXPECT_TRUE(tolerated->empty());

  TemporaryFolder a, b;
  testing::write_bytes(a / "assets/x.xml", "<scene/>");
  testing::write_bytes(b / "assets/x.xml", "<scene/>");
  testing::write_bytes(b / "assets/notes.txt", "not a scene");
  auto clash = discover_scenes({a / "assets"}, {b / "assets"});
  ASSERT_FALSE(clash);
  EXPECT_NE(clash.error().find("both be named assets/x.xml"), std::string::npos);
  auto twice = discover_scenes({a / "assets", a / "assets"}, {});
  ASSERT_FALSE(twice);
  EXPECT_NE(twice.error().find("listed twice"), std::string::npos);
}

TEST(Shards, ParseAndPartitionRoundRobin) {
  EXPECT_FALSE(parse_shard("0/3"));
  EXPECT_FALSE(parse_shard("4/3"));
  EXPECT_FALSE(parse_shard("1/0"));
  EXPECT_FALSE(parse_shard("a/b"));
  EXPECT_FALSE(parse_shard("2"));
  EXPECT_FALSE(parse_shard("1/2/3"));
  auto shard = parse_shard("2/3");
  ASSERT_TRUE(shard);
  EXPECT_EQ(shard->index, 2);
  EXPECT_EQ(shard->count, 3);

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
