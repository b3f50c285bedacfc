// The pour scene; see pour_scene.hpp.
#include "experiments/scene/pour_scene.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "experiments/pile/angle_of_repose.hpp"
#include "experiments/scene/collider_grid.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/scene/mould_fill.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/pile/pile_measures.hpp"
#include "experiments/pile/pile_plot.hpp"
#include "experiments/pile/pile_section.hpp"
#include "experiments/io/png_image.hpp"
#include "grains/absorption_table.hpp"
#include "grains/chawan.hpp"
#include "grains/collision_spheres.hpp"
#include "grains/grain_generator.hpp"
#include "grains/mesh_io.hpp"
#include "grains/random_stream.hpp"
#include "grains/tet_quality.hpp"
#include "grains/water_content.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/sleeping.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

struct Variant {
  grains::Grain grain;
  grains::CollisionSpheres spheres;
};

/// Grain frame to world: p ↦ swell · R p + position.
grains::Vertices place(const grains::Vertices& V, double swell, const Eigen::Quaterniond& rotation, const Vec3& position) {
  return ((swell * V) * rotation.toRotationMatrix().transpose()).rowwise() + position.transpose();
}

/// Spout positions: a square lattice of `cell` inside a circle of `radius` at height
/// `bottom`; grain k goes to point k mod n of layer k / n.
std::vector<Vec3> spout_positions(int count, double cell, double radius, double bottom, int* per_layer) {
  std::vector<Vec3> layer;
  const int n = static_cast<int>(std::floor(radius / cell));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      if (std::hypot(i * cell, j * cell) <= radius) layer.emplace_back(i * cell, j * cell, 0.0);
  if (layer.empty()) throw std::invalid_argument("pour: the bowl is narrower than one grain");
  std::vector<Vec3> positions;
  for (int k = 0; k < count; ++k) positions.push_back(layer[k % layer.size()] + Vec3(0.0, 0.0, bottom));
  *per_layer = static_cast<int>(layer.size());
  return positions;
}

/// One mesh holding all of `parts`, faces renumbered.
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

/// Each grain's pose: rigid, its centre and its rotation since the start (world =
/// q (p₀ − c₀) + c); soft, its simulation vertices. `in_scene` is 0 for the grains still
/// parked far away (not yet poured, or a fill found no room for them), which a render leaves
/// out.
CsvTable pose_table(const xpbd::Model& model, const std::vector<xpbd::Quat>& initial_orientation, int released) {
  const bool rigid = !model.bodies.empty() && model.bodies.front().kind == xpbd::BodyKind::kRigid;
  CsvTable poses(rigid ? std::vector<std::string>{"grain", "x", "y", "z", "qw", "qx", "qy", "qz", "in_scene"}
                       : std::vector<std::string>{"grain", "vertex", "x", "y", "z", "in_scene"});
  for (size_t g = 0; g < model.bodies.size(); ++g) {
    const xpbd::Body& body = model.bodies[g];
    const std::string in_scene = static_cast<int>(g) < released ? "1" : "0";
    if (body.kind == xpbd::BodyKind::kRigid) {
      const xpbd::RigidBody& r = model.rigid_bodies[body.rigid_body];
      const xpbd::Quat q = r.q() * initial_orientation[body.rigid_body].conjugate();
      poses.add_row({cell(static_cast<long>(g)), cell(r.x.x()), cell(r.x.y()), cell(r.x.z()), cell(q.w()), cell(q.x()),
                     cell(q.y()), cell(q.z()), in_scene});
    } else {
      for (int v = 0; v < body.particle_count; ++v) {
        const auto x = model.particles.x.row(body.first_particle + v);
        poses.add_row({cell(static_cast<long>(g)), cell(v), cell(x(0)), cell(x(1)), cell(x(2)), in_scene});
      }
    }
  }
  return poses;
}

/// Bowl outline for the plots: the inside wall's profile r(z) on both sides.
std::string bowl_outline(const grains::ChawanShape& s) {
  std::ostringstream out;
  out << "r,z\n";
  const double a = s.rim_radius - s.wall_thickness;
  for (int k = -40; k <= 40; ++k) {
    const double theta = M_PI / 2 * k / 40.0;
    out << cell(a * std::sin(theta)) << ',' << cell(s.height - s.inner_depth * std::cos(theta)) << '\n';
  }
  return out.str();
}

}  // namespace

