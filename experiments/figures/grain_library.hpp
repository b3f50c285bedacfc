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
#include <vector>

#include "experiments/io/png_image.hpp"
#include "grains/grain_generator.hpp"

namespace rice::experiments {

struct GrainLibrarySettings {
  grains::GrainRecipe recipe;
  int count = 10;
  int variants = 0;  ///< 0: every grain generated; K > 0: K variants, instanced
  std::uint64_t seed = 1;
  bool sections = true;  ///< write cross-section PNGs
};

/// Throws std::invalid_argument naming the setting that is out of range.
void validate(const GrainLibrarySettings& settings);

/// Checks the settings, then writes the set into `folder`. Nothing is written when the
/// settings are bad.
void grain_library_command(const GrainLibrarySettings& settings, const std::filesystem::path& folder);

/// Cross-section of `grain`'s level set at mid-thickness (z = 0) in its swollen size, `pixel`
/// metres a pixel: grain material light, pores and outside dark, edges anti-aliased.
RgbImage cross_section_image(const grains::Grain& grain, double pixel);

/// Columns of grains.csv, and one row for `grain` shown at swell factor `swell` (its own
/// when generated, an instance's otherwise) with orientation `rotation`.
const std::vector<std::string>& grain_table_columns();
std::vector<std::string> grain_table_row(int index, int variant, const std::string& cultivar,
                                         const grains::Grain& grain, double swell,
                                         const Eigen::Quaterniond& rotation);

/// Writes <stem>.ply (render mesh), <stem>.mesh (simulation mesh), <stem>_embedding.csv and,
/// when `section`, <stem>_section.png (at a quarter voxel a pixel) into `folder`.
void write_grain_files(const grains::Grain& grain, const std::filesystem::path& folder, const std::string& stem,
                       bool section);

}  // namespace rice::experiments
