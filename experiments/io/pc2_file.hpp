// PC2, the point cache Blender's Mesh Cache modifier (and Maya, 3ds Max) reads: a header of
// "POINTCACHE2\0", the version (1), the point count, the first frame and the frames between
// samples as float32 and the sample count, then each sample's points as float32 x y z, all
// little-endian. Written one sample at a time, so a long run's cache never sits in memory.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <iosfwd>
#include <vector>

namespace rice::experiments {

void write_pc2_header(std::ostream& out, int points, float first_frame, float frame_step, int samples);

/// One sample: `points` rows of x y z (rounded to float32).
void write_pc2_sample(std::ostream& out, const Eigen::MatrixX3d& points);

struct Pc2Cache {
  int points = 0, samples = 0;
  float first_frame = 0.0f, frame_step = 1.0f;
  std::vector<Eigen::MatrixX3f> positions;  ///< one points × 3 matrix per sample
};

/// Reads a PC2 file; throws std::runtime_error naming it when it is not one or is cut short.
Pc2Cache read_pc2(const std::filesystem::path& file);

}  // namespace rice::experiments
