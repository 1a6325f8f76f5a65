#pragma once
// SHA-256 (FIPS 180-4, section 6.2), for the oracle's regression manifest: a digest that changes
// when a single bit of a trajectory changes.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace fosssim {

/// Incremental SHA-256: update() with any number of byte ranges, then hex_digest() once.
/// Follows FIPS 180-4 ("Secure Hash Standard", NIST 2015): 512-bit blocks, big-endian words,
/// padding with 0x80, zeros and the 64-bit message length in bits.
class Sha256 {
 public:
  Sha256();

  /// Appends `size` bytes at `data` to the message.
  void update(const void* data, std::size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }

  /// Pads the message and returns the 32-byte digest. The hasher must not be updated afterwards.
  std::array<std::uint8_t, 32> digest();
  /// The digest as 64 lowercase hexadecimal digits.
  std::string hex_digest();

 private:
  void compress(const std::uint8_t* block);

  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_bytes_ = 0;
  bool finished_ = false;
};

/// SHA-256 of a byte string, as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

/// SHA-256 of a file's bytes; returns an empty string when the file cannot be read.
std::string sha256_file_hex(const std::string& path);

}  // namespace fosssim
