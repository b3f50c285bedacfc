// Reading and writing grain meshes. Surfaces: OBJ, OFF (also COFF, NOFF, STOFF and their
// combinations; not 4OFF, nOFF or binary OFF) and PLY (ASCII or binary little-endian) in;
// binary PLY out. Tetrahedral meshes: MEDIT .mesh (ASCII, Dimension 3), the format CGAL and
// most tet tools read. Polygons with more than three corners are split into
// triangle fans.
//
// Readers take a stream and the name to report (a file name); the path overloads open the
// file. Every reader treats its input as untrusted: whatever the bytes, it returns a mesh
// whose indices are in range and whose coordinates are finite, or throws std::runtime_error
// whose message starts with the name (and line, for text formats) and says what was wrong.
// Declared element counts are capped by the input's size, so garbage cannot make a reader
// allocate more than a small multiple of the file or loop without consuming it.
//
// Writers write to a stream; placing a file atomically is the caller's business (the
// experiments write through a temporary that is renamed into place).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>

#include "grains/mesh_types.hpp"

namespace rice::grains {

enum class SurfaceFormat { kObj, kOff, kPly };

/// Format from the file's extension (.obj, .off, .ply; any case); throws naming the file.
SurfaceFormat surface_format_of(const std::filesystem::path& path);

/// Reads a surface mesh in `format` from `in`, reporting errors as `name`.
SurfaceMesh read_surface_mesh(std::istream& in, SurfaceFormat format, const std::string& name);

/// Reads a surface mesh, choosing the format by extension.
SurfaceMesh read_surface_mesh(const std::filesystem::path& path);

/// One mesh holding all of `parts`, faces renumbered: many grains written as one file.
SurfaceMesh merged(const std::vector<SurfaceMesh>& parts);

/// Writes a binary little-endian PLY with double vertices and int triangle lists.
void write_ply(std::ostream& out, const SurfaceMesh& mesh);

/// Writes `mesh` as Wavefront OBJ (v and f lines, 1-based indices, 17 significant digits).
void write_obj(std::ostream& out, const SurfaceMesh& mesh);

/// Writes a MEDIT .mesh (vertices and tetrahedra, reference 0) that read_medit reads back
/// bit for bit.
void write_medit(std::ostream& out, const VolumeMesh& mesh);

/// Reads the vertices and tetrahedra of a MEDIT .mesh (other sections are skipped).
VolumeMesh read_medit(std::istream& in, const std::string& name);
VolumeMesh read_medit(const std::filesystem::path& path);

}  // namespace rice::grains
