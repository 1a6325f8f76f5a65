#include "manifest.h"

#include <gtest/gtest.h>

#include "child_process.h"
#include "sha256.h"
#include "support/thrown.h"
#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;

const std::string kRegenerate = "REGENERATE-COMMAND";

std::vector<SceneEntry> test_scenes() {
  return discover_scenes({testing::kAssets, testing::kExtraCredit}, {});
}

std::vector<ManifestEntry> compute_with(const std::string& candidate, const TemporaryFolder& work) {
  CandidateRunOptions options;
  options.candidate = candidate;
  options.timeout_seconds = 60.0;
  options.readable = testing::sandbox_readable();  // the perturbing candidate runs FOSSSim
  return compute_manifest(test_scenes(), options, work.path(), 2);
}

TEST(FinalStateText, OneLinePerParticleWithShortestRoundTripNumbers) {
  Vector q(4), v(4);
  q << 0.1, -2.0, 1.0 / 3.0, 0.0;
  v << 1e-300, 5.0, -0.0, 7.25;
  EXPECT_EQ(final_state_text(q, v, 2),
            "0\t0.1\t-2\t1e-300\t5\n1\t0.3333333333333333\t0\t-0\t7.25\n");
}

TEST(Manifest, DigestsFossSimsTrajectoriesAndRoundTripsThroughItsFolder) {
  TemporaryFolder work, folder;
  const auto entries = compute_with(testing::kFossSim, work);
  ASSERT_EQ(entries.size(), 5u);
  for (const ManifestEntry& e : entries) {
    EXPECT_EQ(e.status, "ok") << e.scene;
    EXPECT_EQ(e.sha256.size(), 64u);
  }
  EXPECT_EQ(entries[0].scene, "assets/basics/spring_chain_explicit.xml");
  EXPECT_EQ(entries[0].frames, 51);
  EXPECT_EQ(entries[0].sha256, sha256_hex(testing::fosssim_trajectory(testing::kChainScene, work)));

  write_manifest(folder.path(), entries, kRegenerate);
  auto read = read_manifest(folder.path());
  EXPECT_EQ(read, entries);
  EXPECT_TRUE(std::filesystem::exists(folder / "final/assets/basics/spring_chain_explicit.txt"));
  EXPECT_TRUE(compare_manifest(read, compute_with(testing::kFossSim, work), kRegenerate).empty());
}

TEST(Manifest, ASingleFlippedBitInAnyFrameIsDetected) {
  TemporaryFolder work;
  const auto golden = compute_with(testing::kFossSim, work);
  testing::use_perturbing_candidate(10, 1, 0,
                                    "flip-bit");  // a middle frame: the final state stays the same
  const auto flipped = compute_with(testing::candidate("perturbing_candidate.sh"), work);
  const auto problems = compare_manifest(golden, flipped, kRegenerate);
  // Every scene's trajectory changed by one bit; each is named, then the hint.
  ASSERT_EQ(problems.size(), golden.size() + 1);
  EXPECT_NE(problems[0].find("assets/basics/spring_chain_explicit.xml: the trajectory changed"),
            std::string::npos)
      << problems[0];
  EXPECT_NE(problems[0].find("the final state is unchanged, so an earlier frame differs"),
            std::string::npos)
      << problems[0];
  EXPECT_NE(problems.back().find(kRegenerate), std::string::npos);
}

TEST(Manifest, AFlippedBitInTheLastFrameNamesTheParticle) {
  TemporaryFolder work;
  const auto golden = compute_with(testing::kFossSim, work);
  testing::use_perturbing_candidate(30, 1, 0, "flip-bit");  // the last frame of the 30-step scenes
  const auto flipped = compute_with(testing::candidate("perturbing_candidate.sh"), work);
  const auto problems = compare_manifest(golden, flipped, kRegenerate);
  bool named = false;
  for (const std::string& p : problems) {
    if (p.rfind("assets/implicit/orbit_implicit.xml:", 0) == 0) {
      EXPECT_NE(p.find("final state now \"1\t"), std::string::npos) << p;
      named = true;
    }
  }
  EXPECT_TRUE(named);
}

TEST(Manifest, NewRemovedFailingAndHandEditedScenesAreReported) {
  ManifestEntry a{"s/a.xml", "ok", 3, 96, std::string(64, 'a'), "0\t1\t2\n"};
  ManifestEntry b{"s/b.xml", "ok", 3, 96, std::string(64, 'b'), "0\t1\t2\n"};
  ManifestEntry c{"s/c.xml", "ok", 3, 96, std::string(64, 'c'), "0\t1\t2\n"};
  ManifestEntry a_crashed = a;
  a_crashed.status = "crashed";
  ManifestEntry c_edited = c;
  c_edited.final_state = "0\t1\t3\n";
  const auto problems = compare_manifest(
      {a, b, c_edited},
      {a_crashed, c, ManifestEntry{"s/new.xml", "ok", 3, 96, std::string(64, 'n'), "0\t1\t2\n"}},
      kRegenerate);
  ASSERT_EQ(problems.size(), 5u);
  EXPECT_NE(problems[0].find("s/a.xml: FOSSSim's run now ends with status \"crashed\""),
            std::string::npos);
  EXPECT_NE(problems[1].find("s/c.xml: the digest matches but the manifest's final state does not"),
            std::string::npos)
      << problems[1];
  EXPECT_NE(
      problems[2].find("s/new.xml: not in the manifest (a new scene?); run `REGENERATE-COMMAND`"),
      std::string::npos)
      << problems[2];
  EXPECT_NE(problems[3].find("s/b.xml: in the manifest, but the scene was not found"),
            std::string::npos);
}

TEST(Manifest, UpdateRemovesFinalStatesOfRemovedScenes) {
  TemporaryFolder folder;
  ManifestEntry a{"s/a.xml", "ok", 3, 96, std::string(64, 'a'), "0\t1\t2\n"};
  ManifestEntry b{"s/b.xml", "ok", 3, 96, std::string(64, 'b'), "0\t1\t2\n"};
  write_manifest(folder.path(), {a, b}, kRegenerate);
  EXPECT_TRUE(std::filesystem::exists(folder / "final/s/b.txt"));
  write_manifest(folder.path(), {a}, kRegenerate);
  EXPECT_FALSE(std::filesystem::exists(folder / "final/s/b.txt"));
  auto read = read_manifest(folder.path());
  EXPECT_EQ(read, std::vector<ManifestEntry>{a});
}

TEST(Manifest, MissingManifestIsAClearError) {
  TemporaryFolder folder;
  const Error read_error = thrown_by<Error>([&] { read_manifest(folder / "nothing"); });
  EXPECT_NE(std::string(read_error.what()).find("golden.tsv"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
