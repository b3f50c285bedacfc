// Each frame's render meshes; see render_mesh_observer.hpp.
#include "experiments/scene/render_mesh_observer.hpp"

#include "experiments/io/atomic_file.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {

grains::SurfaceMesh merged(const std::vector<grains::SurfaceMesh>& parts) {
  grains::SurfaceMesh all;
  Eigen::Index vertices = 0, faces = 0;
  for (const grains::SurfaceMesh& part : parts) vertices += part.V.rows(), faces += part.F.rows();
  all.V.resize(vertices, 3);
  all.F.resize(faces, 3);
  Eigen::Index v = 0, f = 0;
  for (const grains::SurfaceMesh& part : parts) {
    all.V.middleRows(v, part.V.rows()) = part.V;
    all.F.middleRows(f, part.F.rows()) = part.F.array() + static_cast<int>(v);
    v += part.V.rows();
    f += part.F.rows();
  }
  return all;
}

void RenderMeshObserver::begin(const World&) { make_output_folder(folder_); }

void RenderMeshObserver::observe(const World& world, const Stepper&, int frame, double) {
  std::vector<grains::SurfaceMesh> meshes;
  for (int g = 0; g < world.count(); ++g) meshes.push_back(world.render_mesh(g));
  write_file_atomically(folder_ / (frame_name(frame) + ".ply"),
                        [&](std::ostream& out) { grains::write_ply(out, merged(meshes)); });
}

}  // namespace rice::experiments
