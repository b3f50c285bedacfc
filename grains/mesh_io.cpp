// OBJ/OFF/PLY readers, PLY and MEDIT writers, MEDIT reader. Hand-written because no package
// in reach reads all three formats into plain matrices without pulling a mesh class along
// (CGAL's readers fill its own Surface_mesh); the formats are small. Every reader is fuzzed
// (tests/fuzz/).
#include "grains/mesh_io.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
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

// True when `count` items of at least `min_item_bytes` each fit in `bytes`.
bool count_fits(long long count, long long bytes, long long min_item_bytes) {
  return count >= 0 && count <= bytes / std::max(min_item_bytes, 1LL);
}

// A declared count must be non-negative and fit in the bytes left at `min_item_bytes` an item.
void check_count(const std::string& name, const std::string& what, long long count, long long bytes,
                 long long min_item_bytes, long line = 0) {
  if (count < 0) fail(name, what + " count " + std::to_string(count) + " is negative", line);
  if (!count_fits(count, bytes, min_item_bytes))
    fail(name,
         what + " count " + std::to_string(count) + " cannot fit in the " + std::to_string(bytes) + " bytes left",
         line);
}

// A vertex index stored as a number of any type: integral, in [0, INT_MAX]. `where` names the
// face.
int index_value(double value, const std::string& name, const std::string& where) {
  if (!(value >= 0.0 && value <= INT_MAX) || value != std::floor(value))
    fail(name, where + " corner " + std::to_string(value) + " is not a vertex index");
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

// The OFF keywords this reader reads in full: [ST][C][N]OFF. Each vertex line starts with
// x y z; texture coordinates (ST), colours (C) and normals (N) follow and are skipped. 4OFF
// (a fourth, homogeneous coordinate) and nOFF (any dimension) would be misread, so are refused.
bool is_supported_off_keyword(std::string_view keyword) {
  for (const std::string_view prefix : {"ST", "C", "N"})
    if (keyword.starts_with(prefix)) keyword.remove_prefix(prefix.size());
  return keyword == "OFF";
}

SurfaceMesh read_off(std::istream& in, const std::string& name) {
  const long long size = bytes_left(in, name);
  long number = 0;
  std::string line, header;
  if (!next_off_line(in, line, number)) fail(name, "missing OFF header");
  std::istringstream words(line);
  if (!(words >> header)) fail(name, "missing OFF header", number);
  if (!is_supported_off_keyword(header))
    fail(name, "'" + header + "' is not a supported OFF header (OFF, optionally prefixed by ST, C, N)", number);
  if (line.find("BINARY") != std::string::npos) fail(name, "binary OFF is not supported", number);
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

// The PLY scalar types, resolved once from their names in the header: comparing names for
// every value read would dominate the reading of a large binary file.
enum class PlyScalar { kNone, kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

PlyScalar ply_scalar(const std::string& type) {
  static const std::map<std::string, PlyScalar> names = {
      {"char", PlyScalar::kInt8},     {"int8", PlyScalar::kInt8},       {"uchar", PlyScalar::kUint8},
      {"uint8", PlyScalar::kUint8},   {"short", PlyScalar::kInt16},     {"int16", PlyScalar::kInt16},
      {"ushort", PlyScalar::kUint16}, {"uint16", PlyScalar::kUint16},   {"int", PlyScalar::kInt32},
      {"int32", PlyScalar::kInt32},   {"uint", PlyScalar::kUint32},     {"uint32", PlyScalar::kUint32},
      {"float", PlyScalar::kFloat32}, {"float32", PlyScalar::kFloat32}, {"double", PlyScalar::kFloat64},
      {"float64", PlyScalar::kFloat64}};
  const auto it = names.find(type);
  return it == names.end() ? PlyScalar::kNone : it->second;
}

int ply_scalar_size(PlyScalar type) {
  switch (type) {
    case PlyScalar::kInt8: case PlyScalar::kUint8: return 1;
    case PlyScalar::kInt16: case PlyScalar::kUint16: return 2;
    case PlyScalar::kInt32: case PlyScalar::kUint32: case PlyScalar::kFloat32: return 4;
    case PlyScalar::kFloat64: return 8;
    case PlyScalar::kNone: break;
  }
  return 0;
}

// PLY: the vertex element's x, y, z and the face element's vertex index list are read;
// every other property is skipped.
struct PlyProperty {
  std::string name;
  PlyScalar type = PlyScalar::kNone;
  PlyScalar count_type = PlyScalar::kNone;  ///< a list's length type; kNone for a scalar property
  bool is_list() const { return count_type != PlyScalar::kNone; }
};
struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

double read_binary_scalar(std::istream& in, PlyScalar type) {
  unsigned char bytes[8] = {};
  in.read(reinterpret_cast<char*>(bytes), ply_scalar_size(type));
  const auto as = [&](auto value) {
    std::memcpy(&value, bytes, sizeof(value));
    return static_cast<double>(value);
  };
  switch (type) {
    case PlyScalar::kInt8: return as(std::int8_t{});
    case PlyScalar::kUint8: return as(std::uint8_t{});
    case PlyScalar::kInt16: return as(std::int16_t{});
    case PlyScalar::kUint16: return as(std::uint16_t{});
    case PlyScalar::kInt32: return as(std::int32_t{});
    case PlyScalar::kUint32: return as(std::uint32_t{});
    case PlyScalar::kFloat32: return as(float{});
    case PlyScalar::kFloat64: case PlyScalar::kNone: break;
  }
  return as(double{});
}

// The fewest bytes one item of `element` can take: ASCII needs a character and a separator
// per value, binary the scalar sizes (lists counted as empty).
long long min_item_bytes(const PlyElement& element, bool ascii) {
  long long bytes = 0;
  for (const PlyProperty& p : element.properties)
    bytes += ascii ? 2 : ply_scalar_size(p.is_list() ? p.count_type : p.type);
  return bytes;
}

struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  long lines = 0;  ///< lines up to and including end_header
};

PlyHeader read_ply_header(std::istream& in, const std::string& name) {
  std::string line;
  PlyHeader header;
  std::vector<PlyElement>& elements = header.elements;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) fail(name, "missing 'ply' magic", 1);
  for (long number = 2;; ++number) {
    if (!std::getline(in, line)) fail(name, "file ends before end_header", number);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "format") {
      words >> header.format;
    } else if (tag == "element") {
      PlyElement element;
      if (!(words >> element.name >> element.count)) fail(name, "an element needs a name and a count", number);
      elements.push_back(element);
    } else if (tag == "property") {
      if (elements.empty()) fail(name, "property before any element", number);
      std::string type, count_type;
      words >> type;
      if (type == "list") words >> count_type >> type;
      PlyProperty property;
      words >> property.name;
      property.type = ply_scalar(type);
      if (!count_type.empty()) property.count_type = ply_scalar(count_type);
      const bool float_count =
          property.count_type == PlyScalar::kFloat32 || property.count_type == PlyScalar::kFloat64;
      const bool known =
          property.type != PlyScalar::kNone && (count_type.empty() || (property.is_list() && !float_count));
      if (!known) fail(name, "unknown property type in '" + line + "' (list counts must be integers)", number);
      elements.back().properties.push_back(property);
    } else if (tag == "end_header") {
      header.lines = number;
      return header;
    }
  }
}

