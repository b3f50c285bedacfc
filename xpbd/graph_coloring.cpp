// Greedy constraint colouring; see graph_coloring.hpp.
#include "xpbd/graph_coloring.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rice::xpbd {

Coloring greedy_coloring(std::span<const int> particles, int arity, int particle_count) {
  if (arity <= 0 || particles.size() % arity != 0)
    throw std::invalid_argument("greedy_coloring: particle list is not a multiple of the arity");
  const int count = static_cast<int>(particles.size()) / arity;
  std::vector<std::vector<int>> colors_of_particle(particle_count);
  std::vector<int> color_of(count);
  std::vector<int> taken_by;  // taken_by[color] == c: colour used by a neighbour of c
  for (int c = 0; c < count; ++c) {
    const auto stencil = particles.subspan(static_cast<size_t>(arity) * c, arity);
    for (const int p : stencil) {
      if (p < 0 || p >= particle_count)
        throw std::out_of_range("greedy_coloring: constraint " + std::to_string(c) +
                                " names particle " + std::to_string(p));
      for (const int color : colors_of_particle[p]) taken_by[color] = c;
    }
    int color = 0;
    while (color < static_cast<int>(taken_by.size()) && taken_by[color] == c) ++color;
    if (color == static_cast<int>(taken_by.size())) taken_by.push_back(-1);
    color_of[c] = color;
    for (const int p : stencil) colors_of_particle[p].push_back(color);
  }
  return group_by_color(color_of);
}

Coloring group_by_color(std::span<const int> color_of) {
  int colors = 0;
  for (const int c : color_of) colors = std::max(colors, c + 1);
  Coloring coloring;
  coloring.begin.assign(colors + 1, 0);
  for (const int c : color_of)
    if (c >= 0) ++coloring.begin[c + 1];
  for (int c = 0; c < colors; ++c) coloring.begin[c + 1] += coloring.begin[c];
  coloring.order.resize(coloring.begin.back());
  std::vector<int> next(coloring.begin.begin(), coloring.begin.end() - 1);
  for (int i = 0; i < static_cast<int>(color_of.size()); ++i)
    if (color_of[i] >= 0) coloring.order[next[color_of[i]]++] = i;
  return coloring;
}

}  // namespace rice::xpbd
