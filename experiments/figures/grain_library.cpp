// `rice grains` driver (see grain_library.hpp).
#include "experiments/figures/grain_library.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/io/png_image.hpp"
#include "grains/cross_section.hpp"
#include "grains/mesh_io.hpp"
#include "grains/surface_measures.hpp"
#include "grains/tet_quality.hpp"

namespace rice::experiments {
namespace {

std::string numbered(const char* prefix, int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%s_%04d", prefix, index);
  return name;
}

void write_embedding_csv(const grains::Embedding& embedding, const std::filesystem::path& path) {
  CsvTable table({"render_vertex", "tet", "w0", "w1", "w2", "w3"});
  for (Eigen::Index i = 0; i < embedding.tet.size(); ++i)
    table.add_row({cell(static_cast<long>(i)), cell(embedding.tet[i]), cell(embedding.weights(i, 0)),
                   cell(embedding.weights(i, 1)), cell(embedding.weights(i, 2)), cell(embedding.weights(i, 3))});
  write_file_atomically(path, table.text());
}

}  // namespace

const std::vector<std::string>& grain_table_columns() {
  static const std::vector<std::string> columns = {
    "grain", "variant", "cultivar", "swell", "length_m", "width_m", "thickness_m", "render_volume_m3",
    "level_set_volume_m3", "porosity", "core_porosity", "pores", "bumps", "spheres_skipped", "render_vertices",
    "render_faces", "simulation_vertices", "simulation_tets", "min_dihedral_deg", "max_radius_edge_ratio",
    "simulation_density", "qw", "qx", "qy", "qz"};
  return columns;
}

std::vector<std::string> grain_table_row(int index, int variant, const std::string& cultivar, const grains::Grain& grain,
                                   double swell, const Eigen::Quaterniond& rotation) {
  const double scale = swell / grain.shape.swell;  // 1 for generated grains
  const grains::Vec3 extent = grains::bounding_box_extent(grain.render.V) * scale;
  const grains::TetQuality quality = grains::measure_tet_quality(grain.simulation);
  const double volume_scale = std::pow(swell, 3);
  return {cell(index), cell(variant), cultivar, cell(swell), cell(extent.x()), cell(extent.y()), cell(extent.z()),
          cell(grains::enclosed_volume(grain.render) * scale * scale * scale),
          cell(grain.level_set.porous_volume * volume_scale), cell(grain.level_set.porosity()),
          cell(grain.level_set.measured_core_porosity), cell(grain.level_set.pore_count),
          cell(grain.level_set.bump_count), cell(grain.level_set.spheres_skipped),
          cell(static_cast<long>(grain.render.V.rows())), cell(static_cast<long>(grain.render.F.rows())),
          cell(static_cast<long>(grain.simulation.V.rows())), cell(static_cast<long>(grain.simulation.T.rows())),
          cell(quality.min_dihedral_degrees), cell(quality.max_radius_edge_ratio), cell(grain.simulation_density),
          cell(rotation.w()), cell(rotation.x()), cell(rotation.y()), cell(rotation.z())};
}

RgbImage cross_section_image(const grains::Grain& grain, double pixel) {
  // The level set is in the unswollen frame: sample it at pixel / P.
  const double swell = grain.shape.swell, frame_pixel = pixel / swell;
  const grains::Vec3 low = grain.render.V.colwise().minCoeff().transpose() / swell;
  const grains::Vec3 high = grain.render.V.colwise().maxCoeff().transpose() / swell;
  const grains::Vec3 margin = grains::Vec3::Constant(4.0 * frame_pixel);
  const Eigen::MatrixXf distance =
      grains::cross_section_z(*grain.level_set.grid, low - margin, high + margin, 0.0, frame_pixel);
  RgbImage image(static_cast<int>(distance.cols()), static_cast<int>(distance.rows()));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double material = std::clamp(0.5 - distance(y, x) / frame_pixel, 0.0, 1.0);  // 1 inside
      const auto mix = [&](double dark, double light) {
        return static_cast<std::uint8_t>(dark + material * (light - dark));
      };
      image.set(x, y, mix(25, 245), mix(30, 238), mix(45, 220));
    }
  return image;
}

