// Paper Figure 11 and eq. 4: water absorption against soaking time for several water
// temperatures (data points and Peleg fits), and the damping law log(1/β) = a log(t) + b
// fitted to them. Writes CSVs and figure11.png.
#pragma once

#include <filesystem>

namespace rice::experiments {

struct WaterAbsorptionFigureSettings {
  std::filesystem::path table;  ///< absorption data; empty: the shipped table
};

/// Reads the table and fits the model; throws naming the file when either fails.
void validate(const WaterAbsorptionFigureSettings& settings);

/// Writes absorption_data.csv, absorption_curves.csv, peleg_fits.csv, damping_fits.csv,
/// figure11.png (two panels) and run_info.txt into `folder`.
void water_absorption_figure_command(const WaterAbsorptionFigureSettings& settings,
                                     const std::filesystem::path& folder);

}  // namespace rice::experiments
