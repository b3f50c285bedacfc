// Each frame's poses; see frames_observer.hpp.
#include "experiments/scene/frames_observer.hpp"

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"

namespace rice::experiments {
namespace {

CsvTable pose_table(const World& world) {
  const xpbd::Model& model = world.model;
  CsvTable poses(world.rigid() ? std::vector<std::string>{"grain", "x", "y", "z", "qw", "qx", "qy", "qz", "in_scene"}
                               : std::vector<std::string>{"grain", "vertex", "x", "y", "z", "in_scene"});
  for (int g = 0; g < world.count(); ++g) {
    const xpbd::Body& body = model.bodies[g];
    const std::string in_scene = g < world.released ? "1" : "0";
    if (body.kind == xpbd::BodyKind::kRigid) {
      const xpbd::RigidBody& r = model.rigid_bodies[body.rigid_body];
      const xpbd::Quat q = r.q() * world.initial_orientation[body.rigid_body].conjugate();
      poses.add_row({cell(g), cell(r.x.x()), cell(r.x.y()), cell(r.x.z()), cell(q.w()), cell(q.x()), cell(q.y()),
                     cell(q.z()), in_scene});
    } else {
      for (int v = 0; v < body.particle_count; ++v) {
        const auto x = model.particles.x.row(body.first_particle + v);
        poses.add_row({cell(g), cell(v), cell(x(0)), cell(x(1)), cell(x(2)), in_scene});
      }
    }
  }
  return poses;
}

}  // namespace

void FramesObserver::begin(const World&) { make_output_folder(folder_); }

void FramesObserver::observe(const World& world, const Stepper&, int frame, double) {
  write_file_atomically(folder_ / (frame_name(frame) + ".csv"), pose_table(world).text());
}

}  // namespace rice::experiments
