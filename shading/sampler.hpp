// Per-pixel sample values in [0, 1), deterministic in (seed, pixel, sample index, dimension),
// so tiles render independently and a run repeats exactly on any thread count.
//
//  - kIndependent: a hash of all four, uniform and uncorrelated.
//  - kStratified: each pair of dimensions is jittered on a √n × √n grid (n the samples per
//    pixel rounded down to a square), the strata visited in a per-pixel, per-pair shuffled
//    order so the pairs do not line up (pbrt's StratifiedSampler with padding).
//  - kSobol: each pair of dimensions takes the first two dimensions of the Sobol sequence, a
//    (0, 2)-sequence in base 2, randomised by a digital shift (XOR) per pixel and pair and an
//    XOR shuffle of the index within each power-of-two block (pbrt's PaddedSobolSampler).
// Written by hand: the samplers of pbrt or Mitsuba are not packaged for Debian.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

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

inline std::uint32_t reverse_bits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

/// Second dimension of the Sobol sequence (primitive polynomial x + 1): generator columns
/// v_1 = 2^31, v_k = v_{k−1} ⊕ (v_{k−1} >> 1).
inline std::uint32_t sobol_second(std::uint32_t index) {
  std::uint32_t result = 0;
  for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

}  // namespace detail

/// The sample stream of one pixel.
class PixelSampler {
 public:
  PixelSampler(SamplerKind kind, std::uint64_t seed, int x, int y, int samples_per_pixel)
      : kind_(kind),
        pixel_key_(detail::mix(seed ^ detail::mix((static_cast<std::uint64_t>(y) << 32) | static_cast<std::uint32_t>(x)))),
        samples_(samples_per_pixel),
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
        const int cell = shuffled(index, cells, key);
        a = (cell % grid_ + ja) / grid_;
        b = (cell / grid_ + jb) / grid_;
        return;
      }
      case SamplerKind::kSobol: {
        // XOR the index with a random value below its power-of-two block: a permutation of
        // each block, so every prefix of 2^k samples is still a (0, 2)-net.
        const std::uint32_t block = std::bit_ceil(static_cast<std::uint32_t>(samples_));
        const std::uint32_t i = static_cast<std::uint32_t>(index) ^ (static_cast<std::uint32_t>(key >> 40) & (block - 1));
        const std::uint32_t shift_a = static_cast<std::uint32_t>(key), shift_b = static_cast<std::uint32_t>(key >> 32);
        a = detail::to_unit(detail::reverse_bits(i) ^ shift_a);
        b = detail::to_unit(detail::sobol_second(i) ^ shift_b);
        return;
      }
    }
  }

 private:
  // A bijection of [0, n) from the key: a random affine map modulo n with a unit stride.
  static int shuffled(int index, int n, std::uint64_t key) {
    std::uint64_t stride = key % static_cast<std::uint64_t>(n);
    auto gcd = [](std::uint64_t p, std::uint64_t q) {
      while (q != 0) p = std::exchange(q, p % q);
      return p;
    };
    while (gcd(stride, static_cast<std::uint64_t>(n)) != 1) stride = (stride + 1) % static_cast<std::uint64_t>(n);
    return static_cast<int>((stride * static_cast<std::uint64_t>(index) + (key >> 32)) % static_cast<std::uint64_t>(n));
  }

  SamplerKind kind_;
  std::uint64_t pixel_key_;
  int samples_;
  int grid_;
};

}  // namespace rice::shading
