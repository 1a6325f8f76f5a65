#include "sha256.h"

#include <openssl/evp.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "core/error.h"

namespace fosssim {

namespace {

/// One SHA-256 computation through OpenSSL's EVP digest interface.
class Sha256 {
 public:
  Sha256() : context_(EVP_MD_CTX_new()) {
    check(context_ != nullptr && EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) == 1);
  }

  void update(const void* data, std::size_t size) {
    check(EVP_DigestUpdate(context_.get(), data, size) == 1);
  }

  /// Finishes the digest: 64 lowercase hexadecimal digits.
  std::string hex_digest() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    check(EVP_DigestFinal_ex(context_.get(), digest, &size) == 1);
    static constexpr char kHex[] = "0123456789abcdef";
    std::string hex;
    for (unsigned int k = 0; k < size; ++k) {
      hex.push_back(kHex[digest[k] >> 4]);
      hex.push_back(kHex[digest[k] & 15]);
    }
    return hex;
  }

 private:
  struct ContextDeleter {
    void operator()(EVP_MD_CTX* context) const { EVP_MD_CTX_free(context); }
  };

  /// OpenSSL fails here only when it cannot allocate or finds no SHA-256 provider.
  static void check(bool ok) {
    if (!ok) throw Error(ErrorKind::kUnavailable, "OpenSSL cannot compute a SHA-256 digest");
  }

  std::unique_ptr<EVP_MD_CTX, ContextDeleter> context_;
};

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  Sha256 hasher;
  hasher.update(bytes.data(), bytes.size());
  return hasher.hex_digest();
}

std::string sha256_file_hex(const std::string& path) {
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rbe"));
  if (!file) return "";
  Sha256 hasher;
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof(buffer), file.get())) > 0) hasher.update(buffer, got);
  if (std::ferror(file.get())) return "";
  return hasher.hex_digest();
}

}  // namespace fosssim
