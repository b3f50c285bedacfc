// A run's point cache; see point_cache.hpp.
#include "experiments/render/point_cache.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/pc2_file.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/run_frames.hpp"
#include "grains/embedding.hpp"
#include "grains/mesh_io.hpp"
#include "grains/mesh_simplification.hpp"

namespace rice::experiments {
namespace {

/// Each variant's cached mesh and, for a soft run, its vertices' embedding in the variant's
/// simulation mesh.
struct CacheVariants {
  RunVariants run;
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<grains::Embedding> embedding;
};

CacheVariants cache_variants(const PointCacheSettings& s) {
  CacheVariants v{read_run_variants(s.run, 0.0), {}, {}};
  for (size_t k = 0; k < v.run.meshes.size(); ++k) {
    const grains::SurfaceMesh& mesh = v.run.meshes[k];
    v.meshes.push_back(s.max_vertices > 0 ? grains::simplified(mesh, s.max_vertices) : mesh);
    if (!v.run.simulation.empty())
      v.embedding.push_back(s.max_vertices > 0 ? grains::embed_points(v.meshes[k].V, v.run.simulation[k])
                                               : v.run.embedding[k]);
  }
  return v;
}

/// Every grain's cached mesh at `frame`, in grains.csv's order, one after another.
Eigen::MatrixX3d frame_vertices(const CacheVariants& v, const NumericCsv& grains_csv, const NumericCsv& frame,
                                Eigen::Index count) {
  Eigen::MatrixX3d x(count, 3);
  Eigen::Index row = 0;
  const auto put = [&](const grains::Vertices& V) {
    if (row + V.rows() > count)
      throw std::runtime_error("point-cache: " + frame.path.string() + " holds more grains than grains.csv");
    x.middleRows(row, V.rows()) = V;
    row += V.rows();
  };
  if (v.run.simulation.empty()) {
    check_rigid_frame(grains_csv, frame);
    const int variant = grains_csv.column("variant");
    for (size_t g = 0; g < grains_csv.rows.size(); ++g) {
      const grains::Vertices& V = v.meshes[static_cast<int>(grains_csv.rows[g][variant])].V;
      put((rigid_grain_place(grains_csv, frame, g) * V.transpose()).transpose());
    }
  } else {
    for (const SoftGrain& grain : soft_run_grains(grains_csv, frame, v.run, true))
      put(grains::apply_embedding(v.embedding[grain.variant], grain.x, v.run.simulation[grain.variant].T));
  }
  if (row != count) throw std::runtime_error("point-cache: " + frame.path.string() + " does not hold every grain");
  return x;
}

/// All grains' cached meshes as one mesh, at `x`.
grains::SurfaceMesh one_mesh(const CacheVariants& v, const NumericCsv& grains_csv, const Eigen::MatrixX3d& x) {
  std::vector<grains::SurfaceMesh> parts;
  const int variant = grains_csv.column("variant");
  Eigen::Index row = 0;
  for (const auto& grain : grains_csv.rows) {
    const grains::SurfaceMesh& mesh = v.meshes[static_cast<int>(grain[variant])];
    parts.push_back({x.middleRows(row, mesh.V.rows()), mesh.F});
    row += mesh.V.rows();
  }
  return grains::merged(parts);
}

}  // namespace

void validate(const PointCacheSettings& s) {
  if (s.max_vertices < 0 || (s.max_vertices > 0 && s.max_vertices < 4))
    throw std::invalid_argument("point-cache: --max-vertices must be 0 (whole meshes) or at least 4");
}

void point_cache_command(const PointCacheSettings& s, const std::filesystem::path& folder) {
  validate(s);
  for (const char* name : {"grains.csv", "variants", "frames"})
    if (!std::filesystem::exists(s.run / name))
      throw std::invalid_argument("point-cache: --run " + s.run.string() + " has no " + name +
                                  " (a scene run's output folder is expected)");
  const auto start = std::chrono::steady_clock::now();
  const CacheVariants variants = cache_variants(s);
  const NumericCsv grains_csv = read_numeric_csv(s.run / "grains.csv");
  const std::vector<std::filesystem::path> frames = run_frames(s.run);
  Eigen::Index points = 0;
  const int variant = grains_csv.column("variant");
  for (const auto& grain : grains_csv.rows) points += variants.meshes[static_cast<int>(grain[variant])].V.rows();
  make_output_folder(folder);
  const Eigen::MatrixX3d first = frame_vertices(variants, grains_csv, read_numeric_csv(frames.front()), points);
  write_file_atomically(folder / "grains.obj",
                        [&](std::ostream& out) { grains::write_obj(out, one_mesh(variants, grains_csv, first)); });
  Progress progress("point-cache: frames", static_cast<int>(frames.size()));
  const std::string stem = frames.front().stem().string();
  const int first_frame = std::stoi(stem.substr(stem.find('_') + 1));  // frame_NNNN
  write_file_atomically(folder / "grains.pc2", [&](std::ostream& out) {
    write_pc2_header(out, static_cast<int>(points), static_cast<float>(first_frame), 1.0f,
                     static_cast<int>(frames.size()));
    for (size_t k = 0; k < frames.size(); ++k) {
      write_pc2_sample(out, frame_vertices(variants, grains_csv, read_numeric_csv(frames[k]), points));
      progress.update(static_cast<int>(k + 1));
    }
  });
  progress.finish();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "point-cache"},
                                  {"run", s.run.string()},
                                  {"grains", cell(static_cast<long>(grains_csv.rows.size()))},
                                  {"frames", cell(static_cast<long>(frames.size()))},
                                  {"first_frame", cell(first_frame)},
                                  {"fps", cell(run_fps(s.run))},
                                  {"max_vertices", cell(s.max_vertices)},
                                  {"points", cell(static_cast<long>(points))},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
