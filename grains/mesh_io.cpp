// OBJ/OFF/PLY readers, PLY and MEDIT writers. Hand-written because no package in reach reads
// all three formats into plain matrices without pulling a mesh class along (CGAL's readers
// fill its own Surface_mesh); the formats are small.
#include "grains/mesh_io.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rice::grains {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int line = 0) {
  std::string where = path.string();
  if (line > 0) where += ":" + std::to_string(line);
  throw std::runtime_error(where + ": " + what);
}

// Growing lists, turned into matrices once the file is read.
struct MeshBuilder {
  std::vector<Vec3> vertices;
  std::vector<Eigen::Vector3i> triangles;

  void add_polygon(const std::vector<int>& corners) {
    for (size_t k = 1; k + 1 < corners.size(); ++k)
      triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
  }
  SurfaceMesh finish(const std::filesystem::path& path) const {
    SurfaceMesh mesh;
    mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    for (size_t i = 0; i < vertices.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = vertices[i];
    mesh.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
    for (size_t i = 0; i < triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k)
        if (triangles[i][k] < 0 || triangles[i][k] >= static_cast<int>(vertices.size()))
          fail(path, "face " + std::to_string(i) + " refers to vertex " + std::to_string(triangles[i][k]) +
                         ", but there are " + std::to_string(vertices.size()) + " vertices");
      mesh.F.row(static_cast<Eigen::Index>(i)) = triangles[i];
    }
    if (mesh.F.rows() == 0) fail(path, "no faces");
    return mesh;
  }
};

SurfaceMesh read_obj(const std::filesystem::path& path, std::istream& in) {
  MeshBuilder builder;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      Vec3 p;
      if (!(words >> p.x() >> p.y() >> p.z())) fail(path, "a vertex needs three numbers", number);
      builder.vertices.push_back(p);
    } else if (tag == "f") {
      std::vector<int> corners;
      std::string corner;
      while (words >> corner) {
        // "i", "i/t", "i/t/n" or "i//n"; negative indices count back from the last vertex.
        int index = 0;
        try {
          index = std::stoi(corner.substr(0, corner.find('/')));
        } catch (const std::exception&) {
          fail(path, "bad face corner '" + corner + "'", number);
        }
        corners.push_back(index > 0 ? index - 1 : static_cast<int>(builder.vertices.size()) + index);
      }
      if (corners.size() < 3) fail(path, "a face needs at least three corners", number);
      builder.add_polygon(corners);
    }
  }
  return builder.finish(path);
}

// Next non-empty, non-comment line of an OFF file, as a stream of words.
bool next_off_line(std::istream& in, std::istringstream& words, int& number) {
  std::string line;
  while (std::getline(in, line)) {
    ++number;
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    words = std::istringstream(line);
    return true;
  }
  return false;
}

SurfaceMesh read_off(const std::filesystem::path& path, std::istream& in) {
  int number = 0;
  std::istringstream words;
  std::string header;
  if (!next_off_line(in, words, number) || !(words >> header) || header.find("OFF") == std::string::npos)
    fail(path, "missing OFF header", number);
  long nv = 0, nf = 0;
  if (!(words >> nv >> nf) && !(next_off_line(in, words, number) && words >> nv >> nf))
    fail(path, "missing vertex and face counts", number);
  if (nv < 0 || nf < 0) fail(path, "negative counts", number);
  MeshBuilder builder;
  for (long i = 0; i < nv; ++i) {
    Vec3 p;
    if (!next_off_line(in, words, number) || !(words >> p.x() >> p.y() >> p.z()))
      fail(path, "vertex " + std::to_string(i) + " needs three numbers", number);
    builder.vertices.push_back(p);
  }
  for (long i = 0; i < nf; ++i) {
    int n = 0;
    if (!next_off_line(in, words, number) || !(words >> n) || n < 3)
      fail(path, "face " + std::to_string(i) + " needs a corner count >= 3", number);
    std::vector<int> corners(n);
    for (int& c : corners)
      if (!(words >> c)) fail(path, "face " + std::to_string(i) + " has too few corners", number);
    builder.add_polygon(corners);
  }
  return builder.finish(path);
}

// PLY: the vertex element's x, y, z and the face element's vertex index list are read;
// every other property is skipped.
struct PlyProperty {
  std::string name, type, count_type;  // count_type non-empty for list properties
};
struct PlyElement {
  std::string name;
  long count = 0;
  std::vector<PlyProperty> properties;
};