// Names a value of a PLY item in messages: a scalar property, a list's length (entry -1) or
// one of its entries.
std::string ply_value_name(const PlyProperty& property, long long entry) {
  if (!property.is_list()) return "property '" + property.name + "'";
  if (entry < 0) return "list '" + property.name + "' length";
  return "list '" + property.name + "' entry " + std::to_string(entry);
}

// The next word of an ASCII PLY line as a number, `word` its text; fails saying whether the
// line ended early or which word is not a number. `what()` names the value, and is called
// only on failure so that reading costs no message text.
template <class Describe>
double ascii_number(std::istream& words, std::string& word, const std::string& name, long line,
                    const Describe& what) {
  if (!(words >> word)) fail(name, "the line ends before " + what(), line);
  // from_chars takes no leading '+', which number streams (and PLY writers) may use.
  const char* begin = word.data() + (word.starts_with('+') && !word.starts_with("+-") ? 1 : 0);
  const char* end = word.data() + word.size();
  double value = 0.0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error == std::errc::result_out_of_range) fail(name, what() + " '" + word + "' is out of range", line);
  if (error != std::errc{} || stop != end) fail(name, what() + " '" + word + "' is not a number", line);
  return value;
}

SurfaceMesh read_ply(std::istream& in, const std::string& name) {
  const PlyHeader header = read_ply_header(in, name);
  const std::vector<PlyElement>& elements = header.elements;
  const bool ascii = header.format == "ascii";
  if (!ascii && header.format != "binary_little_endian")
    fail(name, "PLY format '" + header.format + "' is not supported (ascii or binary_little_endian)");
  // The input's size is told once: seeking for it per item would discard the stream's buffer
  // each time. Binary reads then count down what is left.
  long long left = bytes_left(in, name);
  long long unclaimed = left;
  for (const PlyElement& element : elements) {
    const long long item_bytes = min_item_bytes(element, ascii);
    check_count(name, "element '" + element.name + "'", element.count, unclaimed, item_bytes);
    unclaimed -= element.count * std::max(item_bytes, 1LL);
  }

  MeshBuilder builder(name);
  // Reused from item to item: allocating them anew for each would dominate large files.
  std::string line, word, where;
  std::vector<int> corners;
  long line_number = header.lines;
  for (const PlyElement& element : elements) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    const auto has_scalar = [&](const char* property) {
      return std::any_of(element.properties.begin(), element.properties.end(),
                         [&](const PlyProperty& p) { return p.name == property && !p.is_list(); });
    };
    if (is_vertex && !(has_scalar("x") && has_scalar("y") && has_scalar("z")))
      fail(name, "the vertex element needs scalar properties x, y and z");
    std::istringstream words;
    for (long long item = 0; item < element.count; ++item) {
      where.assign("element '").append(element.name).append("' ").append(std::to_string(item));
      if (ascii) {
        if (!std::getline(in, line)) fail(name, "file ends before " + where);
        ++line_number;
        words.clear();
        words.str(line);
      }
      // Property `property`'s value (entry -1 of a list: its length; k >= 0: its entry k).
      const auto scalar = [&](const PlyProperty& property, long long entry) {
        const PlyScalar type = entry < 0 && property.is_list() ? property.count_type : property.type;
        const auto what = [&] { return where + " " + ply_value_name(property, entry); };
        if (ascii) return ascii_number(words, word, name, line_number, what);
        const double value = read_binary_scalar(in, type);
        if (!in) fail(name, "file ends inside " + what());
        left -= ply_scalar_size(type);
        return value;
      };
      Vec3 p = Vec3::Zero();
      corners.clear();
      for (const PlyProperty& property : element.properties) {
        if (property.is_list()) {
          const long long n = list_length(scalar(property, -1), name, where);
          const long long bytes = ascii ? static_cast<long long>(line.size()) : left;
          const int entry_bytes = ascii ? 2 : ply_scalar_size(property.type);
          if (!count_fits(n, bytes, entry_bytes))  // checked first: the message costs an allocation
            check_count(name, where + " list", n, bytes, entry_bytes, ascii ? line_number : 0);
          const bool indices = is_face && (property.name == "vertex_indices" || property.name == "vertex_index");
          for (long long k = 0; k < n; ++k) {
            const double value = scalar(property, k);
            if (indices) corners.push_back(index_value(value, name, where));
          }
        } else {
          const double value = scalar(property, -1);
          if (property.name == "x") p.x() = value;
          if (property.name == "y") p.y() = value;
          if (property.name == "z") p.z() = value;
        }
      }
      if (is_vertex) builder.add_vertex(p, ascii ? line_number : 0);
      if (is_face) builder.add_polygon(corners, where, ascii ? line_number : 0);
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

SurfaceMesh merged(const std::vector<SurfaceMesh>& parts) {
  SurfaceMesh all;
  Eigen::Index vertices = 0, faces = 0;
  for (const SurfaceMesh& part : parts) vertices += part.V.rows(), faces += part.F.rows();
  all.V.resize(vertices, 3);
  all.F.resize(faces, 3);
  Eigen::Index v = 0, f = 0;
  for (const SurfaceMesh& part : parts) {
    all.V.middleRows(v, part.V.rows()) = part.V;
    all.F.middleRows(f, part.F.rows()) = part.F.array() + static_cast<int>(v);
    v += part.V.rows();
    f += part.F.rows();
  }
  return all;
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

void write_obj(std::ostream& out, const SurfaceMesh& mesh) {
  out.precision(17);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    out << "v " << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << '\n';
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    out << "f " << mesh.F(f, 0) + 1 << ' ' << mesh.F(f, 1) + 1 << ' ' << mesh.F(f, 2) + 1 << '\n';
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
    if (word == "Dimension") {
      std::string dimension;
      in >> dimension;
      if (dimension != "3") fail(name, "Dimension '" + dimension + "' is not supported (only 3: tetrahedra in space)");
    } else if (word == "Vertices") {
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
