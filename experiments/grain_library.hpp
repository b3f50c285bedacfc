// `rice grains`: a set of procedural grains written to disk — for each grain (or, with
// variants, each variant) its render mesh (PLY), simulation mesh (MEDIT .mesh), embedding
// (CSV) and a mid-thickness cross-section of its level set (PNG, paper Fig. 7); and one
// grains.csv row per grain with its dimensions, volumes, porosity, P, mesh sizes and quality.
// With variants K > 0 only K grains are generated and every grain is an instance of one of
// them with its own rotation and swell factor.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "grains/grain_generator.hpp"

namespace rice::experiments {

struct GrainLibrarySettings {
  grains::GrainRecipe recipe;
  int count = 10;
  int variants = 0;  ///< 0: every grain generated; K > 0: K variants, instanced
  std::uint64_t seed = 1;
  bool sections = true;  ///< write cross-section PNGs
};

/// Checks the settings, then writes the set into `folder`. Nothing is written when the
/// settings are bad.
void grain_library_command(const GrainLibrarySettings& settings, const std::filesystem::path& folder);

/// Writes a cross-section of `grain`'s level set at mid-thickness (z = 0) as PNG: grain
/// material light, pores and outside dark, edges anti-aliased over one pixel.
void write_cross_section_png(const grains::Grain& grain, const std::filesystem::path& path);

}  // namespace rice::experiments
