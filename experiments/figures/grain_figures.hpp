// Paper Figures 8 and 9: grain meshes and their level-set cross-sections.
//   Figure 8: automatically generated japonica grains of different sizes (swell factor P
//             from 1 to 1.5, eq. 2).
//   Figure 9: indica, japonica and aromatic grains side by side, their generated dimensions
//             compared with the literature values the cultivar models are built from.
#pragma once

#include <cstdint>
#include <filesystem>

namespace rice::experiments {

/// Writes grain_k.{ply,mesh}, grain_k_embedding.csv, figure8.csv, figure8_sections.png.
void grain_sizes_figure_command(std::uint64_t seed, const std::filesystem::path& folder);

/// Generates `count` grains per cultivar; writes each cultivar's first grain's files,
/// figure9.csv (literature against generated dimensions), figure9_sections.png.
void cultivars_figure_command(std::uint64_t seed, int count, const std::filesystem::path& folder);

}  // namespace rice::experiments
