// PC2 point caches; see pc2_file.hpp.
#include "experiments/io/pc2_file.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace rice::experiments {
namespace {

static_assert(std::endian::native == std::endian::little, "PC2 is little-endian; this writer copies bytes as they are");

constexpr char kSignature[12] = "POINTCACHE2";  // with its terminating zero: 12 bytes

template <class T>
void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T take(std::istream& in, const std::filesystem::path& file) {
  T value;
  if (!in.read(reinterpret_cast<char*>(&value), sizeof value))
    throw std::runtime_error(file.string() + ": a PC2 cache cut short");
  return value;
}

}  // namespace

void write_pc2_header(std::ostream& out, int points, float first_frame, float frame_step, int samples) {
  out.write(kSignature, sizeof kSignature);
  put<std::int32_t>(out, 1);
  put<std::int32_t>(out, points);
  put<float>(out, first_frame);
  put<float>(out, frame_step);
  put<std::int32_t>(out, samples);
}

void write_pc2_sample(std::ostream& out, const Eigen::MatrixX3d& points) {
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> rows = points.cast<float>();
  out.write(reinterpret_cast<const char*>(rows.data()), static_cast<std::streamsize>(rows.size() * sizeof(float)));
}

Pc2Cache read_pc2(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char signature[sizeof kSignature];
  if (!in.read(signature, sizeof signature) || std::memcmp(signature, kSignature, sizeof signature) != 0)
    throw std::runtime_error(file.string() + ": not a PC2 point cache");
  Pc2Cache cache;
  if (take<std::int32_t>(in, file) != 1) throw std::runtime_error(file.string() + ": not PC2 version 1");
  cache.points = take<std::int32_t>(in, file);
  cache.first_frame = take<float>(in, file);
  cache.frame_step = take<float>(in, file);
  cache.samples = take<std::int32_t>(in, file);
  if (cache.points < 0 || cache.samples < 0) throw std::runtime_error(file.string() + ": a negative count");
  for (int s = 0; s < cache.samples; ++s) {
    Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> rows(cache.points, 3);
    if (!in.read(reinterpret_cast<char*>(rows.data()), static_cast<std::streamsize>(rows.size() * sizeof(float))))
      throw std::runtime_error(file.string() + ": a PC2 cache cut short at sample " + std::to_string(s));
    cache.positions.emplace_back(rows);
  }
  return cache;
}

}  // namespace rice::experiments
