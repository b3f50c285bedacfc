// OBJ/OFF/PLY readers, PLY and MEDIT writers, MEDIT reader. Hand-written because no package
// in reach reads all three formats into plain matrices without pulling a mesh class along
// (CGAL's readers fill its own Surface_mesh); the formats are small. Every reader is fuzzed
// (tests/fuzz/).
#include "grains/mesh_io.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rice::grains {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what, long line = 0) {
  std::string where = name;
  if (line > 0) where += ":" + std::to_string(line);
  throw std::runtime_error(where + ": " + what);
}

// Bytes from the stream's position to its end; the position is kept. A stream at its end
// (a header line that ran to the end of the file) has none left; one whose size cannot be
// told (a pipe) is refused, as its declared counts could not be capped.
long long bytes_left(std::istream& in, const std::string& name) {
  if (in.eof()) return 0;
  const std::streampos here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  if (here < 0 || end < 0 || !in) fail(name, "cannot tell the size of the input (not a file?)");
  return static_cast<long long>(end - here);
}

// A declared count must be non-negative and fit in the bytes left at `min_item_bytes` an item.
void check_count(const std::string& name, const std::string& what, long long count, long long bytes,
                 long long min_item_bytes, long line = 0) {
  if (count < 0) fail(name, what + " count " + std::to_string(count) + " is negative", line);
  if (count > bytes / std::max(min_item_bytes, 1LL))
    fail(name,
         what + " count " + std::to_string(count) + " cannot fit in the " + std::to_string(bytes) + " bytes left",
         line);
}

// A vertex index stored as a number of any type: integral, in [0, INT_MAX].
int index_value(double value, const std::string& name, const std::string& what) {
  if (!(value >= 0.0 && value <= INT_MAX) || value != std::floor(value))
    fail(name, what + " " + std::to_string(value) + " is not a vertex index");
  return static_cast<int>(value);
}

// A PLY list length read as a number (ASCII lists may write any number): a whole number
// small enough to convert; check_count then caps it by the bytes left.
long long list_length(double value, const std::string& name, const std::string& where) {
  if (!(value >= 0.0 && value <= 1e15) || value != std::floor(value))
    fail(name, where + " has a list length " + std::to_string(value) + " that is not a count");
  return static_cast<long long>(value);
}

// Growing lists, turned into matrices once the file is read.
class MeshBuilder {
 public:
  explicit MeshBuilder(const std::string& name) : name_(name) {}

  long vertex_count() const { return static_cast<long>(vertices_.size()); }

  void add_vertex(const Vec3& p, long line = 0) {
    if (!p.allFinite()) fail(name_, "vertex " + std::to_string(vertices_.size()) + " is not finite", line);
    vertices_.push_back(p);
  }
  void add_polygon(const std::vector<int>& corners, const std::string& face, long line = 0) {
    if (corners.size() < 3) fail(name_, face + " has fewer than three corners", line);
    for (size_t k = 1; k + 1 < corners.size(); ++k) triangles_.emplace_back(corners[0], corners[k], corners[k + 1]);
  }