void validate(const PourSettings& s) {
  // Messages name the settings as `rice pour` spells them.
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("pour: " + what);
  };
  grains::cultivar_by_name(s.cultivar);  // throws, listing the names
  require(s.count >= 1 && s.count <= 100000, "--count must be in [1, 100000]");
  require(s.variants >= 1 && s.variants <= 1000, "--variants must be in [1, 1000]");
  require(s.frames >= 1 && s.frames <= 100000, "--frames must be in [1, 100000]");
  require(s.fps > 0.0 && s.fps <= 1000.0, "--fps must be in (0, 1000]");
  require(s.substeps >= 0 && s.substeps <= 10000, "--substeps must be in [0, 10000] (0: by body kind)");
  require(s.iterations >= 1 && s.iterations <= 1000, "--iterations must be in [1, 1000]");
  require(s.young >= 1e3 && s.young <= 1e9, "--young must be in [1e3, 1e9] Pa");
  require(s.poisson > -1.0 && s.poisson < 0.5, "Poisson's ratio must be in (-1, 0.5)");
  require(s.soak_minutes > 0.0 && s.soak_minutes <= 1e5, "--soak-minutes must be in (0, 1e5]");
  require(s.soak_temperature >= 0.0 && s.soak_temperature <= 100.0, "--soak-temperature must be in [0, 100] C");
  require(std::isnan(s.stickiness) || (s.stickiness >= 0.0 && s.stickiness <= 1000.0),
          "--stickiness must be in [0, 1000] grain weights");
  require(s.static_friction >= 0.0 && s.static_friction <= 10.0 && s.dynamic_friction >= 0.0 &&
              s.dynamic_friction <= s.static_friction,
          "need 0 <= --dynamic-friction <= --static-friction <= 10, got " + cell(s.dynamic_friction) + " and " +
              cell(s.static_friction));
  require(s.grid_spacing >= 2e-4 && s.grid_spacing <= 1e-2, "--grid-spacing must be in [2e-4, 1e-2] m");
  require(s.chawan_scale >= 0.1 && s.chawan_scale <= 10.0, "the chawan's scale must be in [0.1, 10]");
  require(s.pour_seconds >= 0.0 && s.pour_seconds <= 1e4, "--pour-seconds must be in [0, 1e4]");
  require(s.spout_height >= 0.0 && s.spout_height <= 10.0, "--spout-height must be in [0, 10] m");
  require(s.spout_radius >= 0.0 && s.spout_radius <= 1.0, "--spout-radius must be in [0, 1] m (0: the container's)");
  for (size_t c = 0; c < s.colliders.size(); ++c) {
    require(s.colliders[c].shape != xpbd::ColliderShape::kDistanceGrid, "scene colliders are analytic shapes");
    xpbd::validate(s.colliders[c], static_cast<int>(c) + 1);  // 0 is the container
  }
  for (const MeshCollider& m : s.mesh_colliders) {
    require(m.mesh.F.rows() > 0 && m.mesh.V.allFinite(), "a mesh collider needs triangles and finite vertices");
    require(m.grid_spacing >= 2e-4 && m.grid_spacing <= 1e-2, "a mesh collider's grid spacing must be in [2e-4, 1e-2] m");
  }
  require(s.fill_round_seconds > 0.0 && s.fill_round_seconds <= 1e3, "the fill's rounds must be (0, 1e3] s apart");
  require(s.fill_mould < static_cast<int>(s.mesh_colliders.size()) &&
              (s.fill_mould < 0 || s.mesh_colliders[s.fill_mould].hollow),
          "the mould to fill must be a hollow mesh collider");
}

int substeps_per_frame(const PourSettings& settings) {
  if (settings.substeps > 0) return settings.substeps;
  return settings.body == xpbd::BodyKind::kRigid ? 80 : 480;
}