int ply_type_size(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},   {"uint8", 1},   {"short", 2},   {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4},    {"uint", 4},    {"int32", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

double read_binary_scalar(std::istream& in, const std::string& type) {
  unsigned char bytes[8] = {};
  in.read(reinterpret_cast<char*>(bytes), ply_type_size(type));
  const auto as = [&](auto value) {
    std::memcpy(&value, bytes, sizeof(value));
    return static_cast<double>(value);
  };
  if (type == "char" || type == "int8") return as(std::int8_t{});
  if (type == "uchar" || type == "uint8") return as(std::uint8_t{});
  if (type == "short" || type == "int16") return as(std::int16_t{});
  if (type == "ushort" || type == "uint16") return as(std::uint16_t{});
  if (type == "int" || type == "int32") return as(std::int32_t{});
  if (type == "uint" || type == "uint32") return as(std::uint32_t{});
  if (type == "float" || type == "float32") return as(float{});
  return as(double{});
}

SurfaceMesh read_ply(const std::filesystem::path& path, std::istream& in) {
  std::string line, format;
  std::vector<PlyElement> elements;
  int number = 0;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) fail(path, "missing 'ply' magic", 1);
  for (number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "format") {
      words >> format;
    } else if (tag == "element") {
      PlyElement element;
      words >> element.name >> element.count;
      elements.push_back(element);
    } else if (tag == "property") {
      if (elements.empty()) fail(path, "property before any element", number);
      PlyProperty property;
      words >> property.type;
      if (property.type == "list") words >> property.count_type >> property.type;
      words >> property.name;
      if (ply_type_size(property.type) == 0 ||
          (!property.count_type.empty() && ply_type_size(property.count_type) == 0))
        fail(path, "unknown property type in '" + line + "'", number);
      elements.back().properties.push_back(property);
    } else if (tag == "end_header") {
      break;
    }
  }
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian")
    fail(path, "PLY format '" + format + "' is not supported (ascii or binary_little_endian)");

  MeshBuilder builder;
  for (const PlyElement& element : elements) {
    for (long item = 0; item < element.count; ++item) {
      std::istringstream words;
      if (ascii) {
        if (!std::getline(in, line)) fail(path, "file ends inside element '" + element.name + "'");
        words = std::istringstream(line);
      }
      const auto scalar = [&](const std::string& type) {
        double value = 0.0;
        if (ascii ? !(words >> value) : !(value = read_binary_scalar(in, type), in))
          fail(path, "file ends inside element '" + element.name + "' " + std::to_string(item));
        return value;
      };
      Vec3 p = Vec3::Zero();
      std::vector<int> corners;
      for (const PlyProperty& property : element.properties) {
        if (!property.count_type.empty()) {
          const int n = static_cast<int>(scalar(property.count_type));
          std::vector<int> list(n);
          for (int& c : list) c = static_cast<int>(scalar(property.type));
          if (property.name == "vertex_indices" || property.name == "vertex_index") corners = list;
        } else {
          const double value = scalar(property.type);
          if (property.name == "x") p.x() = value;
          if (property.name == "y") p.y() = value;
          if (property.name == "z") p.z() = value;
        }
      }
      if (element.name == "vertex") builder.vertices.push_back(p);
      if (element.name == "face") {
        if (corners.size() < 3) fail(path, "face " + std::to_string(item) + " has fewer than three corners");
        builder.add_polygon(corners);
      }
    }
  }
  return builder.finish(path);
}

// Writes through a temporary sibling and renames it into place.
template <class WriteBody>
void write_atomically(const std::filesystem::path& path, std::ios::openmode mode, WriteBody body) {
  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    std::ofstream out(temporary, mode);
    if (!out) fail(path, "cannot open for writing");
    body(out);
    if (!out.flush()) fail(path, "write failed");
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace

SurfaceMesh read_surface_mesh(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  if (extension == ".obj") return read_obj(path, in);
  if (extension == ".off") return read_off(path, in);
  if (extension == ".ply") return read_ply(path, in);
  fail(path, "unknown mesh extension '" + extension + "' (expected .obj, .off or .ply)");
}

void write_ply(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  static_assert(std::endian::native == std::endian::little, "binary PLY output assumes a little-endian host");
  write_atomically(path, std::ios::binary, [&](std::ofstream& out) {
    out << "ply\nformat binary_little_endian 1.0\n"
        << "element vertex " << mesh.V.rows() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "element face " << mesh.F.rows() << "\n"
        << "property list uchar int vertex_indices\nend_header\n";
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
      for (int k = 0; k < 3; ++k) out.write(reinterpret_cast<const char*>(&mesh.V(v, k)), sizeof(double));
    const std::uint8_t three = 3;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      out.write(reinterpret_cast<const char*>(&three), 1);
      for (int k = 0; k < 3; ++k) out.write(reinterpret_cast<const char*>(&mesh.F(f, k)), sizeof(int));
    }
  });
}

void write_medit(const std::filesystem::path& path, const VolumeMesh& mesh) {
  write_atomically(path, std::ios::out, [&](std::ofstream& out) {
    out.precision(17);
    out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << mesh.V.rows() << "\n";
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
      out << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << " 0\n";
    out << "Tetrahedra\n" << mesh.T.rows() << "\n";
    for (Eigen::Index t = 0; t < mesh.T.rows(); ++t)  // MEDIT indices are 1-based
      out << mesh.T(t, 0) + 1 << ' ' << mesh.T(t, 1) + 1 << ' ' << mesh.T(t, 2) + 1 << ' ' << mesh.T(t, 3) + 1
          << " 0\n";
    out << "End\n";
  });
}

VolumeMesh read_medit(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) fail(path, "cannot open");
  VolumeMesh mesh;
  std::string word;
  while (in >> word) {
    if (word == "Vertices") {
      long n = 0;
      in >> n;
      mesh.V.resize(n, 3);
      int reference = 0;
      for (long v = 0; v < n; ++v) in >> mesh.V(v, 0) >> mesh.V(v, 1) >> mesh.V(v, 2) >> reference;
    } else if (word == "Tetrahedra") {
      long n = 0;
      in >> n;
      mesh.T.resize(n, 4);
      int reference = 0;
      for (long t = 0; t < n; ++t) {
        in >> mesh.T(t, 0) >> mesh.T(t, 1) >> mesh.T(t, 2) >> mesh.T(t, 3) >> reference;
        mesh.T.row(t).array() -= 1;
      }
    }
    if (!in) fail(path, "malformed section '" + word + "'");
  }
  return mesh;
}

}  // namespace rice::grains