  SurfaceMesh finish() const {
    if (vertices_.size() > static_cast<size_t>(INT_MAX)) fail(name_, "more vertices than an int can index");
    SurfaceMesh mesh;
    mesh.V.resize(static_cast<Eigen::Index>(vertices_.size()), 3);
    for (size_t i = 0; i < vertices_.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = vertices_[i];
    mesh.F.resize(static_cast<Eigen::Index>(triangles_.size()), 3);
    for (size_t i = 0; i < triangles_.size(); ++i) {
      for (int k = 0; k < 3; ++k)
        if (triangles_[i][k] < 0 || triangles_[i][k] >= static_cast<int>(vertices_.size()))
          fail(name_, "face " + std::to_string(i) + " refers to vertex " + std::to_string(triangles_[i][k]) +
                          ", but there are " + std::to_string(vertices_.size()) + " vertices");
      mesh.F.row(static_cast<Eigen::Index>(i)) = triangles_[i];
    }
    if (mesh.F.rows() == 0) fail(name_, "no faces");
    return mesh;
  }

 private:
  const std::string& name_;
  std::vector<Vec3> vertices_;
  std::vector<Eigen::Vector3i> triangles_;
};

// One OBJ face corner "i", "i/t", "i/t/n" or "i//n" as a 0-based index; negative indices
// count back from the last vertex read so far.
int obj_corner(const std::string& corner, long vertices, const std::string& name, long line) {
  const std::string text = corner.substr(0, corner.find('/'));
  long long index = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (error != std::errc{} || end != text.data() + text.size() || index == 0)
    fail(name, "bad face corner '" + corner + "' (OBJ indices start at 1, or count back from -1)", line);
  const long long zero_based = index > 0 ? index - 1 : vertices + index;
  if (zero_based < 0 || zero_based > INT_MAX) fail(name, "face corner '" + corner + "' is out of range", line);
  return static_cast<int>(zero_based);
}

SurfaceMesh read_obj(std::istream& in, const std::string& name) {
  MeshBuilder builder(name);
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      Vec3 p;
      if (!(words >> p.x() >> p.y() >> p.z())) fail(name, "a vertex needs three numbers", number);
      builder.add_vertex(p, number);
    } else if (tag == "f") {
      std::vector<int> corners;
      for (std::string corner; words >> corner;) corners.push_back(obj_corner(corner, builder.vertex_count(), name, number));
      builder.add_polygon(corners, "a face", number);
    }
  }
  return builder.finish();
}

// Next non-empty, non-comment line of an OFF file.
bool next_off_line(std::istream& in, std::string& line, long& number) {
  while (std::getline(in, line)) {
    ++number;
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
  }
  return false;
}

SurfaceMesh read_off(std::istream& in, const std::string& name) {
  const long long size = bytes_left(in, name);
  long number = 0;
  std::string line, header;
  if (!next_off_line(in, line, number)) fail(name, "missing OFF header");
  std::istringstream words(line);
  if (!(words >> header) || header.find("OFF") == std::string::npos) fail(name, "missing OFF header", number);
  long long nv = 0, nf = 0;
  if (!(words >> nv >> nf)) {  // the counts may stand on the next line
    if (!next_off_line(in, line, number)) fail(name, "missing vertex and face counts", number);
    words = std::istringstream(line);
    if (!(words >> nv >> nf)) fail(name, "missing vertex and face counts", number);
  }
  check_count(name, "vertex", nv, size, 6, number);  // "0 0 0\n"
  check_count(name, "face", nf, size, 8, number);    // "3 0 1 2\n"
  MeshBuilder builder(name);
  for (long long i = 0; i < nv; ++i) {
    Vec3 p;
    if (!next_off_line(in, line, number)) fail(name, "file ends before vertex " + std::to_string(i));
    words = std::istringstream(line);
    if (!(words >> p.x() >> p.y() >> p.z())) fail(name, "vertex " + std::to_string(i) + " needs three numbers", number);
    builder.add_vertex(p, number);
  }
  for (long long i = 0; i < nf; ++i) {
    const std::string face = "face " + std::to_string(i);
    if (!next_off_line(in, line, number)) fail(name, "file ends before " + face);
    words = std::istringstream(line);
    long long n = 0;
    if (!(words >> n)) fail(name, face + " needs a corner count", number);
    check_count(name, face + " corner", n, static_cast<long long>(line.size()), 2, number);
    std::vector<int> corners(static_cast<size_t>(n));
    for (int& c : corners)
      if (!(words >> c)) fail(name, face + " has fewer corners than it declares", number);
    builder.add_polygon(corners, face, number);
  }
  return builder.finish();
}

