// `rice point-cache`: a scene run as Blender reads an animation. grains.obj holds every grain's
// render mesh (its variant's, simplified to at most `max_vertices` vertices: the full meshes
// of 800 grains over 180 frames would be 35 GB) as one mesh of fixed topology at the first
// frame; grains.pc2 holds its vertices at every frame, for Blender's Mesh Cache modifier
// (scripts/blender_import.py builds the animated scene). A rigid grain's mesh is placed by its
// pose, a soft grain's rides on its simulation vertices through its embedding, as the
// renderer draws them (run_frames.hpp); grains still parked sit at their parking places.
#pragma once

#include <filesystem>

namespace rice::experiments {

struct PointCacheSettings {
  std::filesystem::path run;  ///< a scene run's output folder
  int max_vertices = 1000;    ///< per grain; 0: the render meshes whole
};

/// Throws std::invalid_argument for max_vertices in 1..3.
void validate(const PointCacheSettings& settings);

/// Writes grains.obj, grains.pc2 and run_info.txt into `folder`; throws std::invalid_argument
/// first when `run` is not a run's folder.
void point_cache_command(const PointCacheSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
