// Greedy graph colouring of constraints: two constraints that share a particle never get the
// same colour, so all constraints of one colour can be projected in parallel and the result
// does not depend on the thread count (parallel Gauss–Seidel, Fratarcangeli et al. 2016).
#pragma once

#include <span>
#include <vector>

namespace rice::xpbd {

/// Constraint indices grouped by colour: colour c holds order[begin[c] .. begin[c+1]).
struct Coloring {
  std::vector<int> order;
  std::vector<int> begin{0};
  int colors() const { return static_cast<int>(begin.size()) - 1; }
  std::span<const int> color(int c) const {
    return {order.data() + begin[c], static_cast<size_t>(begin[c + 1] - begin[c])};
  }
};

/// Colours `count` constraints of `arity` particles each; constraint c touches
/// particles[arity·c .. arity·c + arity). Deterministic: constraints are visited in index
/// order and each takes the smallest colour none of its particles has yet.
Coloring greedy_coloring(std::span<const int> particles, int arity, int particle_count);

/// Groups items by colour: item i goes to colour color_of[i], in index order within it; an
/// item of colour −1 is left out.
Coloring group_by_color(std::span<const int> color_of);

}  // namespace rice::xpbd
