// Fuzz target entries (see fuzz_targets.hpp).
#include "tests/fuzz/fuzz_targets.hpp"

#include <cstring>
#include <map>
#include <optional>
#include <sstream>

#include "experiments/scene/checkpoint_file.hpp"
#include "experiments/scene/scene_file.hpp"
#include "grains/absorption_table.hpp"
#include "grains/mesh_io.hpp"
#include "xpbd/state_archive.hpp"
#include "xpbd/types.hpp"

namespace rice::fuzz {
namespace {

constexpr const char* kName = "fuzz-input";

void expect(bool promise_kept, const std::string& what) {
  if (!promise_kept) throw Finding(what);
}

// The input as a seekable stream (readers cap declared counts by the bytes left).
std::istringstream stream_of(std::string_view bytes) { return std::istringstream(std::string(bytes)); }

// Runs `read`. An input error must be a std::runtime_error naming the input; it gives nullopt.
template <class Read>
auto read_or_refuse(Read read) -> std::optional<decltype(read())> {
  try {
    return read();
  } catch (const Finding&) {
    throw;
  } catch (const std::runtime_error& e) {
    expect(std::string_view(e.what()).starts_with(kName), std::string("the error does not name the input: ") + e.what());
    return std::nullopt;
  }
}

// Memory bounded by the input: a few dozen bytes of mesh per byte read, plus a constant.
void expect_size_bounded(size_t mesh_bytes, size_t input_bytes) {
  expect(mesh_bytes <= 64 * input_bytes + 4096,
         std::to_string(input_bytes) + " input bytes made a mesh of " + std::to_string(mesh_bytes) + " bytes");
}

template <class Matrix>
bool same_bits(const Matrix& a, const Matrix& b) {
  return a.rows() == b.rows() && std::memcmp(a.data(), b.data(), sizeof(typename Matrix::Scalar) * a.size()) == 0;
}

void read_surface(std::string_view bytes, grains::SurfaceFormat format) {
  std::istringstream in = stream_of(bytes);
  const auto mesh = read_or_refuse([&] { return grains::read_surface_mesh(in, format, kName); });
  if (!mesh) return;
  expect(mesh->V.allFinite(), "a vertex is not finite");
  expect(mesh->F.rows() > 0, "no faces, yet no error");
  expect(mesh->F.minCoeff() >= 0 && mesh->F.maxCoeff() < mesh->V.rows(), "a face index is out of range");
  expect_size_bounded(sizeof(double) * mesh->V.size() + sizeof(int) * mesh->F.size(), bytes.size());
  std::stringstream ply;
  grains::write_ply(ply, *mesh);
  const grains::SurfaceMesh back = grains::read_surface_mesh(ply, grains::SurfaceFormat::kPly, kName);
  expect(same_bits(back.V, mesh->V) && same_bits(back.F, mesh->F), "the PLY round trip changed the mesh");
}

void read_obj(std::string_view bytes) { read_surface(bytes, grains::SurfaceFormat::kObj); }
void read_off(std::string_view bytes) { read_surface(bytes, grains::SurfaceFormat::kOff); }
void read_ply(std::string_view bytes) { read_surface(bytes, grains::SurfaceFormat::kPly); }

void medit_round_trip(std::string_view bytes) {
  std::istringstream in = stream_of(bytes);
  const auto mesh = read_or_refuse([&] { return grains::read_medit(in, kName); });
  if (!mesh) return;
  expect(mesh->V.allFinite(), "a vertex is not finite");
  expect(mesh->T.rows() > 0, "no tetrahedra, yet no error");
  expect(mesh->T.minCoeff() >= 0 && mesh->T.maxCoeff() < mesh->V.rows(), "a tetrahedron index is out of range");
  expect_size_bounded(sizeof(double) * mesh->V.size() + sizeof(int) * mesh->T.size(), bytes.size());
  std::stringstream medit;
  grains::write_medit(medit, *mesh);
  const grains::VolumeMesh back = grains::read_medit(medit, kName);
  expect(same_bits(back.V, mesh->V) && same_bits(back.T, mesh->T), "the MEDIT round trip changed the mesh");
}

void read_absorption(std::string_view bytes) {
  std::istringstream in = stream_of(bytes);
  const auto samples = read_or_refuse([&] { return grains::read_absorption_table(in, kName); });
  if (!samples) return;
  expect(!samples->empty(), "no rows, yet no error");
  for (const grains::AbsorptionSample& s : *samples)
    expect(s.temperature_c >= 0.0 && s.temperature_c <= 100.0 && s.soak_minutes > 0.0 && s.soak_minutes <= 1e5 &&
               s.absorption_percent > 0.0 && s.absorption_percent <= 1000.0,
           "a sample outside the documented ranges");
}

void read_scene(std::string_view bytes) {
  const auto scene = read_or_refuse([&] { return experiments::parse_scene(bytes, kName); });
  if (!scene) return;
  const experiments::Scene& p = *scene;
  expect(p.grains.count >= 1 && p.grains.count <= 100000 && p.grains.variants >= 1 && p.grains.variants <= 1000 &&
             p.solver.frames >= 1 && p.solver.frames <= 100000 && p.solver.substeps >= 0 &&
             p.solver.substeps <= 10000 && p.solver.iterations >= 1 && p.solver.iterations <= 1000,
         "a count outside the documented ranges");
  expect(p.solver.fps > 0.0 && p.solver.fps <= 1000.0 && p.grains.young >= 1e3 && p.grains.young <= 1e9 &&
             p.grains.poisson > -1.0 && p.grains.poisson < 0.5 && p.grains.soak_minutes > 0.0 &&
             p.grains.soak_minutes <= 1e5 && p.grains.soak_temperature >= 0.0 && p.grains.soak_temperature <= 100.0 &&
             p.container.grid_spacing >= 2e-4 && p.container.grid_spacing <= 1e-2 && p.emitter.height >= 0.0 &&
             p.emitter.height <= 10.0 && p.emitter.radius >= 0.0 && p.emitter.radius <= 1.0 &&
             p.emitter.seconds > 0.0 && p.emitter.seconds <= 1e4,
         "a number outside the documented ranges");
  expect(p.effects.dynamic_friction >= 0.0 && p.effects.dynamic_friction <= p.effects.static_friction &&
             p.effects.static_friction <= 10.0,
         "friction coefficients outside 0 <= mu_k <= mu_s <= 10");
  expect(!p.solver.vertex_block_descent || p.grains.body == xpbd::BodyKind::kSoft, "vertex block descent on rigid grains");
  expect(p.emitter.kind != experiments::EmitterKind::kFill ||
             (p.emitter.mould >= 0 && p.emitter.mould < static_cast<int>(p.mesh_colliders.size()) &&
              p.mesh_colliders[p.emitter.mould].hollow),
         "a fill whose mould is not a hollow mesh");
  if (const auto& r = p.render)
    expect(r->width >= 16 && r->width <= 16384 && r->height >= 16 && r->height <= 16384 && r->samples_per_pixel >= 1 &&
               r->vertical_fov_degrees > 0.0 && r->vertical_fov_degrees < 180.0 && r->eye.has_value() == r->look_at.has_value() &&
               p.grains.body == xpbd::BodyKind::kRigid,
           "a render setting outside the documented ranges");
  for (const xpbd::Collider& c : p.colliders)
    expect(!c.motion.empty() && c.dynamic_friction <= c.static_friction, "a collider without a pose or with mu_k > mu_s");
  const experiments::Scene again = experiments::parse_scene(bytes, kName);
  expect(again.name == p.name && again.grains.count == p.grains.count && again.grains.seed == p.grains.seed,
         "two reads of one input differ");
}

/// A checkpoint file (experiments/scene/checkpoint_file.hpp), read as the scene its own header
/// names, so that only its version, sizes and state digest can refuse it: read, it writes back
/// to the same bytes. Then the same bytes as a state (xpbd/state_archive.hpp): read as sizes and
/// elements, they end in std::runtime_error or values, never in an allocation past their size.
void read_checkpoint(std::string_view bytes) {
  std::uint64_t digest = 0;
  if (bytes.size() >= 28) std::memcpy(&digest, bytes.data() + 20, sizeof digest);
  const auto checkpoint = read_or_refuse([&] { return experiments::parse_checkpoint(bytes, digest, kName); });
  if (checkpoint) expect(experiments::checkpoint_bytes(*checkpoint) == bytes, "a checkpoint read back differs");
  xpbd::StateReader in(bytes);
  std::vector<double> numbers;
  std::map<std::pair<int, int>, double> pairs;
  std::string text;
  xpbd::Positions x;
  std::vector<std::vector<std::string>> rows;
  try {
    in(numbers, pairs, text, x, rows);
  } catch (const std::runtime_error&) {
    return;
  }
  expect(sizeof(double) * (numbers.size() + x.size()) + text.size() <= bytes.size(), "a state larger than its bytes");
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"obj", read_obj}, {"off", read_off}, {"ply", read_ply}, {"medit", medit_round_trip}, {"absorption", read_absorption},
      {"scene", read_scene}, {"checkpoint", read_checkpoint}};
  return all;
}

const Target& target_named(std::string_view name) {
  for (const Target& target : targets())
    if (name == target.name) return target;
  throw std::invalid_argument("no fuzz target '" + std::string(name) + "'");
}

}  // namespace rice::fuzz
