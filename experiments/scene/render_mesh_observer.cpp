// Each frame's render meshes; see render_mesh_observer.hpp.
#include "experiments/scene/render_mesh_observer.hpp"

#include "experiments/io/atomic_file.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {

void RenderMeshObserver::begin(const World&) { make_output_folder(folder_); }

void RenderMeshObserver::observe(const World& world, const Stepper&, int frame, double) {
  std::vector<grains::SurfaceMesh> meshes;
  for (int g = 0; g < world.count(); ++g) meshes.push_back(world.render_mesh(g));
  write_file_atomically(folder_ / (frame_name(frame) + ".ply"),
                        [&](std::ostream& out) { grains::write_ply(out, grains::merged(meshes)); });
}

}  // namespace rice::experiments
