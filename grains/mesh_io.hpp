// Reading and writing grain meshes. Surfaces: OBJ, OFF and PLY (ASCII or binary
// little-endian) in; binary PLY out. Tetrahedral meshes: MEDIT .mesh (ASCII), the format
// CGAL and most tet tools read. Polygons with more than three corners are split into
// triangle fans. Writes go to a temporary name first and are renamed into place, so a failed
// run leaves no half-written file.
#pragma once

#include <filesystem>

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Reads a surface mesh, choosing the format by extension (.obj, .off, .ply; any case).
/// Throws std::runtime_error naming the file (and line, for text formats) on bad input.
SurfaceMesh read_surface_mesh(const std::filesystem::path& path);

/// Writes a binary little-endian PLY with double vertices and int triangle lists.
void write_ply(const std::filesystem::path& path, const SurfaceMesh& mesh);

/// Writes a MEDIT .mesh file (vertices and tetrahedra, reference 0).
void write_medit(const std::filesystem::path& path, const VolumeMesh& mesh);

/// Reads a MEDIT .mesh file written by write_medit (vertices and tetrahedra only).
VolumeMesh read_medit(const std::filesystem::path& path);

}  // namespace rice::grains