// PLY: the vertex element's x, y, z and the face element's vertex index list are read;
// every other property is skipped.
struct PlyProperty {
  std::string name, type, count_type;  // count_type non-empty for list properties
};
struct PlyElement {
  std::string name;
  long long count = 0;
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

bool ply_type_is_integral(const std::string& type) {
  return ply_type_size(type) > 0 && type.find("float") == std::string::npos && type != "double";
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

// The fewest bytes one item of `element` can take: ASCII needs a character and a separator
// per value, binary the scalar sizes (lists counted as empty).
long long min_item_bytes(const PlyElement& element, bool ascii) {
  long long bytes = 0;
  for (const PlyProperty& p : element.properties)
    bytes += ascii ? 2 : ply_type_size(p.count_type.empty() ? p.type : p.count_type);
  return bytes;
}

std::vector<PlyElement> read_ply_header(std::istream& in, const std::string& name, std::string& format) {
  std::string line;
  std::vector<PlyElement> elements;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) fail(name, "missing 'ply' magic", 1);
  for (long number = 2;; ++number) {
    if (!std::getline(in, line)) fail(name, "file ends before end_header", number);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "format") {
      words >> format;
    } else if (tag == "element") {
      PlyElement element;
      if (!(words >> element.name >> element.count)) fail(name, "an element needs a name and a count", number);
      elements.push_back(element);
    } else if (tag == "property") {
      if (elements.empty()) fail(name, "property before any element", number);
      PlyProperty property;
      words >> property.type;
      if (property.type == "list") words >> property.count_type >> property.type;
      words >> property.name;
      const bool known = ply_type_size(property.type) > 0 &&
                         (property.count_type.empty() || ply_type_is_integral(property.count_type));
      if (!known) fail(name, "unknown property type in '" + line + "' (list counts must be integers)", number);
      elements.back().properties.push_back(property);
    } else if (tag == "end_header") {
      return elements;
    }
  }
}

SurfaceMesh read_ply(std::istream& in, const std::string& name) {
  std::string format;
  const std::vector<PlyElement> elements = read_ply_header(in, name, format);
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian")
    fail(name, "PLY format '" + format + "' is not supported (ascii or binary_little_endian)");
  long long size = bytes_left(in, name);
  for (const PlyElement& element : elements) {
    const long long item_bytes = min_item_bytes(element, ascii);
    check_count(name, "element '" + element.name + "'", element.count, size, item_bytes);
    size -= element.count * std::max(item_bytes, 1LL);
  }

  MeshBuilder builder(name);
  std::string line;
  for (const PlyElement& element : elements) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    const auto has_scalar = [&](const char* property) {
      return std::any_of(element.properties.begin(), element.properties.end(),
                         [&](const PlyProperty& p) { return p.name == property && p.count_type.empty(); });
    };
    if (is_vertex && !(has_scalar("x") && has_scalar("y") && has_scalar("z")))
      fail(name, "the vertex element needs scalar properties x, y and z");
    std::istringstream words;
    for (long long item = 0; item < element.count; ++item) {
      const std::string where = "element '" + element.name + "' " + std::to_string(item);
      if (ascii) {
        if (!std::getline(in, line)) fail(name, "file ends before " + where);
        words.clear();
        words.str(line);
      }
      const auto scalar = [&](const std::string& type) {
        double value = 0.0;
        if (ascii ? !(words >> value) : !(value = read_binary_scalar(in, type), in))
          fail(name, "file ends inside " + where);
        return value;
      };
      Vec3 p = Vec3::Zero();
      std::vector<int> corners;
      for (const PlyProperty& property : element.properties) {
        if (!property.count_type.empty()) {
          const long long n = list_length(scalar(property.count_type), name, where);
          check_count(name, where + " list", n, ascii ? static_cast<long long>(line.size()) : bytes_left(in, name),
                      ascii ? 2 : ply_type_size(property.type));
          const bool indices = is_face && (property.name == "vertex_indices" || property.name == "vertex_index");
          for (long long k = 0; k < n; ++k) {
            const double value = scalar(property.type);
            if (indices) corners.push_back(index_value(value, name, where + " corner"));
          }
        } else {
          const double value = scalar(property.type);
          if (property.name == "x") p.x() = value;
          if (property.name == "y") p.y() = value;
          if (property.name == "z") p.z() = value;
        }
      }
      if (is_vertex) builder.add_vertex(p);
      if (is_face) builder.add_polygon(corners, where);
    }
  }
  return builder.finish();
}

}  // namespace