PourResult pour_command(const PourSettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const bool plate = settings.container == Container::kPlate;
  const grains::ChawanShape bowl_shape = grains::scaled({}, settings.chawan_scale);

  // Grains: variants, their spheres, then instances placed on a lattice above the bowl.
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name(settings.cultivar);
  grains::RandomStream random(settings.seed);
  std::vector<std::uint64_t> seeds(settings.variants);
  for (std::uint64_t& seed : seeds) seed = random.child_seed();
  std::vector<Variant> variants(settings.variants);
  for_each_item("grain variants", settings.variants, [&](int i) {
    variants[i].grain = grains::make_grain(recipe, seeds[i], 1.0);
    variants[i].spheres = grains::fit_collision_spheres(variants[i].grain.simulation);
  });
  auto instances = grains::make_instances(settings.count, settings.variants, recipe.cultivar, random);
  double longest = 0.0;
  for (const Variant& v : variants)
    longest = std::max(longest, (v.grain.simulation.V.colwise().maxCoeff() - v.grain.simulation.V.colwise().minCoeff()).norm());
  longest *= recipe.cultivar.swell_max;
  const double inner_radius = bowl_shape.rim_radius - bowl_shape.wall_thickness;
  // Mesh colliders: their distance grids, sampled now.
  std::vector<xpbd::Collider> mesh_colliders;
  for (const MeshCollider& m : settings.mesh_colliders) {
    xpbd::Collider c = m.collider;
    c.shape = xpbd::ColliderShape::kDistanceGrid;
    c.grid = std::make_shared<const xpbd::DistanceGrid>(distance_grid_of(m.mesh, m.grid_spacing, 0.01, m.hollow));
    mesh_colliders.push_back(std::move(c));
  }
  int per_layer = 0;
  const double spout_radius = settings.spout_radius > 0.0 ? settings.spout_radius
                              : plate                      ? 1.1 * longest
                                                           : 0.6 * inner_radius - longest;
  std::vector<Vec3> drops, lattice;
  Vec3 fill_cell = Vec3::Zero();
  if (settings.fill_mould >= 0) {
    // Each grain along the world's axes (turned end over end or not), in a cell of the largest
    // grain's box; each is built at a lattice point (parked apart from the others: a
    // "layer" is one lattice's worth) and moved to its own when released.
    Vec3 box = Vec3::Zero();
    for (const Variant& v : variants)
      box = box.cwiseMax((v.grain.simulation.V.colwise().maxCoeff() - v.grain.simulation.V.colwise().minCoeff()).transpose());
    fill_cell = 1.05 * recipe.cultivar.swell_max * box;
    lattice = mould_lattice(mesh_colliders[settings.fill_mould], fill_cell);
    if (lattice.empty()) throw std::invalid_argument("fill: not one grain fits in the mould");
    for (int g = 0; g < settings.count; ++g) drops.push_back(lattice[g % lattice.size()]);
    const std::array<Eigen::Quaterniond, 4> turns{
        Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0), Eigen::Quaterniond(0.0, 0.0, 1.0, 0.0),
        Eigen::Quaterniond(0.0, 0.0, 0.0, 1.0)};
    for (int g = 0; g < settings.count; ++g) instances[g].rotation = turns[g % 4];
    per_layer = static_cast<int>(lattice.size());
  } else {
    drops = spout_positions(settings.count, 1.05 * longest, spout_radius,
                            settings.spout_height + (plate ? 0.0 : bowl_shape.height), &per_layer);
  }
  const int layers = (settings.count + per_layer - 1) / per_layer;
  // A layer must have fallen clear of the spout, 1.05 grain lengths from rest, before the next
  // leaves: else grains are released inside each other.
  const double clear_seconds = std::sqrt(2.0 * 1.05 * longest / 9.81);
  if (settings.fill_mould < 0 && layers > 1 && settings.pour_seconds > 0.0 && settings.pour_seconds / layers < clear_seconds)
    throw std::invalid_argument("pour: " + std::to_string(layers) + " layers of " + std::to_string(per_layer) +
                                " grains leave the spout " + fixed(1e3 * settings.pour_seconds / layers, 1) +
                                " ms apart, sooner than one falls clear of the next (" +
                                fixed(1e3 * clear_seconds, 1) + " ms): raise --pour-seconds to at least " +
                                fixed(layers * clear_seconds, 2));
  make_output_folder(folder);
  make_output_folder(folder / "frames");
  const grains::SurfaceMesh bowl = grains::make_chawan(bowl_shape);
  if (!plate) {
    write_file_atomically(folder / "chawan.obj", [&](std::ostream& out) { grains::write_obj(out, bowl); });
    write_file_atomically(folder / "bowl_outline.csv", bowl_outline(bowl_shape));
  }
  // Parked layers wait 2 m apart along x, far from the bowl and from each other.
  const auto parking = [&](int g) { return Vec3(2.0 * (1 + g / per_layer), 0.0, 0.0); };

  const grains::WaterContentModel water(grains::read_absorption_table(grains::default_absorption_table()));
  const double cohesion_ratio =
      water.cohesion_ratio(std::isnan(settings.stickiness) ? recipe.cultivar.stickiness : settings.stickiness,
                           settings.soak_minutes, settings.soak_temperature);
  const double rayleigh_time = settings.damping ? water.beta(settings.soak_minutes, settings.soak_temperature) : 0.0;
  const auto material = xpbd::lame_from_young_poisson(settings.young, settings.poisson);

  xpbd::Model model;
  model.contact.static_friction = settings.static_friction;
  model.contact.dynamic_friction = settings.dynamic_friction;
  model.contact.cohesion = settings.cohesion;
  model.sleep.enabled = settings.sleeping;
  std::vector<grains::Vertices> rest_vertices(settings.count);  // at the spout
  for (int g = 0; g < settings.count; ++g) {
    const Variant& variant = variants[instances[g].variant];
    const double P = instances[g].swell;
    const Eigen::Quaterniond& R = instances[g].rotation;
    rest_vertices[g] = place(variant.grain.simulation.V, P, R, drops[g]);
    const xpbd::TetMesh mesh{rest_vertices[g].rowwise() + parking(g).transpose(), variant.grain.simulation.T};
    const xpbd::SphereSet spheres{place(variant.spheres.centres, P, R, drops[g] + parking(g)), P * variant.spheres.radii};
    const double density = variant.grain.simulation_density;
    const int b = settings.body == xpbd::BodyKind::kRigid
                      ? xpbd::add_rigid_body(model, mesh, density, spheres)
                      : xpbd::add_soft_body(model, mesh, density, material, rayleigh_time, spheres);
    const double mass = density * grains::total_volume({mesh.V, mesh.T});
    model.bodies[b].bond_strength = settings.cohesion ? cohesion_ratio * mass * model.gravity.norm() : 0.0;
    model.bodies[b].asleep = true;  // parked until its layer leaves the spout
  }
  std::vector<Vec3> initial_centre(settings.count);
  for (int g = 0; g < settings.count; ++g) initial_centre[g] = xpbd::body_centre(model, model.bodies[g]) - parking(g);
  // What a renderer needs to place each grain's render mesh at a frame's pose (c, q):
  // world = c + q (drop + P R p − c₀) for p in its variant's render mesh.
  make_output_folder(folder / "variants");
  for (int i = 0; i < settings.variants; ++i) {
    write_file_atomically(folder / "variants" / ("variant_" + std::to_string(i) + ".ply"),
                          [&](std::ostream& out) { grains::write_ply(out, variants[i].grain.render); });
  }
  CsvTable placement({"grain", "variant", "swell", "qw", "qx", "qy", "qz", "drop_x", "drop_y", "drop_z", "centre_x",
                      "centre_y", "centre_z"});
  for (int g = 0; g < settings.count; ++g) {
    const Eigen::Quaterniond& R = instances[g].rotation;
    placement.add_row({cell(g), cell(instances[g].variant), cell(instances[g].swell), cell(R.w()), cell(R.x()),
                       cell(R.y()), cell(R.z()), cell(drops[g].x()), cell(drops[g].y()), cell(drops[g].z()),
                       cell(initial_centre[g].x()), cell(initial_centre[g].y()), cell(initial_centre[g].z())});
  }
  write_file_atomically(folder / "grains.csv", placement.text());
  // Moves a parked grain to its drop point moved by `offset`, and wakes it.
  const auto release = [&](int g, const Vec3& offset) {
    const Vec3 move = offset - parking(g);
    xpbd::Body& body = model.bodies[g];
    if (body.kind == xpbd::BodyKind::kRigid) {
      xpbd::RigidBody& rigid = model.rigid_bodies[body.rigid_body];
      rigid.x += move;
      rigid.remember_pose();
    } else {
      model.particles.x.middleRows(body.first_particle, body.particle_count).rowwise() += move.transpose();
    }
    xpbd::wake(body);
  };
  // A heap that grew up to the spout (sticky grains can build a column) would have new grains
  // released inside it: the spout then rises to keep a grain length and a half above the top
  // of the grains that have landed (slower than 0.1 m/s; a grain falls faster 10 ms after its
  // release, and layers leave further apart than that).
  const auto speed = [&](const xpbd::Body& body) {
    if (body.kind == xpbd::BodyKind::kRigid) return model.rigid_bodies[body.rigid_body].v.norm();
    return model.particles.v.middleRows(body.first_particle, body.particle_count).colwise().mean().norm();
  };
  const auto spout_lift = [&](int released) {
    double top = -INFINITY;
    for (int g = 0; g < released; ++g)
      if (speed(model.bodies[g]) < 0.1) top = std::max(top, xpbd::body_centre(model, model.bodies[g]).z());
    return std::max(0.0, top + 1.5 * longest - drops.front().z());
  };
  int released = 0;
  std::vector<xpbd::Quat> initial_orientation;
  for (const xpbd::RigidBody& rigid : model.rigid_bodies) initial_orientation.push_back(rigid.q());

  xpbd::Collider container;
  if (plate) {
    container.shape = xpbd::ColliderShape::kHalfSpace;  // the plane z = 0, normal +z
  } else {
    container.shape = xpbd::ColliderShape::kDistanceGrid;
    container.grid = std::make_shared<const xpbd::DistanceGrid>(distance_grid_of(bowl, settings.grid_spacing, 0.01));
  }
  container.static_friction = settings.static_friction;
  container.dynamic_friction = settings.dynamic_friction;
  model.colliders.push_back(container);
  model.colliders.insert(model.colliders.end(), settings.colliders.begin(), settings.colliders.end());
  model.colliders.insert(model.colliders.end(), mesh_colliders.begin(), mesh_colliders.end());
  const double setup_seconds = seconds_since(start);

  xpbd::SolverSettings solver_settings;
  solver_settings.time_step = 1.0 / settings.fps;
  solver_settings.substeps = substeps_per_frame(settings);
  solver_settings.iterations = settings.iterations;
  if (settings.vertex_block_descent) solver_settings.method = xpbd::Method::kVbd;
  xpbd::Solver solver(model, solver_settings);

  CsvTable stats({"frame", "time_s", "wall_s", "awake", "candidates", "contacts", "bonds", "bonds_broken",
                  "max_penetration_m", "kinetic_energy_j", "top_m", "broad_phase_s", "narrow_phase_s", "solve_s",
                  "sleeping_s"});
  // The highest centre of the grains released so far, and its value before the first
  // collider is removed (a mould taken away).
  const auto top_of_grains = [&] {
    double top = -INFINITY;
    for (int g = 0; g < released; ++g) top = std::max(top, xpbd::body_centre(model, model.bodies[g]).z());
    return top;
  };
  double first_removal = INFINITY;
  for (const xpbd::Collider& c : model.colliders) first_removal = std::min(first_removal, c.removal_time);
  double top_before_removal = std::numeric_limits<double>::quiet_NaN();
  double next_round = 0.0;  // the fill's
  int fill_rounds = 0;
  // A grain's render mesh through its embedding, from its simulation vertices now.
  const auto render_mesh_now = [&](int g) -> grains::SurfaceMesh {
    const grains::Grain& grain = variants[instances[g].variant].grain;
    const xpbd::Body& body = model.bodies[g];
    grains::Vertices simulation;
    if (body.kind == xpbd::BodyKind::kRigid) {
      const xpbd::RigidBody& rigid = model.rigid_bodies[body.rigid_body];
      const xpbd::Quat q = rigid.q() * initial_orientation[body.rigid_body].conjugate();
      simulation = ((rest_vertices[g].rowwise() - initial_centre[g].transpose()) * q.toRotationMatrix().transpose())
                       .rowwise() +
                   rigid.x.transpose();
    } else {
      simulation = model.particles.x.middleRows(body.first_particle, body.particle_count);
    }
    return {grains::apply_embedding(grain.embedding, simulation, grain.simulation.T), grain.render.F};
  };
  Progress progress("pour frames", settings.frames);
  const auto simulation_start = std::chrono::steady_clock::now();
  for (int frame = 1; frame <= settings.frames; ++frame) {
    const auto frame_start = std::chrono::steady_clock::now();
    if (settings.fill_mould >= 0) {
      const double mould_removal = settings.mesh_colliders[settings.fill_mould].collider.removal_time;
      if (released < settings.count && solver.time() >= next_round - 1e-9 && solver.time() < mould_removal) {
        // A round of the fill: grains at the free lattice points, lowest first.
        std::vector<Vec3> occupied;
        for (int g = 0; g < released; ++g) occupied.push_back(xpbd::body_centre(model, model.bodies[g]));
        for (const Vec3& spot : free_points(lattice, occupied, fill_cell.maxCoeff())) {
          if (released == settings.count) break;
          release(released, spot - drops[released]);
          ++released;
        }
        next_round = solver.time() + settings.fill_round_seconds;
        ++fill_rounds;
      }
    } else {
      const int due = settings.pour_seconds > 0.0
                          ? std::min(settings.count, per_layer * (1 + static_cast<int>(std::floor(
                                                                          solver.time() / settings.pour_seconds * layers))))
                          : settings.count;  // a clump: every layer at once
      if (released < due) {
        // Layers due in the same frame (long frames) leave stacked a cell apart.
        const double lift = spout_lift(released);
        const int first_layer = released / per_layer;
        for (; released < due; ++released)
          release(released, Vec3(0.0, 0.0, lift + 1.05 * longest * (released / per_layer - first_layer)));
      }
    }
    solver.step();
    const double wall = seconds_since(frame_start);
    const xpbd::ContactStatistics& contact = solver.contacts()->statistics();
    const xpbd::SolverTimings& t = solver.timings();
    const long awake = std::count_if(model.bodies.begin(), model.bodies.end(), [](const xpbd::Body& b) { return !b.asleep; });
    const double top = top_of_grains();
    if (solver.time() <= first_removal) top_before_removal = top;
    stats.add_row({cell(frame), cell(solver.time()), cell(wall), cell(awake), cell(contact.candidates),
                   cell(contact.contacts), cell(contact.bonds), cell(contact.bonds_broken),
                   cell(contact.max_penetration), cell(xpbd::kinetic_energy(model)), cell(top), cell(t.broad_phase),
                   cell(t.narrow_phase), cell(t.solve()), cell(t.sleeping)});
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", frame);
    write_file_atomically(folder / "frames" / (std::string(name) + ".csv"), pose_table(model, initial_orientation, released).text());
    if (settings.render_meshes) {
      std::vector<grains::SurfaceMesh> meshes;
      for (int g = 0; g < settings.count; ++g) meshes.push_back(render_mesh_now(g));
      write_file_atomically(folder / "frames" / (std::string(name) + ".ply"),
                            [&](std::ostream& out) { grains::write_ply(out, merged(meshes)); });
    }
    progress.update(frame);
    stop_point();
  }
  progress.finish();
  const double simulation_seconds = seconds_since(simulation_start);
  if (settings.fill_mould >= 0 && released < settings.count)
    std::printf("fill: %d of %d grains found no room in the mould (they stay parked, out of the measures)\n",
                settings.count - released, settings.count);
  write_file_atomically(folder / "stats.csv", stats.text());

  // The grains released; those still parked (a fill found them no room) stay out.
  CsvTable final_centres({"grain", "x", "y", "z", "r"});
  std::vector<Vec3> centres;
  for (int g = 0; g < released; ++g) {
    const Vec3 c = xpbd::body_centre(model, model.bodies[g]);
    centres.push_back(c);
    final_centres.add_row({cell(g), cell(c.x()), cell(c.y()), cell(c.z()), cell(std::hypot(c.x(), c.y()))});
  }
  write_file_atomically(folder / "final_centres.csv", final_centres.text());
  PourResult result;
  result.simulation_seconds = simulation_seconds;
  result.awake = static_cast<int>(
      std::count_if(model.bodies.begin(), model.bodies.end(), [](const xpbd::Body& b) { return !b.asleep; }));
  result.penetration = xpbd::deepest_penetration(model, solver.time());
  result.footprint_radius = footprint_radius(centres);
  result.clusters = count_clusters(model, 1e-4);
  result.top = top_of_grains();
  // Paper Fig. 16 b (a mould's fill) and the chawan's packing (Fig. 15): the pile cut half way
  // up from the room's floor, and the share of the room there that grains cover (the room: the
  // pixels outside the container's solid that connect to the one under the grains' mean centre).
  const xpbd::Collider* container_room =
      settings.fill_mould >= 0 ? &mesh_colliders[settings.fill_mould] : plate ? nullptr : &model.colliders.front();
  // The grains in the container: inside the mould's room, or within the bowl's rim (its
  // room reaches past its walls); those that fell out, maybe far, stay out of the picture.
  const xpbd::ColliderKeyframe pose =
      container_room ? xpbd::collider_pose(*container_room, 0.0) : xpbd::ColliderKeyframe{};
  const auto room_at = [&](const Vec3& p) {
    return xpbd::local_signed_distance(*container_room, pose.rotation.conjugate() * (p - pose.translation)).distance;
  };
  const auto in_container = [&](const Vec3& c) {
    return settings.fill_mould >= 0 ? room_at(c) > 0.0 : c.head<2>().norm() < bowl_shape.rim_radius;
  };
  const long contained = container_room ? std::count_if(centres.begin(), centres.end(), in_container) : 0;
  if (container_room) result.in_container = static_cast<int>(contained);
  if (contained > 0) {
    std::vector<grains::SurfaceMesh> meshes;
    Eigen::Vector2d lower = Eigen::Vector2d::Constant(INFINITY), upper = -lower, mean = Eigen::Vector2d::Zero();
    for (int g = 0; g < released; ++g) {
      if (!in_container(centres[g])) continue;
      meshes.push_back(render_mesh_now(g));
      lower = lower.cwiseMin(meshes.back().V.leftCols<2>().colwise().minCoeff().transpose());
      upper = upper.cwiseMax(meshes.back().V.leftCols<2>().colwise().maxCoeff().transpose());
      mean += centres[g].head<2>() / contained;
    }
    if (settings.fill_mould < 0) {  // the whole bowl in the picture
      lower = lower.cwiseMin(Eigen::Vector2d::Constant(-bowl_shape.rim_radius));
      upper = upper.cwiseMax(Eigen::Vector2d::Constant(bowl_shape.rim_radius));
    }
    const double floor = settings.fill_mould >= 0 ? 0.0 : bowl_shape.height - bowl_shape.inner_depth;
    result.section_height = 0.5 * (floor + result.top);
    const PileSection section = cut_pile(meshes, result.section_height, lower, upper, 1e-4);
    const auto in_room = [&](const Eigen::Vector2d& p) {
      return room_at(Vec3(p.x(), p.y(), result.section_height)) > 0.0;
    };
    const std::vector<char> room = region_around(section, in_room, mean);
    result.packing_fraction = packing_fraction(section, room);
    write_png(folder / "section.png", section_image(section, room));
  }
  result.top_before_removal = std::isfinite(first_removal) ? top_before_removal : std::numeric_limits<double>::quiet_NaN();
  const std::optional<HeapProfile> fitted = write_pile_plot(
      folder, centres,
      {.plate = plate,
       .cohesion = settings.cohesion,
       .rim_radius = bowl_shape.rim_radius,
       .ring_width = 0.5 * longest});
  result.angle_of_repose_degrees = fitted ? fitted->angle_degrees : std::numeric_limits<double>::quiet_NaN();
  result.heap_height = fitted ? fitted->apex_height : std::numeric_limits<double>::quiet_NaN();
  stop_point();

  const xpbd::SolverTimings& t = solver.timings();
  std::cout << "rice pour: " << settings.count << (settings.body == xpbd::BodyKind::kRigid ? " rigid" : " soft")
            << " grains, " << settings.frames << " frames in " << simulation_seconds << " s (broad phase "
            << t.broad_phase << " s, narrow phase " << t.narrow_phase << " s, solves " << t.solve() << " s, sleeping "
            << t.sleeping << " s); set-up " << setup_seconds << " s\n";
  if (fitted)
    std::cout << "rice pour: angle of repose " << fixed(result.angle_of_repose_degrees, 1) << " degrees, heap "
              << fixed(1e3 * result.heap_height, 1) << " mm high\n";
  write_file_atomically(
      folder / "run_info.txt",
      run_info({{"command", "pour"},
                {"container", plate ? "plate" : "chawan"},
                {"chawan_scale", cell(settings.chawan_scale)},
                {"angle_of_repose_deg", fitted ? cell(result.angle_of_repose_degrees) : "n/a"},
                {"heap_height_m", fitted ? cell(result.heap_height) : "n/a"},
                {"awake_at_end", cell(result.awake)},
                {"footprint_radius_m", cell(result.footprint_radius)},
                {"clusters", cell(result.clusters)},
                {"top_centre_at_end_m", cell(result.top)},
                {"rim_height_m", plate ? "n/a" : cell(bowl_shape.height)},
                {"grains_in_container", container_room ? cell(result.in_container) : "n/a"},
                {"section_height_m", container_room ? cell(result.section_height) : "n/a"},
                {"packing_fraction_in_room_at_section", container_room ? cell(result.packing_fraction) : "n/a"},
                {"top_centre_before_removal_m", std::isfinite(first_removal) ? cell(result.top_before_removal) : "n/a"},
                {"penetration_between_grains_at_end_m", cell(result.penetration.between_bodies)},
                {"penetration_into_container_at_end_m", cell(result.penetration.into_colliders)},
                {"cultivar", settings.cultivar},
                {"count", cell(settings.count)},
                {"variants", cell(settings.variants)},
                {"body", settings.body == xpbd::BodyKind::kRigid ? "rigid" : "soft"},
                {"frames", cell(settings.frames)},
                {"pour_seconds", cell(settings.pour_seconds)},
                {"spout_height_m", cell(settings.spout_height)},
                {"emitter", settings.fill_mould >= 0 ? "fill" : "spout"},
                {"fill_rounds", cell(fill_rounds)},
                {"grains_placed", cell(released)},
                {"spout_radius_m", cell(spout_radius)},
                {"more_colliders", cell(static_cast<long>(settings.colliders.size() + settings.mesh_colliders.size()))},
                {"grains_per_layer", cell(per_layer)},
                {"fps", cell(settings.fps)},
                {"substeps", cell(substeps_per_frame(settings))},
                {"iterations", cell(settings.iterations)},
                {"method", settings.vertex_block_descent ? "vbd" : "xpbd"},
                {"young_pa", cell(settings.young)},
                {"rayleigh_time_s", cell(rayleigh_time)},
                {"cohesion", settings.cohesion ? "on" : "off"},
                {"damping", settings.damping ? "on" : "off"},
                {"pull_off_force_in_weights", cell(cohesion_ratio)},
                {"sleeping", settings.sleeping ? "on" : "off"},
                {"static_friction", cell(settings.static_friction)},
                {"dynamic_friction", cell(settings.dynamic_friction)},
                {"seed", std::to_string(settings.seed)},
                {"setup_wall_s", cell(setup_seconds)},
                {"simulation_wall_s", cell(simulation_seconds)},
                {"broad_phase_s", cell(t.broad_phase)},
                {"narrow_phase_s", cell(t.narrow_phase)},
                {"solve_s", cell(t.solve())},
                {"sleeping_s", cell(t.sleeping)},
                {"frame_poses", settings.body == xpbd::BodyKind::kRigid
                                    ? "world = q (p0 - c0) + (x, y, z); c0 the grain's first centre"
                                    : "simulation vertices"},
                {"wall_s", cell(seconds_since(start))}}));
  return result;
}

}  // namespace rice::experiments
