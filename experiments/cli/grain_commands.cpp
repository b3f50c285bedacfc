// `rice grains`: a library of procedural grains; its options are the cultivar's shape (edits
// of the cultivar named), the porosity and the meshes.
#include <CLI/CLI.hpp>

#include <functional>
#include <utility>

#include "experiments/cli/command_family.hpp"
#include "experiments/cli/option_checks.hpp"
#include "experiments/figures/grain_library.hpp"
#include "grains/cultivar.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

class GrainCommands : public CommandFamily {
 public:
  explicit GrainCommands(CLI::App& app) {
    CLI::App* c = app.add_subcommand("grains", "procedural grains: render and simulation meshes, embedding");
    c->add_option("--out", out_, "output folder")->capture_default_str();
    c->add_option("--cultivar", cultivar_, "japonica, indica, aromatic or glutinous")->capture_default_str();
    c->add_option("--count", library_.count, "number of grains")->check(number_in(1, 1e6))->capture_default_str();
    c->add_option("--variants", library_.variants, "0: generate every grain; K: K variants, instanced")
        ->check(number_in(0, 1e5))->capture_default_str();
    c->add_option("--seed", library_.seed, "random seed")->check(seed_value())->capture_default_str();
    c->add_option("--base-mesh", base_mesh_, "closed manifold OBJ/OFF/PLY [m] replacing the base shape")
        ->check(CLI::ExistingFile);
    add_cultivar_edits(c);
    add_porosity_and_meshes(c);
    add(c, [this] { experiments::validate(settings()); }, [this] { grain_library_command(settings(), out_); });
  }

 private:
  void add_cultivar_edits(CLI::App* c) {
    using grains::Cultivar;
    const auto edit = [&](const std::string& name, const std::string& help, CLI::Validator range,
                          std::function<double&(Cultivar&)> field) {
      CLI::Option* option = c->add_option(name)->type_name("FLOAT")->description(help + " (cultivar default)")->check(range);
      cultivar_edits_.emplace_back(option, std::move(field));
    };
    edit("--length", "mean raw length [m]", number_in(1e-3, 30e-3), [](Cultivar& v) -> double& { return v.length.mean; });
    edit("--width", "mean raw width [m]", number_in(0.5e-3, 10e-3), [](Cultivar& v) -> double& { return v.width.mean; });
    edit("--thickness", "mean raw thickness [m]", number_in(0.5e-3, 10e-3),
         [](Cultivar& v) -> double& { return v.thickness.mean; });
    edit("--cooked-length-ratio", "cooked/raw length", number_in(0.5, 3),
         [](Cultivar& v) -> double& { return v.cooked_length_ratio; });
    edit("--cooked-width-ratio", "cooked/raw width", number_in(0.5, 3),
         [](Cultivar& v) -> double& { return v.cooked_width_ratio; });
    edit("--cooked-thickness-ratio", "cooked/raw thickness", number_in(0.5, 3),
         [](Cultivar& v) -> double& { return v.cooked_thickness_ratio; });
    edit("--tip-exponent", "tip profile exponent p (2 ellipsoidal, larger blunter)", number_in(1, 8),
         [](Cultivar& v) -> double& { return v.tip_exponent; });
    edit("--asymmetry", "dorsal/ventral width asymmetry", number_in(0, 0.5, Ends::kOpenHigh),
         [](Cultivar& v) -> double& { return v.asymmetry; });
    edit("--notch-depth", "embryo notch depth / thickness", number_in(0, 0.5, Ends::kOpenHigh),
         [](Cultivar& v) -> double& { return v.notch_depth; });
    edit("--notch-size", "embryo notch radius / length", number_in(0, 0.5, Ends::kOpenHigh),
         [](Cultivar& v) -> double& { return v.notch_size; });
    edit("--swell-min", "smallest P of eq. 2", number_in(1, 1.5), [](Cultivar& v) -> double& { return v.swell_min; });
    edit("--swell-max", "largest P of eq. 2", number_in(1, 1.5), [](Cultivar& v) -> double& { return v.swell_max; });
  }

  void add_porosity_and_meshes(CLI::App* c) {
    grains::PorosityParameters& porosity = library_.recipe.porosity;
    c->add_option("--density", library_.recipe.density, "grain material density [kg/m^3]")->check(number_in(100, 1e4))
        ->capture_default_str();
    c->add_option("--porosity", porosity.core_porosity, "void fraction of the core")->check(number_in(0, 0.9))
        ->capture_default_str();
    c->add_option("--pores", porosity.pore_count, "pore count (-1: from --porosity)")->check(number_in(-1, 1e5))
        ->capture_default_str();
    // Radii and voxels under 20 µm and 5 µm would make level sets of billions of voxels.
    c->add_option("--pore-radius-min", porosity.pore_radius_min, "[m]")->check(number_in(20e-6, 1e-3))
        ->capture_default_str();
    c->add_option("--pore-radius-max", porosity.pore_radius_max, "[m]")->check(number_in(20e-6, 1e-3))
        ->capture_default_str();
    c->add_option("--bumps", porosity.bump_count, "spheres on the surface")->check(number_in(0, 1e5))
        ->capture_default_str();
    c->add_option("--bump-radius-min", porosity.bump_radius_min, "[m]")->check(number_in(20e-6, 1e-3))
        ->capture_default_str();
    c->add_option("--bump-radius-max", porosity.bump_radius_max, "[m]")->check(number_in(20e-6, 1e-3))
        ->capture_default_str();
    c->add_option("--skin", porosity.skin_thickness, "pore-free skin [m]")->check(number_in(0, 1e-3))
        ->capture_default_str();
    c->add_option("--voxel-size", porosity.voxel_size, "[m] (0: smallest radius / 1.5; else >= 5e-6)")
        ->check(number_in(0, 1e-3))->capture_default_str();
    c->add_option("--adaptivity", library_.recipe.mesh_adaptivity, "render mesh adaptivity")->check(number_in(0, 1))
        ->capture_default_str();
    c->add_option("--min-vertices", library_.recipe.simulation.min_vertices, "simulation mesh size range")
        ->check(number_in(4, 1e4))->capture_default_str();
    c->add_option("--max-vertices", library_.recipe.simulation.max_vertices, "simulation mesh size range")
        ->check(number_in(4, 1e4))->capture_default_str();
    c->add_flag("--no-sections", no_sections_, "skip the cross-section PNGs");
  }

  /// The cultivar named, then the user's edits of it, then the base mesh read.
  GrainLibrarySettings settings() const {
    GrainLibrarySettings settings = library_;
    settings.recipe.cultivar = grains::cultivar_by_name(cultivar_);
    for (const auto& [option, field] : cultivar_edits_)
      if (option->count()) field(settings.recipe.cultivar) = option->as<double>();
    if (!base_mesh_.empty()) settings.recipe.base_mesh = grains::read_surface_mesh(base_mesh_);
    settings.sections = !no_sections_;
    return settings;
  }

  GrainLibrarySettings library_;
  std::string out_ = "out/grains", cultivar_ = "japonica", base_mesh_;
  bool no_sections_ = false;
  /// Edits of the chosen cultivar, applied after it is looked up by name.
  std::vector<std::pair<CLI::Option*, std::function<double&(grains::Cultivar&)>>> cultivar_edits_;
};

}  // namespace

std::unique_ptr<CommandFamily> add_grain_commands(CLI::App& app) { return std::make_unique<GrainCommands>(app); }

}  // namespace rice::experiments
