// Per-pixel sample values in [0, 1), deterministic in (seed, pixel, sample index, dimension),
// so tiles render independently and a run repeats exactly on any thread count.
//
//  - kIndependent: a hash of all four, uniform and uncorrelated.
//  - kStratified: each pair of dimensions is jittered on a √n × √n grid (n the samples per
//    pixel rounded down to a square), the strata visited in a per-pixel, per-pair random
//    order (Kensler's hashed permutation, "Correlated Multi-Jittered Sampling", 2013) so the
//    pairs do not line up (pbrt's StratifiedSampler with padding).
//  - kSobol: each pair of dimensions takes the first two dimensions of the Sobol sequence, a
//    (0, 2)-sequence in base 2, shuffled and Owen-scrambled per pixel and pair by hashing
//    (Burley, "Practical Hash-based Owen Scrambling", JCGT 2020). Scrambling the index keeps
//    every power-of-two prefix a (0, m, 2)-net. An earlier XOR shift of index and values
//    left the pairs correlated (one pair's first coordinate a fixed XOR of another's), and
//    the error stopped falling at 64 samples.
// Written by hand: the samplers of pbrt or Mitsuba are not packaged for Debian.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace rice::shading {

enum class SamplerKind { kIndependent, kStratified, kSobol };

namespace detail {

/// A 64-bit mix (the finaliser of SplitMix64).
inline std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline double to_unit(std::uint32_t bits) { return bits * 0x1p-32; }

/// The bits of x in reverse order, a byte at a time from a table.
inline std::uint32_t reverse_bits(std::uint32_t x) {
  static constexpr auto table = [] {
    std::array<std::uint8_t, 256> t{};
    for (int b = 0; b < 256; ++b) {
      int r = 0;
      for (int k = 0; k < 8; ++k) r |= ((b >> k) & 1) << (7 - k);
      t[b] = static_cast<std::uint8_t>(r);
    }
    return t;
  }();
  return (std::uint32_t{table[x & 0xff]} << 24) | (std::uint32_t{table[(x >> 8) & 0xff]} << 16) |
         (std::uint32_t{table[(x >> 16) & 0xff]} << 8) | table[x >> 24];
}

/// Laine–Karras hash: a permutation of 32-bit values in which each bit depends only on the
/// bits below it (so, applied to bit-reversed values, an Owen scramble).
inline std::uint32_t laine_karras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

/// Nested uniform (Owen) scramble of a 32-bit binary fraction.
inline std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits(laine_karras(reverse_bits(x), seed));
}

/// A permutation of [0, n) chosen by `key` (Kensler 2013: a hash that is a bijection on the
/// next power of two, walked until it lands below n).
inline std::uint32_t permute(std::uint32_t i, std::uint32_t n, std::uint32_t key) {
  std::uint32_t w = n - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16;
    i ^= (i & w) >> 4;
    i ^= key >> 8;
    i *= 0x0929eb3fu;
    i ^= key >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | key >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return (i + key) % n;
}

/// Second dimension of the Sobol sequence (primitive polynomial x + 1): generator columns
/// v_1 = 2^31, v_k = v_{k−1} ⊕ (v_{k−1} >> 1), XORed over the index's set bits, a byte of the
/// index at a time from tables (scrambled indices use all 32 bits).
inline std::uint32_t sobol_second(std::uint32_t index) {
  static constexpr auto tables = [] {
    std::array<std::array<std::uint32_t, 256>, 4> t{};
    std::array<std::uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    for (int byte = 0; byte < 4; ++byte)
      for (int b = 0; b < 256; ++b) {
        std::uint32_t x = 0;
        for (int j = 0; j < 8; ++j)
          if ((b >> j) & 1) x ^= v[8 * byte + j];
        t[byte][b] = x;
      }
    return t;
  }();
  return tables[0][index & 0xff] ^ tables[1][(index >> 8) & 0xff] ^ tables[2][(index >> 16) & 0xff] ^
         tables[3][index >> 24];
}

}  // namespace detail

/// The sample stream of one pixel.
class PixelSampler {
 public:
  PixelSampler(SamplerKind kind, std::uint64_t seed, int x, int y, int samples_per_pixel)
      : kind_(kind),
        pixel_key_(detail::mix(seed ^ detail::mix((static_cast<std::uint64_t>(y) << 32) | static_cast<std::uint32_t>(x)))),
        grid_(static_cast<int>(std::sqrt(static_cast<double>(samples_per_pixel)))) {}

  /// Values of dimensions 2·pair and 2·pair + 1 for sample `index`.
  void pair(int index, int pair, double& a, double& b) const {
    const std::uint64_t key = detail::mix(pixel_key_ ^ (0x2545f4914f6cdd1dULL * (pair + 1)));
    switch (kind_) {
      case SamplerKind::kIndependent: {
        const std::uint64_t h = detail::mix(key ^ static_cast<std::uint64_t>(index));
        a = detail::to_unit(static_cast<std::uint32_t>(h));
        b = detail::to_unit(static_cast<std::uint32_t>(h >> 32));
        return;
      }
      case SamplerKind::kStratified: {
        const int cells = grid_ * grid_;
        const std::uint64_t h = detail::mix(key ^ static_cast<std::uint64_t>(index));
        const double ja = detail::to_unit(static_cast<std::uint32_t>(h)), jb = detail::to_unit(static_cast<std::uint32_t>(h >> 32));
        if (index >= cells) {  // beyond the square grid: plain random
          a = ja;
          b = jb;
          return;
        }
        const int cell = static_cast<int>(detail::permute(static_cast<std::uint32_t>(index),
                                                          static_cast<std::uint32_t>(cells),
                                                          static_cast<std::uint32_t>(key >> 32)));
        a = (cell % grid_ + ja) / grid_;
        b = (cell / grid_ + jb) / grid_;
        return;
      }
      case SamplerKind::kSobol: {
        const std::uint64_t seeds = detail::mix(key);
        const std::uint32_t i = detail::owen_scramble(static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(key));
        // Dimension 0 of the Sobol sequence is reverse_bits(i), and owen_scramble(reverse_bits(i))
        // = reverse_bits(laine_karras(i)).
        a = detail::to_unit(detail::reverse_bits(detail::laine_karras(i, static_cast<std::uint32_t>(seeds))));
        b = detail::to_unit(detail::owen_scramble(detail::sobol_second(i), static_cast<std::uint32_t>(seeds >> 32)));
        return;
      }
    }
  }

 private:
  SamplerKind kind_;
  std::uint64_t pixel_key_;
  int grid_;
};

}  // namespace rice::shading
