// A mesh's vertices split along its creases, for drawing: the renderer interpolates vertex
// normals (the mean of the faces' around a vertex), so a vertex shared by a flat top and a
// wall at right angles bent both faces' shading towards 45° (the rice cooker pot's 3 mm rim
// drew as a jagged, rounded band). Each vertex becomes one copy per group of its faces whose
// normals lie within `angle` of the group's first; smooth regions keep their shared vertices.
// Hand-written: nothing in reach (CGAL's PMP, OpenVDB) splits a soup's vertices by crease angle
// for drawing without rebuilding the mesh.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::experiments {

grains::SurfaceMesh split_creases(const grains::SurfaceMesh& mesh, double angle_degrees = 40.0);

}  // namespace rice::experiments
