// The run for ParaView; see paraview_observer.hpp. The VTK XML formats are written by hand: a
// few lines of text, where linking VTK would bring a large library for them.
#include "experiments/scene/paraview_observer.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"

namespace rice::experiments {
namespace {

/// A DataArray of `values` (already space-separated text).
std::string data_array(const std::string& type, const std::string& name, int components, const std::string& values) {
  return "        <DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
         std::to_string(components) + "\" format=\"ascii\">" + values + "</DataArray>\n";
}

std::string frame_poly_data(const World& world, const std::vector<int>& bonds) {
  std::ostringstream points, velocity, awake, bonded, grain, in_scene, connectivity, offsets;
  for (int g = 0; g < world.count(); ++g) {
    const xpbd::Vec3 c = world.centre(g), v = world.velocity(g);
    points << ' ' << cell(c.x()) << ' ' << cell(c.y()) << ' ' << cell(c.z());
    velocity << ' ' << cell(v.x()) << ' ' << cell(v.y()) << ' ' << cell(v.z());
    awake << ' ' << (world.model.bodies[g].asleep ? 0 : 1);
    bonded << ' ' << bonds[g];
    grain << ' ' << g;
    in_scene << ' ' << (g < world.released ? 1 : 0);
    connectivity << ' ' << g;
    offsets << ' ' << g + 1;
  }
  const std::string n = std::to_string(world.count());
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <PolyData>\n    <Piece NumberOfPoints=\"" + n + "\" NumberOfVerts=\"" + n +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n      <Points>\n" +
         data_array("Float64", "centre", 3, points.str()) + "      </Points>\n      <PointData Vectors=\"velocity\">\n" +
         data_array("Float64", "velocity", 3, velocity.str()) + data_array("UInt8", "awake", 1, awake.str()) +
         data_array("Int32", "bonds", 1, bonded.str()) + data_array("Int32", "grain", 1, grain.str()) +
         data_array("UInt8", "in_scene", 1, in_scene.str()) + "      </PointData>\n      <Verts>\n" +
         data_array("Int32", "connectivity", 1, connectivity.str()) + data_array("Int32", "offsets", 1, offsets.str()) +
         "      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

}  // namespace

void ParaviewObserver::begin(const World&) { make_output_folder(folder_ / "paraview"); }

void ParaviewObserver::observe(const World& world, const Stepper& stepper, int frame, double) {
  write_file_atomically(folder_ / "paraview" / (frame_name(frame) + ".vtp"),
                        frame_poly_data(world, stepper.bonded_neighbours()));
  last_frame_ = frame;
}

void ParaviewObserver::end(const World&, const Stepper&, SceneReport& report) {
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (int frame = 1; frame <= last_frame_; ++frame)  // a resumed run wrote the earlier frames before
    pvd += "    <DataSet timestep=\"" + cell(frame / fps_) + "\" file=\"paraview/" + frame_name(frame) + ".vtp\"/>\n";
  pvd += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(folder_ / "grains.pvd", pvd);
  report.info.push_back({"paraview", "grains.pvd"});
}

}  // namespace rice::experiments
