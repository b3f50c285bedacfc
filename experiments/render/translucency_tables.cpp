// Reading and blending the translucent model's tables; see translucency_tables.hpp.
#include "experiments/render/translucency_tables.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "experiments/io/numeric_csv.hpp"
#include "experiments/render/scene_pieces.hpp"

#ifndef RICE_SHADING_DATA_DIR
#error "RICE_SHADING_DATA_DIR must name shading/data (set by experiments/CMakeLists.txt)"
#endif

namespace rice::experiments {

std::vector<TranslucencyAtWater> read_translucency_tables(const std::filesystem::path& path) {
  const NumericCsv csv = read_numeric_csv(path);
  const int w = csv.column("absorption_percent"), d = csv.column("d_mm"), c = csv.column("cos_theta"),
            tau = csv.column("tau");
  std::set<double> ds, cs;
  std::map<double, std::map<std::pair<double, double>, double>> nodes;  // W → (d, cos θ) → τ
  for (const auto& row : csv.rows) {
    ds.insert(row[d]);
    cs.insert(row[c]);
    nodes[row[w]][{row[d], row[c]}] = row[tau];
  }
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(path.string() + ": " + what);
  };
  if (nodes.empty()) fail("no rows");
  if (ds.size() < 2 || cs.size() < 2 || *ds.begin() != 0.0 || *cs.begin() != -1.0 || *cs.rbegin() != 1.0)
    fail("the nodes must span d from 0 and cos_theta over [-1, 1], two at least on each");
  for (const std::set<double>* axis : {&ds, &cs}) {
    const double step = (*axis->rbegin() - *axis->begin()) / static_cast<double>(axis->size() - 1);
    int k = 0;
    for (const double x : *axis)
      if (std::abs(x - (*axis->begin() + step * k++)) > 1e-9 * (1.0 + std::abs(x))) fail("the nodes are not evenly spaced");
  }
  std::vector<TranslucencyAtWater> out;
  for (const auto& [absorption, grid] : nodes) {
    if (grid.size() != ds.size() * cs.size())
      fail("water content " + std::to_string(absorption) + " has " + std::to_string(grid.size()) + " nodes, not " +
           std::to_string(ds.size() * cs.size()));
    std::vector<double> values;
    for (const double dk : ds)
      for (const double ck : cs) values.push_back(grid.at({dk, ck}));
    out.push_back({absorption, shading::TranslucencyTable(1e-3 * *ds.rbegin(), static_cast<int>(ds.size()),
                                                          static_cast<int>(cs.size()), std::move(values))});
  }
  return out;
}

const std::vector<TranslucencyAtWater>& shipped_translucency() {
  static const std::vector<TranslucencyAtWater> tables =
      read_translucency_tables(std::filesystem::path(RICE_SHADING_DATA_DIR) / "translucency.csv");
  return tables;
}

std::shared_ptr<const shading::TranslucencyTable> translucency_at(const std::vector<TranslucencyAtWater>& tables,
                                                                  double absorption_percent) {
  if (tables.empty()) throw std::invalid_argument("translucency_at: no tables");
  if (absorption_percent <= tables.front().absorption_percent)
    return std::make_shared<shading::TranslucencyTable>(tables.front().table);
  for (std::size_t k = 0; k + 1 < tables.size(); ++k) {
    const TranslucencyAtWater &a = tables[k], &b = tables[k + 1];
    if (absorption_percent <= b.absorption_percent) {
      const double t = (absorption_percent - a.absorption_percent) / (b.absorption_percent - a.absorption_percent);
      return std::make_shared<shading::TranslucencyTable>(shading::TranslucencyTable::blend(a.table, b.table, t));
    }
  }
  return std::make_shared<shading::TranslucencyTable>(tables.back().table);
}

shading::Material translucent_rice_material(double absorption_percent) {
  shading::Material m = rice_material(absorption_percent);
  m.translucency = translucency_at(shipped_translucency(), absorption_percent);
  return m;
}

}  // namespace rice::experiments
