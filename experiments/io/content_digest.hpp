// A stable digest of bytes: FNV-1a, 64 bits. Written here as the standard library has no
// stable content hash (std::hash may change between builds); it names what a file was made
// from, not a defence against tampering.
#pragma once

#include <cstdint>
#include <string_view>

namespace rice::experiments {

inline constexpr std::uint64_t kDigestBasis = 14695981039346656037ull;

/// The digest of `bytes`, continuing from `hash` (the digest of what came before them).
inline std::uint64_t content_digest(std::string_view bytes, std::uint64_t hash = kDigestBasis) {
  for (const unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

}  // namespace rice::experiments
