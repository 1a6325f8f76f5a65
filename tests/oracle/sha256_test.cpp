#include "sha256.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

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

TEST(Sha256, PaddingBoundariesAgreeBetweenWholeAndPiecewiseInput) {
  // Lengths around the 55/56/64-byte padding boundaries, fed at once and one byte at a time.
  for (std::size_t length : {0u, 1u, 55u, 56u, 57u, 63u, 64u, 65u, 119u, 120u, 128u, 1000u}) {
    std::string message;
    for (std::size_t k = 0; k < length; ++k) message.push_back(static_cast<char>(k * 7 + 3));
    Sha256 piecewise;
    for (char c : message) piecewise.update(&c, 1);
    EXPECT_EQ(piecewise.hex_digest(), sha256_hex(message)) << "length " << length;
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
