// A small template cage as a grain's simulation mesh (paper §4.3 embeds its high-resolution
// mesh in a coarse one; this is the coarsest such mesh that still bends and twists). The cage
// is a spindle along the grain's length axis x: at `stations` planes x = x_j it has a diamond
// of four vertices (x_j, ±k_j a, 0), (x_j, 0, ±k_j b), and a tip vertex (x_±, 0, 0) beyond
// each end. Between two diamonds lies a hexahedron cut into six tets around its diagonal,
// between the end diamonds and the tips a pyramid cut into two, so the cage has 4 n + 2
// vertices and 6 (n − 1) + 4 tets. Its cross-section at x is the diamond
//   |y| / a + |z| / b ≤ k(x),
// with k piecewise linear between the stations and 0 at the tips; a and b fix the diamond's
// shape (the points' largest |y| and |z| times √2, so a diamond of k = 1 holds an ellipse of
// those semi-axes). The k_j are raised until every point lies inside (fit_profile), so the cage
// encloses the grain, and the grain's embedding in it has no negative weight.
//
// Why by hand: Mesh_3 lands in a range of 8–12 vertices for two grains in eight
// (`rice study grain-substeps`), and XPBD's stable step is set by the elements' size: a
// template cage gives every grain the same few large elements. Measured, it does not buy the
// larger step (docs/studies.md, grain-substeps), so it is a study option, not the scenes' mesh.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

struct TemplateCageParameters {
  int stations = 2;      ///< diamonds along the length (≥ 1): 4·stations + 2 vertices
  /// Each tip lies beyond the furthest point by this fraction of that point's distance from the
  /// end station: further out, the end diamonds are smaller and the tips' tets longer.
  double tip_extension = 0.5;
  double margin = 0.02;  ///< each k_j beyond what the points need, a fraction
};

/// Throws std::invalid_argument naming the parameter and its range.
void validate(const TemplateCageParameters& parameters);

/// A cage of positively oriented tets enclosing the points `V`, given in the grain frame
/// (length along x, centred on the x axis; base_shape.hpp).
VolumeMesh make_template_cage(const Vertices& V, const TemplateCageParameters& parameters = {});

}  // namespace rice::grains
