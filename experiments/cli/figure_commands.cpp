// `rice figure 8|9|10|11|13` and `rice table 1`: one function per figure or table, each adding
// its options and saying how it is checked and run.
#include <CLI/CLI.hpp>

#include "experiments/cli/command_family.hpp"
#include "experiments/cli/option_checks.hpp"
#include "experiments/figures/figure10.hpp"
#include "experiments/figures/figure13.hpp"
#include "experiments/figures/grain_figures.hpp"
#include "experiments/figures/table1.hpp"
#include "experiments/figures/water_absorption_figure.hpp"

namespace rice::experiments {
namespace {

class FigureCommands : public CommandFamily {
 public:
  explicit FigureCommands(CLI::App& app) {
    CLI::App* figure = app.add_subcommand("figure", "regenerate a figure of the paper");
    figure->require_subcommand(1);
    add_grain_figures(figure);
    add_figure10(figure);
    add_figure11(figure);
    add_figure13(figure);
    CLI::App* table = app.add_subcommand("table", "regenerate a table of the paper");
    table->require_subcommand(1);
    add_table1(table);
  }

 private:
  void add_grain_figures(CLI::App* figure) {
    CLI::App* f8 = figure->add_subcommand("8", "japonica grains of different sizes (P from 1 to 1.5)");
    f8->add_option("--out", figure8_out_, "output folder")->capture_default_str();
    f8->add_option("--seed", seed_, "random seed")->check(seed_value())->capture_default_str();
    add(f8, nullptr, [this] { grain_sizes_figure_command(seed_, figure8_out_); });
    CLI::App* f9 = figure->add_subcommand("9", "indica, japonica, aromatic side by side; dimensions against the literature");
    f9->add_option("--out", figure9_out_, "output folder")->capture_default_str();
    f9->add_option("--seed", seed_, "random seed")->check(seed_value())->capture_default_str();
    f9->add_option("--count", figure9_count_, "grains per cultivar for the dimension statistics")
        ->check(number_in(2, 1000))->capture_default_str();
    add(f9, nullptr, [this] { cultivars_figure_command(seed_, figure9_count_, figure9_out_); });
  }

  void add_figure10(CLI::App* figure) {
    CLI::App* c = figure->add_subcommand("10", "a clump of grains dropped on a plate after three soak times");
    c->add_option("--out", figure10_out_, "output folder")->capture_default_str();
    c->add_option("--scene", figure10_.scene, "the drop scene")->capture_default_str();
    c->add_option("--soak-minutes", figure10_.soak_minutes, "soak times at the scene's temperature")
        ->check(number_in(0, 1e5, Ends::kOpenLow))->capture_default_str();
    c->add_option("--set", figure10_.overrides, "section.key=value for every run (repeatable)");
    add(c, [this] { experiments::validate(figure10_); }, [this] { figure10_command(figure10_, figure10_out_); });
  }

  void add_figure11(CLI::App* figure) {
    CLI::App* c = figure->add_subcommand("11", "water absorption vs soaking time and the damping law of eq. 4");
    c->add_option("--out", absorption_out_, "output folder")->capture_default_str();
    c->add_option("--table", absorption_.table,
                  "absorption CSV (temperature_c,soak_minutes,absorption_percent); default: shipped table")
        ->check(CLI::ExistingFile);
    add(c, [this] { experiments::validate(absorption_); },
        [this] { water_absorption_figure_command(absorption_, absorption_out_); });
  }

  void add_figure13(CLI::App* figure) {
    CLI::App* c = figure->add_subcommand("13", "japonica grains soaked at 5 °C for five times: the CDRF, the translucent model and the path tracer");
    Figure13Settings& s = figure13_;
    c->add_option("--out", figure13_out_, "output folder")->capture_default_str();
    c->add_option("--soak-minutes", s.soak_minutes, "soak times, one grain each")
        ->check(number_in(0, 1e4, Ends::kOpenLow))->capture_default_str();
    c->add_option("--temperature", s.temperature_c, "soaking water [°C]")->check(number_in(0, 100))
        ->capture_default_str();
    c->add_option("--width", s.width, "pixels")->check(number_in(16, 16384))->capture_default_str();
    c->add_option("--height", s.height, "pixels")->check(number_in(16, 16384))->capture_default_str();
    c->add_option("--spp", s.samples_per_pixel, "samples per pixel")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--translucent-bounces", s.translucent_bounces, "bounces of the translucent model's row")
        ->check(number_in(0, 16))->capture_default_str();
    c->add_option("--path-spp", s.path_spp, "samples per pixel of the path-traced row")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--seed", s.seed, "random seed (the grain and the samples)")->check(seed_value())
        ->capture_default_str();
    add(c, [this] { experiments::validate(figure13_); }, [this] { figure13_command(figure13_, figure13_out_); });
  }

  void add_table1(CLI::App* table) {
    CLI::App* c =
        table->add_subcommand("1", "shari, chawan, onigiri and bunny: simulation and render times beside the paper's");
    c->add_option("--out", table1_out_, "output folder")->capture_default_str();
    c->add_option("--scenes", table1_.scenes, "the folder of the scene files")->capture_default_str();
    c->add_flag("--full", table1_.full, "also render each last frame at 3840x2160, 800 spp (long)");
    c->add_option("--set", table1_.overrides, "section.key=value for every scene (repeatable)");
    add(c, nullptr, [this] { table1_command(table1_, table1_out_); });
  }

  std::uint64_t seed_ = 1;
  int figure9_count_ = 20;
  std::string figure8_out_ = "out/figure8", figure9_out_ = "out/figure9";
  Figure10Settings figure10_;
  std::string figure10_out_ = "out/figure10";
  WaterAbsorptionFigureSettings absorption_;
  std::string absorption_out_ = "out/figure11";
  Figure13Settings figure13_;
  std::string figure13_out_ = "out/figure13";
  Table1Settings table1_;
  std::string table1_out_ = "out/table1";
};

}  // namespace

std::unique_ptr<CommandFamily> add_figure_commands(CLI::App& app) { return std::make_unique<FigureCommands>(app); }

}  // namespace rice::experiments
