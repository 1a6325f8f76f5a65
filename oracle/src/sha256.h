#pragma once
// SHA-256 digests for the oracle's regression manifest: a digest that changes when a single bit
// of a trajectory changes. The hashing is OpenSSL's (libcrypto's EVP interface); this file only
// adds the hexadecimal text the manifest stores and the streaming of a file.

#include <string>
#include <string_view>

namespace fosssim {

/// SHA-256 of a byte string, as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

/// SHA-256 of a file's bytes, read in pieces of 64 KiB (never the whole file in memory), as 64
/// lowercase hexadecimal digits; an empty string when the file cannot be read.
std::string sha256_file_hex(const std::string& path);

}  // namespace fosssim