void write_grain_files(const grains::Grain& grain, const std::filesystem::path& folder, const std::string& stem,
                       bool section) {
  write_file_atomically(folder / (stem + ".ply"), [&](std::ostream& out) { grains::write_ply(out, grain.render); });
  write_file_atomically(folder / (stem + ".mesh"),
                        [&](std::ostream& out) { grains::write_medit(out, grain.simulation); });
  write_embedding_csv(grain.embedding, folder / (stem + "_embedding.csv"));
  if (section)
    write_png(folder / (stem + "_section.png"),
              cross_section_image(grain, 0.25 * grain.level_set.voxel_size * grain.shape.swell));
}

void validate(const GrainLibrarySettings& settings) {
  grains::validate(settings.recipe);
  if (settings.count < 1) throw std::invalid_argument("--count must be >= 1");
  if (settings.variants < 0) throw std::invalid_argument("--variants must be >= 0");
}

void grain_library_command(const GrainLibrarySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  make_output_folder(folder);

  const bool instanced = settings.variants > 0;
  const int generated = instanced ? settings.variants : settings.count;
  grains::RandomStream random(settings.seed);
  std::vector<std::uint64_t> seeds(generated);
  for (std::uint64_t& seed : seeds) seed = random.child_seed();

  // Generated grains are kept only as variants to instance; otherwise each grain leaves as
  // its files and its table row (thousands of grains would not fit in memory).
  const std::string& cultivar = settings.recipe.cultivar.name;
  std::vector<grains::Grain> variants(instanced ? generated : 0);
  std::vector<std::vector<std::string>> rows(instanced ? 0 : generated);
  std::vector<grains::GrainTimings> timings(generated);
  for_each_item(instanced ? "variants" : "grains", generated, [&](int i) {
    grains::Grain grain =
        grains::make_grain(settings.recipe, seeds[i], instanced ? std::optional<double>(1.0) : std::nullopt);
    write_grain_files(grain, folder, numbered(instanced ? "variant" : "grain", i), settings.sections);
    timings[i] = grain.timings;
    if (instanced)
      variants[i] = std::move(grain);
    else
      rows[i] = grain_table_row(i, i, cultivar, grain, grain.shape.swell, Eigen::Quaterniond::Identity());
  });
  const double generation_seconds = seconds_since(start);

  const auto instancing_start = std::chrono::steady_clock::now();
  CsvTable table(grain_table_columns());
  if (instanced) {
    const auto instances = grains::make_instances(settings.count, settings.variants, settings.recipe.cultivar, random);
    for (int i = 0; i < settings.count; ++i)
      table.add_row(grain_table_row(i, instances[i].variant, cultivar, variants[instances[i].variant], instances[i].swell,
                              instances[i].rotation));
  } else {
    for (const auto& row : rows) table.add_row(row);
  }
  write_file_atomically(folder / "grains.csv", table.text());
  const double instancing_seconds = seconds_since(instancing_start);

  grains::GrainTimings mean;  // per generated grain, one thread
  for (const grains::GrainTimings& t : timings) {
    mean.level_set += t.level_set / generated;
    mean.render_mesh += t.render_mesh / generated;
    mean.simulation_mesh += t.simulation_mesh / generated;
    mean.embedding += t.embedding / generated;
  }
  const double mean_grain_seconds = mean.total();
  std::cout << "rice grains: " << generated << (instanced ? " variants" : " grains") << " in " << generation_seconds
            << " s (" << mean_grain_seconds << " s per grain: sum of its stage times, files excluded)";
  if (instanced) std::cout << "; " << settings.count << " instances in " << instancing_seconds << " s";
  std::cout << '\n';
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "grains"},
                                  {"cultivar", cultivar},
                                  {"count", cell(settings.count)},
                                  {"variants", cell(settings.variants)},
                                  {"seed", std::to_string(settings.seed)},
                                  {"generation_wall_s", cell(generation_seconds)},
                                  {"mean_seconds_per_generated_grain", cell(mean_grain_seconds)},
                                  {"mean_level_set_s", cell(mean.level_set)},
                                  {"mean_render_mesh_s", cell(mean.render_mesh)},
                                  {"mean_simulation_mesh_s", cell(mean.simulation_mesh)},
                                  {"mean_embedding_s", cell(mean.embedding)},
                                  {"instancing_wall_s", cell(instancing_seconds)},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
