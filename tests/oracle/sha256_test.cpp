#include "sha256.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

#include "test_support.h"

namespace fosssim {
namespace {

// Test vectors of FIPS 180-4 as published with the standard (NIST CSRC "Example Algorithms",
// SHA256.pdf, and SHA256ShortMsg / LongMsg): "abc", the empty message, the 448-bit and 896-bit
// two-block messages, and one million 'a'.
TEST(Sha256, MatchesTheFips180Vectors) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(
      sha256_hex("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklm"
                 "nopqklmnopqrlmnopqrsmnopqrstnopqrstu"),
      "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AFileStreamedInPiecesHasTheDigestOfItsBytes) {
  // Lengths around the 55/56/64-byte padding boundaries and around the 64 KiB pieces the file
  // is read in: the streamed digest must equal the digest of the whole byte string.
  const testing::TemporaryFolder folder;
  for (std::size_t length : {0u, 1u, 55u, 56u, 57u, 63u, 64u, 65u, 119u, 120u, 128u, 1000u, 65535u,
                             65536u, 65537u, 2u * 65536u + 55u}) {
    std::string message;
    for (std::size_t k = 0; k < length; ++k) message.push_back(static_cast<char>(k * 7 + 3));
    const std::string path = folder / ("message-" + std::to_string(length));
    testing::write_bytes(path, message);
    EXPECT_EQ(sha256_file_hex(path), sha256_hex(message)) << "length " << length;
  }
}

TEST(Sha256, AFileThatCannotBeReadHasNoDigest) {
  const testing::TemporaryFolder folder;
  EXPECT_EQ(sha256_file_hex(folder / "missing"), "");
  EXPECT_EQ(sha256_file_hex(folder.path()), "");  // a folder: opens, but reading fails
}

TEST(Sha256, PaddingBoundariesMatchKnownDigests) {
  // The same byte pattern (k * 7 + 3) at lengths around the padding boundaries, against digests
  // from Python's hashlib: hashlib.sha256(bytes((k * 7 + 3) % 256 for k in range(n))).
  const std::pair<std::size_t, const char*> known[] = {
      {55, "e7313d333c272e639f790978283f9eb392e843d0f29b7016828bb1daa4aac70b"},
      {56, "4324d65f3c103567f5589c710bc08f8523f929a9272e3af36fc968e52abc6c27"},
      {57, "35df609437dcfea3279283ab79fd554e2bf78f8f7ae2de532d8ee300b09e8f73"},
      {63, "81c80242132f230c3bd41b3e63bbcff16107339549214a99614ff26664625055"},
      {64, "39e3d7b6b5d075d37d053ad89b24b41bef4f3c29760c84447cab3f3be1882241"},
      {65, "aacca6ff74fdbb296d165a45cecfa04e5127bc008770fbbdd48006f2d2fae95e"},
      {119, "9ce7368e4daf32341631b492e80359dc9f594b48453cd0dd5bf0b19279cc177e"},
      {120, "7836b787757e95e58b3ca5aec90b1b004e8deba1e50e9675af9cabf1a13a04b5"}};
  for (const auto& [length, digest] : known) {
    std::string message;
    for (std::size_t k = 0; k < length; ++k) message.push_back(static_cast<char>(k * 7 + 3));
    EXPECT_EQ(sha256_hex(message), digest) << "length " << length;
  }
}

TEST(Sha256, EveryFlippedBitOfATrajectorySizedMessageChangesTheDigest) {
  std::string message(512, '\0');
  for (std::size_t k = 0; k < message.size(); ++k) message[k] = static_cast<char>(k * 31 + 1);
  std::set<std::string> digests{sha256_hex(message)};
  for (std::size_t bit = 0; bit < 8 * message.size(); ++bit) {
    std::string flipped = message;
    flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
    digests.insert(sha256_hex(flipped));
  }
  EXPECT_EQ(digests.size(), 8 * message.size() + 1);
}

}  // namespace
}  // namespace fosssim
