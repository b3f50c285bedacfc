// Water-content fits: known parameters recovered from synthetic curves; the shipped table
// fits well and behaves physically; bad tables are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <unistd.h>

#include "grains/cultivar.hpp"
#include "grains/water_content.hpp"

namespace rice::grains {
namespace {

std::vector<AbsorptionSample> synthetic_peleg(double k1_5c, double k1_30c, double k2) {
  std::vector<AbsorptionSample> samples;
  for (const auto& [temperature, k1] : {std::pair{5.0, k1_5c}, std::pair{30.0, k1_30c}})
    for (double t : {5.0, 10.0, 20.0, 40.0, 80.0, 160.0}) samples.push_back({temperature, t, t / (k1 + k2 * t)});
  return samples;
}

TEST(WaterContent, PelegFitRecoversExactParameters) {
  const WaterContentModel model(synthetic_peleg(2.0, 0.5, 0.035));
  ASSERT_EQ(model.peleg_fits().size(), 2u);
  EXPECT_NEAR(model.peleg_fits()[0].k1, 2.0, 1e-8);
  EXPECT_NEAR(model.peleg_fits()[1].k1, 0.5, 1e-8);
  EXPECT_NEAR(model.peleg_fits()[0].k2, 0.035, 1e-10);
  EXPECT_LT(model.peleg_fits()[0].rms_residual, 1e-8);
  // Two temperatures: the Arrhenius and k2 lines pass through both fits exactly.
  EXPECT_NEAR(model.absorption_percent(40.0, 5.0), 40.0 / (2.0 + 0.035 * 40.0), 1e-8);
  EXPECT_NEAR(model.absorption_percent(40.0, 30.0), 40.0 / (0.5 + 0.035 * 40.0), 1e-8);
}

// Absorption growing as a power of time, W = c t^p, gives eq. 4 with a = p exactly, and β
// at the reference soak equals β_ref.
TEST(WaterContent, DampingLawRecoversAPowerLaw) {
  std::vector<AbsorptionSample> samples;
  for (double temperature : {10.0, 20.0})
    for (double t : {5.0, 15.0, 45.0, 120.0}) samples.push_back({temperature, t, 3.0 * std::pow(t, 0.4)});
  const DampingReference reference{10.0, 120.0, 3e-3};
  const WaterContentModel model(samples, reference);
  for (const DampingFit& fit : model.damping_fits()) {
    EXPECT_NEAR(fit.a, 0.4, 1e-10);
    EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
  }
  EXPECT_NEAR(model.beta(120.0, 10.0), 3e-3, 1e-15);
}

TEST(WaterContent, ShippedTableFitsAndBehavesPhysically) {
  const WaterContentModel model(read_absorption_table(default_absorption_table()));
  ASSERT_EQ(model.peleg_fits().size(), 4u);
  for (size_t i = 0; i < model.peleg_fits().size(); ++i) {
    const PelegFit& fit = model.peleg_fits()[i];
    EXPECT_LT(fit.rms_residual, 1.0) << fit.temperature_c;  // within 1 % absorption
    if (i > 0) {
      EXPECT_LT(fit.k1, model.peleg_fits()[i - 1].k1);  // warmer water: faster uptake
    }
    EXPECT_GT(1.0 / fit.k2, 25.0);  // saturation between 25 and 40 % of the dry weight
    EXPECT_LT(1.0 / fit.k2, 40.0);
  }
  EXPECT_LT(model.arrhenius_c1(), 0.0);  // positive activation energy
  for (const DampingFit& fit : model.damping_fits()) {
    EXPECT_GT(fit.a, 0.0);
    EXPECT_LT(fit.a, 1.0);
    EXPECT_GT(fit.r_squared, 0.8);  // a power law bends away from a saturating curve
  }
  // Longer soaks: more water, smaller β; σ0 grows with water.
  EXPECT_LT(model.beta(120.0, 10.0), model.beta(30.0, 10.0));
  EXPECT_GT(WaterContentModel::scattering_sigma0(25.0), WaterContentModel::scattering_sigma0(10.0));
}

TEST(WaterContent, CohesionIsTheStickinessAtTheReferenceSoakAndGrowsWithWater) {
  const DampingReference reference;
  const WaterContentModel model(read_absorption_table(default_absorption_table()), reference);
  const double sticky = cultivar_by_name("japonica").stickiness, plain = cultivar_by_name("indica").stickiness;
  EXPECT_NEAR(model.cohesion_ratio(sticky, reference.soak_minutes, reference.temperature_c), 15.0, 1e-9);
  EXPECT_NEAR(model.cohesion_ratio(plain, reference.soak_minutes, reference.temperature_c), 3.0, 1e-9);
  EXPECT_EQ(cultivar_by_name("glutinous").stickiness, sticky);
  EXPECT_EQ(cultivar_by_name("aromatic").stickiness, plain);
  EXPECT_LT(model.cohesion_ratio(sticky, 30.0, 10.0), model.cohesion_ratio(sticky, 120.0, 10.0));
  EXPECT_LT(model.cohesion_ratio(sticky, 120.0, 10.0), model.cohesion_ratio(sticky, 240.0, 25.0));
}

TEST(WaterContent, BadTablesAreRefusedWithFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / ("rice-absorption-" + std::to_string(::getpid()) + ".csv");
  const auto message = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      WaterContentModel model(read_absorption_table(path));
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("time,water\n").find(":1: expected header"), std::string::npos);
  EXPECT_NE(message("# c\ntemperature_c,soak_minutes,absorption_percent\n5,10\n").find(":3: expected three"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n5,-1,3\n").find("must be positive"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n5,1,3\n5,2,4\n5,3,5\n").find("two or more"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n-5,1,3\n").find("temperature_c -5 must be in"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n5,1,3,7\n").find(":2: expected three"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n5,1,nan\n").find("must be positive"),
            std::string::npos);
  EXPECT_NE(message("temperature_c,soak_minutes,absorption_percent\n5,1,3x\n").find("'3x' is not a number"),
            std::string::npos);
  std::filesystem::remove(path);
  EXPECT_NE(message("").find("no data rows"), std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rice::grains
