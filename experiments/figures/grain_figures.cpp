// Figure 8 and 9 drivers (see grain_figures.hpp).
#include "experiments/figures/grain_figures.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "experiments/figures/grain_library.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "grains/surface_measures.hpp"

namespace rice::experiments {
namespace {

constexpr double kSectionPixel = 10e-6;  // one common scale for every grain of a figure [m]

// Images side by side, centred vertically, on the section's dark background.
RgbImage side_by_side(const std::vector<RgbImage>& images, int gap) {
  int width = gap, height = 0;
  for (const RgbImage& image : images) {
    width += image.width + gap;
    height = std::max(height, image.height);
  }
  RgbImage montage(width, height + 2 * gap);
  for (int y = 0; y < montage.height; ++y)
    for (int x = 0; x < montage.width; ++x) montage.set(x, y, 25, 30, 45);
  int left = gap;
  for (const RgbImage& image : images) {
    const int top = gap + (height - image.height) / 2;
    for (int y = 0; y < image.height; ++y)
      std::copy_n(&image.pixels[3 * static_cast<size_t>(y) * image.width], 3 * image.width,
                  &montage.pixels[3 * (static_cast<size_t>(top + y) * montage.width + left)]);
    left += image.width + gap;
  }
  return montage;
}

std::vector<std::uint64_t> child_seeds(std::uint64_t seed, int count) {
  grains::RandomStream random(seed);
  std::vector<std::uint64_t> seeds(count);
  for (std::uint64_t& s : seeds) s = random.child_seed();
  return seeds;
}

}  // namespace

void grain_sizes_figure_command(std::uint64_t seed, const std::filesystem::path& folder) {
  const auto start = std::chrono::steady_clock::now();
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const std::vector<double> swells = {1.0, 1.125, 1.25, 1.375, 1.5};
  const int n = static_cast<int>(swells.size());
  make_output_folder(folder);
  const auto seeds = child_seeds(seed, n);
  std::vector<grains::Grain> grains_built(n);
  for_each_item("figure 8: grains", n, [&](int i) {
    grains_built[i] = grains::make_grain(recipe, seeds[i], swells[i]);
    write_grain_files(grains_built[i], folder, "grain_" + std::to_string(i), false);
  });
  CsvTable table(grain_table_columns());
  std::vector<RgbImage> sections;
  for (int i = 0; i < n; ++i) {
    table.add_row(grain_table_row(i, i, "japonica", grains_built[i], swells[i], Eigen::Quaterniond::Identity()));
    sections.push_back(cross_section_image(grains_built[i], kSectionPixel));
  }
  write_file_atomically(folder / "figure8.csv", table.text());
  write_png(folder / "figure8_sections.png", side_by_side(sections, 20));
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"figure", "8"},
                                  {"seed", std::to_string(seed)},
                                  {"section_pixel_m", cell(kSectionPixel)},
                                  {"wall_s", cell(seconds_since(start))}}));
}

void cultivars_figure_command(std::uint64_t seed, int count, const std::filesystem::path& folder) {
  if (count < 2) throw std::invalid_argument("figure 9: --count must be >= 2");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> names = {"indica", "japonica", "aromatic"};
  make_output_folder(folder);
  CsvTable table({"cultivar", "dimension", "literature_raw_m", "literature_cooked_m", "generated_mean_m",
                  "generated_sd_m", "generated_over_literature_cooked"});
  std::vector<RgbImage> sections;
  const auto seeds = child_seeds(seed, static_cast<int>(names.size()));
  for (size_t c = 0; c < names.size(); ++c) {
    grains::GrainRecipe recipe;
    recipe.cultivar = grains::cultivar_by_name(names[c]);
    const auto grain_seeds = child_seeds(seeds[c], count);
    std::vector<grains::Vec3> extents(count);
    grains::Grain first;
    for_each_item("figure 9: " + names[c], count, [&](int i) {
      grains::Grain grain = grains::make_grain(recipe, grain_seeds[i]);
      extents[i] = grains::bounding_box_extent(grain.render.V);
      if (i == 0) first = std::move(grain);
    });
    write_grain_files(first, folder, names[c], false);
    sections.push_back(cross_section_image(first, kSectionPixel));

    const grains::Cultivar& k = recipe.cultivar;
    const double raw[3] = {k.length.mean, k.width.mean, k.thickness.mean};
    const double ratio[3] = {k.cooked_length_ratio, k.cooked_width_ratio, k.cooked_thickness_ratio};
    const char* dimension[3] = {"length", "width", "thickness"};
    for (int d = 0; d < 3; ++d) {
      double mean = 0.0, square = 0.0;
      for (const grains::Vec3& e : extents) mean += e[d] / count;
      for (const grains::Vec3& e : extents) square += (e[d] - mean) * (e[d] - mean) / (count - 1);
      const double cooked = raw[d] * ratio[d];
      table.add_row({names[c], dimension[d], cell(raw[d]), cell(cooked), cell(mean), cell(std::sqrt(square)),
                     cell(mean / cooked)});
      std::cout << names[c] << ' ' << dimension[d] << ": literature raw " << raw[d] * 1e3 << " mm, cooked "
                << cooked * 1e3 << " mm; generated " << mean * 1e3 << " ± " << std::sqrt(square) * 1e3 << " mm\n";
    }
  }
  write_file_atomically(folder / "figure9.csv", table.text());
  write_png(folder / "figure9_sections.png", side_by_side(sections, 20));
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"figure", "9"},
                                  {"seed", std::to_string(seed)},
                                  {"grains_per_cultivar", cell(count)},
                                  {"section_pixel_m", cell(kSectionPixel)},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