SurfaceFormat surface_format_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return SurfaceFormat::kObj;
  if (extension == ".off") return SurfaceFormat::kOff;
  if (extension == ".ply") return SurfaceFormat::kPly;
  fail(path.string(), "unknown mesh extension '" + extension + "' (expected .obj, .off or .ply)");
}

SurfaceMesh read_surface_mesh(std::istream& in, SurfaceFormat format, const std::string& name) {
  switch (format) {
    case SurfaceFormat::kObj: return read_obj(in, name);
    case SurfaceFormat::kOff: return read_off(in, name);
    case SurfaceFormat::kPly: return read_ply(in, name);
  }
  fail(name, "unknown surface format");
}

SurfaceMesh read_surface_mesh(const std::filesystem::path& path) {
  const SurfaceFormat format = surface_format_of(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path.string(), "cannot open");
  return read_surface_mesh(in, format, path.string());
}

void write_ply(std::ostream& out, const SurfaceMesh& mesh) {
  static_assert(std::endian::native == std::endian::little, "binary PLY output assumes a little-endian host");
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
}

void write_medit(std::ostream& out, const VolumeMesh& mesh) {
  const auto precision = out.precision(17);  // shortest that reads back every double exactly
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << mesh.V.rows() << "\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    out << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << " 0\n";
  out << "Tetrahedra\n" << mesh.T.rows() << "\n";
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t)  // MEDIT indices are 1-based
    out << mesh.T(t, 0) + 1 << ' ' << mesh.T(t, 1) + 1 << ' ' << mesh.T(t, 2) + 1 << ' ' << mesh.T(t, 3) + 1
        << " 0\n";
  out << "End\n";
  out.precision(precision);
}

VolumeMesh read_medit(std::istream& in, const std::string& name) {
  const long long size = bytes_left(in, name);
  VolumeMesh mesh;
  bool have_vertices = false, have_tets = false;
  for (std::string word; in >> word && word != "End";) {
    if (word == "Vertices") {
      long long n = 0;
      if (have_vertices || !(in >> n)) fail(name, "a second Vertices section, or one without a count");
      check_count(name, "vertex", n, size, 8);  // "0 0 0 0\n"
      mesh.V.resize(static_cast<Eigen::Index>(n), 3);
      for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
        int reference = 0;
        if (!(in >> mesh.V(v, 0) >> mesh.V(v, 1) >> mesh.V(v, 2) >> reference))
          fail(name, "vertex " + std::to_string(v + 1) + ": expected three coordinates and a reference");
        if (!mesh.V.row(v).allFinite()) fail(name, "vertex " + std::to_string(v + 1) + " is not finite");
      }
      have_vertices = true;
    } else if (word == "Tetrahedra") {
      long long n = 0;
      if (have_tets || !(in >> n)) fail(name, "a second Tetrahedra section, or one without a count");
      check_count(name, "tetrahedron", n, size, 10);  // "1 1 1 1 0\n"
      mesh.T.resize(static_cast<Eigen::Index>(n), 4);
      for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
        int reference = 0;
        if (!(in >> mesh.T(t, 0) >> mesh.T(t, 1) >> mesh.T(t, 2) >> mesh.T(t, 3) >> reference))
          fail(name, "tetrahedron " + std::to_string(t + 1) + ": expected four vertex indices and a reference");
      }
      have_tets = true;
    }
  }
  if (!have_vertices || !have_tets || mesh.T.rows() == 0) fail(name, "needs a Vertices and a non-empty Tetrahedra section");
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t)
    for (int k = 0; k < 4; ++k) {
      if (mesh.T(t, k) < 1 || mesh.T(t, k) > mesh.V.rows())
        fail(name, "tetrahedron " + std::to_string(t + 1) + " refers to vertex " + std::to_string(mesh.T(t, k)) +
                       ", but there are " + std::to_string(mesh.V.rows()) + " vertices (1-based)");
      --mesh.T(t, k);
    }
  return mesh;
}

VolumeMesh read_medit(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) fail(path.string(), "cannot open");
  return read_medit(in, path.string());
}

}  // namespace rice::grains
