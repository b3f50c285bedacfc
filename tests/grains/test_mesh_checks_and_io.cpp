// Topology checks name the defect; readers and writers round-trip; bad files are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <unistd.h>

#include "grains/mesh_io.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

SurfaceMesh unit_tetrahedron() {
  SurfaceMesh mesh;
  mesh.V.resize(4, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  mesh.F.resize(4, 3);
  mesh.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return mesh;
}

// Two tetrahedra sharing only vertex 0: closed and edge-manifold, but pinched at vertex 0.
SurfaceMesh bowtie() {
  SurfaceMesh a = unit_tetrahedron();
  SurfaceMesh mesh;
  mesh.V.resize(7, 3);
  mesh.V.topRows(4) = a.V;
  mesh.V.bottomRows(3) = -a.V.bottomRows(3);
  mesh.F.resize(8, 3);
  mesh.F.topRows(4) = a.F;
  // The mirror image of the first tetrahedron through vertex 0; mirroring reverses the
  // winding, so its faces are flipped back to outward.
  Triangles mirrored = a.F;
  for (Eigen::Index f = 0; f < mirrored.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (mirrored(f, k) > 0) mirrored(f, k) += 3;
    std::swap(mirrored(f, 1), mirrored(f, 2));
  }
  mesh.F.bottomRows(4) = mirrored;
  return mesh;
}

std::filesystem::path temporary_folder() {
  const auto folder = std::filesystem::temp_directory_path() / ("rice-grains-io-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  return folder;
}

TEST(MeshTopology, TetrahedronIsClosedManifoldWithPositiveVolume) {
  const SurfaceMesh mesh = unit_tetrahedron();
  EXPECT_FALSE(closed_manifold_defect(mesh).has_value());
  EXPECT_NEAR(enclosed_volume(mesh), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(connected_component_count(mesh), 1);
}

TEST(MeshTopology, MissingFaceIsReportedAsAHoleWithItsEdge) {
  SurfaceMesh mesh = unit_tetrahedron();
  mesh.F.conservativeResize(3, 3);
  const auto defect = closed_manifold_defect(mesh);
  ASSERT_TRUE(defect.has_value());
  EXPECT_NE(defect->find("not closed"), std::string::npos) << *defect;
  EXPECT_NE(defect->find("edge ("), std::string::npos) << *defect;
}

TEST(MeshTopology, FlippedFaceIsReportedAsInconsistentOrientation) {
  SurfaceMesh mesh = unit_tetrahedron();
  std::swap(mesh.F(3, 1), mesh.F(3, 2));
  const auto defect = closed_manifold_defect(mesh);
  ASSERT_TRUE(defect.has_value());
  EXPECT_NE(defect->find("not consistently oriented"), std::string::npos) << *defect;
}

TEST(MeshTopology, EdgeWithThreeFacesIsNotManifold) {
  SurfaceMesh mesh = unit_tetrahedron();
  mesh.V.conservativeResize(5, 3);
  mesh.V.row(4) << 1, 1, 1;
  mesh.F.conservativeResize(5, 3);
  mesh.F.row(4) << 1, 2, 4;
  const auto defect = closed_manifold_defect(mesh);
  ASSERT_TRUE(defect.has_value());
  EXPECT_NE(defect->find("not manifold"), std::string::npos) << *defect;
}

TEST(MeshTopology, PinchedVertexIsNamed) {
  const SurfaceMesh mesh = bowtie();
  const auto defect = closed_manifold_defect(mesh);
  ASSERT_TRUE(defect.has_value());
  EXPECT_NE(defect->find("vertex 0 "), std::string::npos) << *defect;
  EXPECT_THROW(require_closed_manifold(mesh, "bowtie.obj"), std::invalid_argument);
}

TEST(MeshTopology, IndexOutOfRangeAndDegenerateFacesAreNamed) {
  SurfaceMesh mesh = unit_tetrahedron();
  mesh.F(2, 1) = 9;
  EXPECT_NE(closed_manifold_defect(mesh)->find("face 2 refers to vertex 9"), std::string::npos);
  mesh = unit_tetrahedron();
  mesh.F(1, 2) = mesh.F(1, 0);
  EXPECT_NE(closed_manifold_defect(mesh)->find("face 1 repeats a vertex"), std::string::npos);
}

TEST(MeshIo, ReadsObjOffAndAsciiPlyWithPolygons) {
  const auto folder = temporary_folder();
  // A unit cube as six quads, in three formats.
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  {
    std::ofstream obj(folder / "cube.obj");
    obj << "# cube\n";
    std::istringstream lines(vertices);
    for (std::string line; std::getline(lines, line);) obj << "v " << line << "\n";
    for (const auto& q : quads) obj << "f " << q[0] + 1 << "/1 " << q[1] + 1 << "//2 " << q[2] + 1 << " " << q[3] + 1 << "\n";
    std::ofstream off(folder / "cube.OFF");
    off << "OFF\n# comment\n8 6 0\n" << vertices;
    for (const auto& q : quads) off << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    std::ofstream ply(folder / "cube.ply");
    ply << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face 6\nproperty list uchar int vertex_indices\nend_header\n" << vertices;
    for (const auto& q : quads) ply << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
  }
  for (const char* name : {"cube.obj", "cube.OFF", "cube.ply"}) {
    const SurfaceMesh mesh = read_surface_mesh(folder / name);
    EXPECT_EQ(mesh.V.rows(), 8) << name;
    EXPECT_EQ(mesh.F.rows(), 12) << name;
    EXPECT_FALSE(closed_manifold_defect(mesh).has_value()) << name;
    EXPECT_NEAR(enclosed_volume(mesh), 1.0, 1e-12) << name;
  }
  std::filesystem::remove_all(folder);
}

TEST(MeshIo, BinaryPlyObjAndMeditRoundTripExactly) {
  SurfaceMesh surface = unit_tetrahedron();
  surface.V *= 1.2345678901234567e-3;
  std::stringstream ply;
  write_ply(ply, surface);
  const SurfaceMesh back = read_surface_mesh(ply, SurfaceFormat::kPly, "t.ply");
  EXPECT_EQ(back.V, surface.V);
  EXPECT_EQ(back.F, surface.F);
  std::stringstream obj;
  write_obj(obj, surface);
  const SurfaceMesh from_obj = read_surface_mesh(obj, SurfaceFormat::kObj, "t.obj");
  EXPECT_EQ(from_obj.V, surface.V);  // 17 digits read back exactly
  EXPECT_EQ(from_obj.F, surface.F);

  VolumeMesh volume{surface.V, Tets(1, 4)};
  volume.T << 0, 1, 2, 3;
  std::stringstream medit;
  write_medit(medit, volume);
  const VolumeMesh volume_back = read_medit(medit, "t.mesh");
  EXPECT_EQ(volume_back.V, volume.V);
  EXPECT_EQ(volume_back.T, volume.T);
}

TEST(MeshIo, BadFilesAreRefusedWithFileAndLine) {
  const auto folder = temporary_folder();
  std::ofstream(folder / "bad.obj") << "v 0 0 0\nv 1 0\n";
  std::ofstream(folder / "range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  std::ofstream(folder / "shape.stl") << "solid\n";
  const auto message = [&](const char* name) {
    try {
      read_surface_mesh(folder / name);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("bad.obj").find("bad.obj:2"), std::string::npos) << message("bad.obj");
  EXPECT_NE(message("range.obj").find("refers to vertex 6"), std::string::npos) << message("range.obj");
  EXPECT_NE(message("shape.stl").find("unknown mesh extension"), std::string::npos);
  EXPECT_NE(message("missing.ply").find("cannot open"), std::string::npos);
  std::filesystem::remove_all(folder);
}

// The error message a reader gives for `text`, or "no error".
template <class Read>
std::string read_error(const std::string& text, Read read) {
  std::istringstream in(text);
  try {
    read(in);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

std::string surface_error(const std::string& text, SurfaceFormat format) {
  return read_error(text, [&](std::istream& in) { read_surface_mesh(in, format, "in.mesh"); });
}

std::string medit_error(const std::string& text) {
  return read_error(text, [](std::istream& in) { read_medit(in, "in.mesh"); });
}

TEST(MeshIo, DeclaredCountsAreCappedByTheInputSize) {
  // Each of these once asked for gigabytes or looped without reading; now each is refused at
  // once, naming the input.
  const std::string huge_ply = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                               "property float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_NE(surface_error(huge_ply, SurfaceFormat::kPly).find("in.mesh: element 'vertex' count"), std::string::npos)
      << surface_error(huge_ply, SurfaceFormat::kPly);
  const std::string empty_element = "ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000\nend_header\n";
  EXPECT_NE(surface_error(empty_element, SurfaceFormat::kPly).find("cannot fit"), std::string::npos);
  const std::string long_list = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n";
  EXPECT_NE(surface_error(long_list, SurfaceFormat::kPly).find("list count"), std::string::npos)
      << surface_error(long_list, SurfaceFormat::kPly);
  EXPECT_NE(surface_error("OFF\n3 2000000000 0\n", SurfaceFormat::kOff).find("face count"), std::string::npos);
  EXPECT_NE(surface_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n", SurfaceFormat::kOff)
                .find("corner count"),
            std::string::npos);
  EXPECT_NE(medit_error("Vertices\n999999999999\n").find("vertex count"), std::string::npos);
  EXPECT_NE(medit_error("Vertices\n-4\n").find("negative"), std::string::npos);
}

TEST(MeshIo, NonFiniteCoordinatesAndOutOfRangeIndicesAreRefused) {
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                       "property float y\nproperty float z\nend_header\n";
  const float nan_vertex[3] = {0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f};
  binary.append(reinterpret_cast<const char*>(nan_vertex), sizeof nan_vertex);
  EXPECT_NE(surface_error(binary, SurfaceFormat::kPly).find("not finite"), std::string::npos);
  const std::string float_index = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 1\nproperty list uchar float vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n";
  EXPECT_NE(surface_error(float_index, SurfaceFormat::kPly).find("not a vertex index"), std::string::npos);
  EXPECT_NE(surface_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", SurfaceFormat::kObj).find("bad face corner"),
            std::string::npos);
  EXPECT_NE(surface_error("v 0 0 0\nf 1 -2 -3\n", SurfaceFormat::kObj).find("out of range"), std::string::npos);
  EXPECT_NE(surface_error("v 0 0 0\nf 1 2 99999999999\n", SurfaceFormat::kObj).find("out of range"),
            std::string::npos);
  const std::string tets = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 ";
  EXPECT_NE(medit_error(tets + "5 0\nEnd\n").find("tetrahedron 1 refers to vertex 5"), std::string::npos);
  EXPECT_NE(medit_error(tets + "0 0\nEnd\n").find("refers to vertex 0"), std::string::npos);
  EXPECT_NE(medit_error("Vertices\n1\n0 inf 0 0\n").find("vertex 1"), std::string::npos);
  EXPECT_NE(medit_error("Vertices\n1\n0 0 0 0\nEnd\n").find("Tetrahedra"), std::string::npos);
  EXPECT_NE(surface_error("ply\nformat binary_big_endian 1.0\nend_header\n", SurfaceFormat::kPly).find("not supported"),
            std::string::npos);
  EXPECT_NE(surface_error("ply\nformat ascii 1.0\nelement vertex 1\n", SurfaceFormat::kPly).find("end_header"),
            std::string::npos);
}

// A refusal's message: it starts with the input's name, then must contain `part`.
void expect_refusal(const std::string& message, const std::string& part) {
  EXPECT_TRUE(message.starts_with("in.mesh")) << message;
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(MeshIo, OnlyOffKeywordsReadInFullAreAccepted) {
  const std::string body = " 3 1 0\n0 0 0 0.5 0.5 0.5 1\n1 0 0 0.5 0.5 0.5 1\n0 1 0 0.5 0.5 0.5 1\n3 0 1 2\n";
  for (const char* keyword : {"OFF", "COFF", "NOFF", "CNOFF", "STCNOFF"}) {
    std::istringstream in(keyword + body);
    EXPECT_EQ(read_surface_mesh(in, SurfaceFormat::kOff, "in.mesh").V(1, 0), 1.0) << keyword;
  }
  // 4OFF's fourth coordinate would be dropped, nOFF's dimension read as a count.
  expect_refusal(surface_error("4OFF" + body, SurfaceFormat::kOff), ":1: '4OFF' is not a supported OFF header");
  expect_refusal(surface_error("nOFF\n3" + body, SurfaceFormat::kOff), "'nOFF' is not a supported OFF header");
  expect_refusal(surface_error("MOFF" + body, SurfaceFormat::kOff), "'MOFF' is not a supported OFF header");
  expect_refusal(surface_error("OFF BINARY\n", SurfaceFormat::kOff), "binary OFF is not supported");
}

TEST(MeshIo, MeditOfAnotherDimensionIsRefused) {
  const std::string tets = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
  EXPECT_EQ(read_error("MeshVersionFormatted 2\nDimension 3\n" + tets, [](std::istream& in) { read_medit(in, "in.mesh"); }),
            "no error");
  expect_refusal(medit_error("MeshVersionFormatted 2\nDimension 2\n" + tets), "Dimension '2' is not supported");
  expect_refusal(medit_error("MeshVersionFormatted 2\nDimension\n"), "Dimension '' is not supported");
}

TEST(MeshIo, AsciiPlyDataErrorsSayWhatIsWrongAndWhere) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_refusal(surface_error(header + "0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", SurfaceFormat::kPly),
                 "in.mesh:11: element 'vertex' 1 property 'y' 'abc' is not a number");
  expect_refusal(surface_error(header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n", SurfaceFormat::kPly),
                 "in.mesh:11: the line ends before element 'vertex' 1 property 'z'");
  expect_refusal(surface_error(header + "0 0 0\n1 0 0\n0 1 0\n3 0 x 2\n", SurfaceFormat::kPly),
                 "in.mesh:13: element 'face' 0 list 'vertex_indices' entry 1 'x' is not a number");
  expect_refusal(surface_error(header + "0 0 0\n1 0 1e999\n0 1 0\n3 0 1 2\n", SurfaceFormat::kPly),
                 "'1e999' is out of range");
  EXPECT_EQ(surface_error(header + "+0 0 0\n1 0 -0\n0 1.0 0\n3 0 1 2\n", SurfaceFormat::kPly), "no error");
}

// A binary PLY whose face declares `corners` int corners, with `corners_present` written.
std::string binary_triangle_ply(int corners, int corners_present) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n";
  const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(vertices), sizeof vertices);
  bytes.push_back(static_cast<char>(corners));
  for (int k = 0; k < corners_present; ++k) {
    const int corner = k % 3;
    bytes.append(reinterpret_cast<const char*>(&corner), sizeof corner);
  }
  return bytes;
}

TEST(MeshIo, BinaryPlyListsAreCappedByTheBytesLeftInTheFile) {
  const auto folder = temporary_folder();
  std::ofstream(folder / "good.ply", std::ios::binary) << binary_triangle_ply(3, 3);
  std::ofstream(folder / "long.ply", std::ios::binary) << binary_triangle_ply(255, 3);
  EXPECT_EQ(read_surface_mesh(folder / "good.ply").F.rows(), 1);
  try {
    read_surface_mesh(folder / "long.ply");
    ADD_FAILURE() << "a list longer than the file was read";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_TRUE(message.starts_with((folder / "long.ply").string())) << message;
    EXPECT_NE(message.find("list count 255 cannot fit in the 12 bytes left"), std::string::npos) << message;
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace rice::grains
