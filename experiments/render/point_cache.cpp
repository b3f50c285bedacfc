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

/// What every frame of the cache needs: each variant's cached mesh and, for a soft run, its
/// vertices' embedding in the variant's simulation mesh; each grain's variant; the vertex count.
struct Cache {
  RunVariants run;
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<grains::Embedding> embedding;
  NumericCsv grains_csv;
  std::vector<int> variant;  ///< of each grain
  Eigen::Index points = 0;
};

Cache read_cache(const PointCacheSettings& s) {
  Cache c{read_run_variants(s.run, 0.0), {}, {}, read_numeric_csv(s.run / "grains.csv"), {}, 0};
  for (size_t k = 0; k < c.run.meshes.size(); ++k) {
    const grains::SurfaceMesh& mesh = c.run.meshes[k];
    c.meshes.push_back(s.max_vertices > 0 ? grains::simplified(mesh, s.max_vertices) : mesh);
    if (!c.run.simulation.empty())
      c.embedding.push_back(s.max_vertices > 0 ? grains::embed_points(c.meshes[k].V, c.run.simulation[k])
                                               : c.run.embedding[k]);
  }
  for (size_t g = 0; g < c.grains_csv.rows.size(); ++g) {
    c.variant.push_back(grain_variant(c.grains_csv, g, c.run));
    c.points += c.meshes[c.variant.back()].V.rows();
  }
  return c;
}

/// Every grain's cached mesh at `frame`, in grains.csv's order, one after another.
Eigen::MatrixX3d frame_vertices(const Cache& c, const NumericCsv& frame) {
  Eigen::MatrixX3d x(c.points, 3);
  Eigen::Index row = 0;
  const auto put = [&](const grains::Vertices& V) {  // a grain's count: its variant's (checked by the readers)
    x.middleRows(row, V.rows()) = V;
    row += V.rows();
  };
  if (c.run.simulation.empty()) {
    check_rigid_frame(c.grains_csv, frame);
    for (size_t g = 0; g < c.variant.size(); ++g)
      put((rigid_grain_place(c.grains_csv, frame, g) * c.meshes[c.variant[g]].V.transpose()).transpose());
  } else {
    for (const SoftGrain& grain : soft_run_grains(c.grains_csv, frame, c.run, true))
      put(grains::apply_embedding(c.embedding[grain.variant], grain.x, c.run.simulation[grain.variant].T));
  }
  return x;
}

/// All grains' cached meshes as one mesh, at `x`.
grains::SurfaceMesh one_mesh(const Cache& c, const Eigen::MatrixX3d& x) {
  std::vector<grains::SurfaceMesh> parts;
  Eigen::Index row = 0;
  for (const int variant : c.variant) {
    const grains::SurfaceMesh& mesh = c.meshes[variant];
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
  const Cache cache = read_cache(s);
  const std::vector<std::filesystem::path> frames = run_frames(s.run);
  make_output_folder(folder);
  const Eigen::MatrixX3d first = frame_vertices(cache, read_numeric_csv(frames.front()));
  write_file_atomically(folder / "grains.obj",
                        [&](std::ostream& out) { grains::write_obj(out, one_mesh(cache, first)); });
  Progress progress("point-cache: frames", static_cast<int>(frames.size()));
  const int first_frame = frame_number(frames.front());
  write_file_atomically(folder / "grains.pc2", [&](std::ostream& out) {
    write_pc2_header(out, static_cast<int>(cache.points), static_cast<float>(first_frame), 1.0f,
                     static_cast<int>(frames.size()));
    write_pc2_sample(out, first);
    for (size_t k = 1; k < frames.size(); ++k) {
      write_pc2_sample(out, frame_vertices(cache, read_numeric_csv(frames[k])));
      progress.update(static_cast<int>(k + 1));
    }
  });
  progress.finish();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "point-cache"},
                                  {"run", s.run.string()},
                                  {"grains", cell(static_cast<long>(cache.variant.size()))},
                                  {"frames", cell(static_cast<long>(frames.size()))},
                                  {"first_frame", cell(first_frame)},
                                  {"fps", cell(run_fps(s.run))},
                                  {"max_vertices", cell(s.max_vertices)},
                                  {"points", cell(static_cast<long>(cache.points))},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
