// SPDX-License-Identifier: Apache-2.0
// Surface meshes (issue #17): reading and checking OBJ and PLY, the face-colour PLY output
// (read back by OpenMesh, as a viewer would), closest points against sampled surfaces, and
// the isotropic remesher's quality, fidelity, topology and determinism.
#include "surface/surface_mesh_pvt.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sys/stat.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <gtest/gtest.h>

#include "surface/mesh_detail_pvt.h"

namespace fs = std::filesystem;
using namespace texsyn::detail;

namespace {

std::string mesh_path(const std::string& name)
{
    return std::string(TEXSYN_SOURCE_DIR) + "/data/meshes/" + name;
}

SurfaceMesh bundled(const std::string& name)
{
    SurfaceMesh mesh;
    std::string error;
    EXPECT_TRUE(read_surface_mesh(mesh_path(name), mesh, error)) << error;
    return mesh;
}

class SurfaceMeshTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir = fs::temp_directory_path()
            / (std::string("texsyn_surface_")
                + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string write(const std::string& name, const std::string& bytes) const
    {
        const std::string path = (dir / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    // The error reading `bytes` as file `name` gives, after "PATH: " (which it must start
    // with); the read must fail on one line, print nothing and leave the mesh empty.
    std::string read_error(const std::string& name, const std::string& bytes) const
    {
        const std::string path = write(name, bytes);
        SurfaceMesh mesh;
        mesh.vertices.resize(1);
        std::string error;
        ::testing::internal::CaptureStderr();
        ::testing::internal::CaptureStdout();
        const bool read = read_surface_mesh(path, mesh, error);
        const std::string printed
            = ::testing::internal::GetCapturedStderr() + ::testing::internal::GetCapturedStdout();
        EXPECT_FALSE(read) << name;
        EXPECT_EQ(printed, "") << name;
        EXPECT_TRUE(mesh.vertices.empty() && mesh.faces.empty()) << name;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
        return error.substr(std::min(error.size(), path.size() + 2));
    }

    fs::path dir;
};

// A closed tetrahedron, faces counter-clockwise seen from outside.
const char* const tetrahedron_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                    "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

// A bad file: its name, its bytes and the error reading it gives after "PATH: ".
struct BadFile {
    const char* name;
    std::string bytes;
    const char* error;
};

const std::string triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

uint32_t le32(const char* p)
{
    uint32_t v = 0;
    for (int k = 3; k >= 0; --k)
        v = (v << 8) | uint8_t(p[k]);
    return v;
}

float le_float(const char* p)
{
    const uint32_t bits = le32(p);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

// The data of a binary PLY tetrahedron (float x y z; a face count of `count_bytes`, uint
// indices), little- or big-endian.
std::string binary_tetrahedron(bool big_endian, int count_bytes)
{
    std::string data;
    auto put = [&](uint32_t v, int bytes) {
        for (int k = 0; k < bytes; ++k)
            data.push_back(char(v >> (8 * (big_endian ? bytes - 1 - k : k))));
    };
    const float points[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (const auto& p : points)
        for (float c : p) {
            uint32_t bits;
            std::memcpy(&bits, &c, 4);
            put(bits, 4);
        }
    const uint32_t faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } };
    for (const auto& f : faces) {
        put(3, count_bytes);
        for (uint32_t v : f)
            put(v, 4);
    }
    return data;
}

double distance_to_surface(const SurfaceProjector& projector, const Imath::V3f& p)
{
    return projector.closest_point(p).distance;
}

} // namespace

// --- reading ------------------------------------------------------------------------------

TEST_F(SurfaceMeshTest, BundledMeshesReadWithTheirCountsAndTopology)
{
    struct Expected {
        const char* name;
        size_t vertices, faces, loops;
        long euler;
    };
    for (const Expected& e :
        { Expected { "sphere.obj", 812, 1620, 0, 2 }, Expected { "cow.obj", 2904, 5804, 0, 2 },
            Expected { "mushroom.obj", 2337, 4608, 1, 1 },
            Expected { "torus_uv.obj", 1152, 2304, 0, 0 },
            Expected { "knot.obj", 3200, 6400, 0, 0 },
            Expected { "plane_grid.obj", 4225, 8192, 1, 1 } }) {
        const SurfaceMesh mesh = bundled(e.name);
        EXPECT_EQ(mesh.vertices.size(), e.vertices) << e.name;
        EXPECT_EQ(mesh.faces.size(), e.faces) << e.name;
        const SurfaceTopology t = surface_topology(mesh);
        EXPECT_EQ(t.components, 1u) << e.name;
        EXPECT_EQ(t.boundary_loops, e.loops) << e.name;
        EXPECT_EQ(t.euler_characteristic(), e.euler) << e.name;
        EXPECT_EQ(mesh.uvs.empty(), std::string(e.name) != "torus_uv.obj") << e.name;
    }
    // The first face of sphere.obj, "f 306 126 273", numbered from 0.
    const std::array<uint32_t, 3> first { 305, 125, 272 };
    EXPECT_EQ(bundled("sphere.obj").faces[0], first);
}

TEST_F(SurfaceMeshTest, TorusKeepsOneUvPerFaceCornerAndTwoOnTheSeam)
{
    const SurfaceMesh torus = bundled("torus_uv.obj");
    EXPECT_EQ(torus.face_uvs.size(), 2304u); // one UV triple per face
    EXPECT_EQ(torus.uvs.size(), 1225u);      // the file's 49 x 25 distinct vt values
    std::map<uint32_t, std::set<uint32_t>> uvs_of_vertex;
    for (size_t f = 0; f < torus.faces.size(); ++f)
        for (int k = 0; k < 3; ++k)
            uvs_of_vertex[torus.faces[f][k]].insert(torus.face_uvs[f][k]);
    // The u=0 seam: 24 vertices, each with u=0 on one side and u=1 on the other.
    size_t seam = 0;
    for (const auto& [vertex, uvs] : uvs_of_vertex) {
        std::set<float> us;
        for (uint32_t t : uvs)
            us.insert(torus.uvs[t].x);
        if (us.count(0.0f)) {
            ++seam;
            EXPECT_EQ(us, (std::set<float> { 0.0f, 1.0f })) << "vertex " << vertex;
        }
    }
    EXPECT_EQ(seam, 24u);
    size_t two = 0, four = 0; // the u=0 and v=0 seams cross at one vertex
    for (const auto& entry : uvs_of_vertex) {
        two += entry.second.size() == 2;
        four += entry.second.size() == 4;
    }
    EXPECT_EQ(two, 23u + 47u);
    EXPECT_EQ(four, 1u);
}

TEST_F(SurfaceMeshTest, PolygonsBecomeFansAndKeepTheirCornerUvs)
{
    const std::string path = write("quad.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "f 1/1 2/2 3/3 4/4\n");
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(path, mesh, error)) << error;
    using Tri = std::array<uint32_t, 3>;
    EXPECT_EQ(mesh.faces, (std::vector<Tri> { Tri { 0, 1, 2 }, Tri { 0, 2, 3 } }));
    ASSERT_EQ(mesh.uvs.size(), 4u);
    for (size_t f = 0; f < 2; ++f)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(mesh.uvs[mesh.face_uvs[f][k]],
                Imath::V2f(mesh.vertices[mesh.faces[f][k]].x, mesh.vertices[mesh.faces[f][k]].y));
}

TEST_F(SurfaceMeshTest, PlyReadsAsciiWithVertexUvsAndNegativeObjIndices)
{
    const std::string ply = write("tetra.ply",
        "ply\nformat ascii 1.0\ncomment a tetrahedron\nelement vertex 4\n"
        "property float x\nproperty float y\nproperty float z\nproperty float u\n"
        "property float v\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(ply, mesh, error)) << error;
    EXPECT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.faces.size(), 4u);
    ASSERT_EQ(mesh.uvs.size(), 4u); // per vertex: face_uvs are the faces
    EXPECT_EQ(mesh.face_uvs, mesh.faces);
    EXPECT_EQ(mesh.uvs[3], Imath::V2f(1, 1));

    const std::string obj = write("relative.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
    ASSERT_TRUE(read_surface_mesh(obj, mesh, error)) << error;
    EXPECT_EQ(mesh.faces[0], (std::array<uint32_t, 3> { 0, 2, 1 }));
}

TEST_F(SurfaceMeshTest, BadFilesAreRefusedWithOneLine)
{
    const std::string tetrahedron(tetrahedron_obj);
    const BadFile files[] = {
        { "none.stl", "solid x\n", "is not a mesh texsyn reads (.obj or .ply)" },
        { "empty.obj", "", "has no faces (a surface needs at least one triangle)" },
        { "points.obj", triangle_obj, "has no faces (a surface needs at least one triangle)" },
        { "truncated.obj", tetrahedron.substr(0, tetrahedron.size() - 3), // inside a face
            "line 8: 'f 3 1': a face needs at least 3 vertices, found 2" },
        { "letter.obj", triangle_obj + "f 1 x 3\n",
            "line 4: 'f 1 x 3': a face corner is v, v/vt, v//vn or v/vt/vn, with whole "
            "numbers" },
        { "zero.obj", triangle_obj + "f 0 1 2\n",
            "line 4: 'f 0 1 2': a vertex index must be at least 1 (OBJ counts from 1)" },
        { "range.obj", triangle_obj + "f 1 2 3\nf 1 3 9\n",
            "face 2 refers to vertex 9, but the file has 3 vertices" },
        { "twice.obj", triangle_obj + "f 1 2 2 3\n",
            "line 4: 'f 1 2 2 3': the face lists vertex 2 twice" },
        { "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n",
            "line 2: 'v nan 0 0': a vertex needs three finite numbers (x y z)" },
        { "short.obj", "v 0 0 0\r\nv 1 0\r\nv 0 1 0\r\nf 1 2 3\r\n", // CRLF line ends
            "line 2: 'v 1 0': a vertex needs three finite numbers (x y z)" },
        { "binary.obj", std::string("v 0 0 0\nv \x01\0 0 0\n", 17), // control bytes, a NUL
            "line 2: 'v ?? 0 0': a vertex needs three finite numbers (x y z)" },
        { "mixed.obj", triangle_obj + "vt 0 0\nf 1/1 2/1 3\n",
            "line 5: 'f 1/1 2/1 3': texture coordinates on some face corners only (give every "
            "corner v/vt, or none)" },
        { "vt.obj", triangle_obj + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n",
            "face 1 refers to a texture coordinate the file does not have (it has 2 vt "
            "lines)" },
    };
    for (const BadFile& f : files)
        EXPECT_EQ(read_error(f.name, f.bytes), f.error);
}

TEST_F(SurfaceMeshTest, SurfacesTexsynCannotGrowOnAreRefused)
{
    const std::string fin = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n";
    const BadFile files[] = {
        { "fins.obj", fin + "f 1 2 3\nf 2 1 4\nf 1 2 5\n",
            "the edge between vertices 1 and 2 is shared by 3 faces (non-manifold: a surface "
            "edge borders at most 2)" },
        { "flipped.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nf 1 2 3\nf 1 2 4\n",
            "the faces on either side of the edge between vertices 1 and 2 turn opposite ways "
            "(inconsistent orientation: every face must be counter-clockwise seen from the "
            "same side)" },
        { "bowtie.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n",
            "vertex 1 is where 2 separate fans of faces meet (non-manifold vertex: its faces "
            "must form one fan)" },
        { "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
            "the face on vertices 1, 2, 3 has zero area (below 1e-12 x the squared "
            "bounding-box diagonal)" },
        { "three.obj",
            triangle_obj
                + "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 9 0 0\nv 9 1 0\nv 8 1 0\n"
                  "f 1 2 3\nf 4 5 6\nf 7 8 9\n",
            "has 3 separate components; texsyn grows one surface at a time (split it)" },
        { "inside_out.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n",
            "is a closed surface whose faces face inwards (negative enclosed volume); faces "
            "must be counter-clockwise seen from outside" },
        { "stray.obj", triangle_obj + "v 7 7 7\nf 1 2 3\n",
            "vertex 4 belongs to no face (a surface mesh uses every vertex: remove unused "
            "ones)" },
    };
    for (const BadFile& f : files)
        EXPECT_EQ(read_error(f.name, f.bytes), f.error);
}

TEST_F(SurfaceMeshTest, BadPlyFilesAreRefusedWithWhatIsWrong)
{
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                               "property float x\nproperty float y\nproperty float z\n"
                               "element face 4\nproperty list uchar int vertex_indices\n"
                               "end_header\n";
    const std::string data = binary_tetrahedron(false, 1);
    // The whole file reads; one byte less is truncated.
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(write("tetra.ply", header + data), mesh, error)) << error;
    EXPECT_EQ(mesh.faces.size(), 4u);
    const std::string size = std::to_string(header.size() + data.size());
    EXPECT_EQ(read_error("cut.ply", header + data.substr(0, data.size() - 1)),
        "is truncated: its header announces 4 vertices and 4 faces (at least " + size
            + " bytes), but the file has " + std::to_string(header.size() + data.size() - 1));

    std::string nan_data = data;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&nan_data[12], &nan, 4); // vertex 2's x
    EXPECT_EQ(read_error("nan.ply", header + nan_data),
        "vertex 2 has a coordinate that is not a finite number (nan, 0.000000, 0.000000)");

    // Counts beyond the limit are refused from the header, before anything is allocated.
    std::string huge = header;
    huge.replace(huge.find("vertex 4"), 8, "vertex 60000000");
    EXPECT_EQ(read_error("huge.ply", huge + data),
        "has more than 50000000 vertices (texsyn's limit for one surface)");

    EXPECT_EQ(read_error("ascii_cut.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1"),
        "is truncated: its header announces 3 vertices and 1 faces, but the data stops before "
        "their end");
    const std::string triangle_header
        = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(
        read_error("repeat.ply", triangle_header + "3 0 1 1\n"), "face 1 lists vertex 2 twice");
    EXPECT_EQ(read_error("beyond.ply", triangle_header + "3 0 1 3\n"),
        "face 1 refers to vertex 4, but the file has 3 vertices");
    EXPECT_EQ(read_error("noface.ply",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n0 0 0\n"),
        "the PLY header has no face element with a vertex_indices list");
    EXPECT_EQ(read_error("twice.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement vertex 3\nproperty float y\nend_header\n"),
        "header line 7: a second element 'vertex'"); // a fuzzing finding: the second had no x
    EXPECT_EQ(
        read_error("text.ply", "solid\n"), "not a PLY file (it does not start with a 'ply' line)");
    const std::string binary("ply\nformat ascii 1.0\n\x7f\x01\0\nend_header\n", 35);
    // (The expected text is split: "??'" would be a trigraph.)
    EXPECT_EQ(read_error("binary.ply", binary),
        "header line 3: unknown keyword '??"
        "?'");
}

// Issue #34: meshes from untrusted sources. Files an OBJ names are never opened (a FIFO
// there hung every host), ASCII PLY tokens are validated (OpenMesh's reader grew without
// bound or made up indices on them), and what other tools write is read.
TEST_F(SurfaceMeshTest, MaterialLibrariesAnObjNamesAreNeverOpened)
{
    const std::string fifo = (dir / "materials.mtl").string();
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    // With a FIFO opened for reading, this read would block forever (the test would time out).
    const std::string obj = write("tetra.obj",
        std::string("mtllib materials.mtl\nmtllib ../../../../dev/zero\nusemtl skin\no t\n")
            + tetrahedron_obj);
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(obj, mesh, error)) << error;
    EXPECT_EQ(mesh.faces.size(), 4u);
}

TEST_F(SurfaceMeshTest, AsciiPlyTokensAreValidatedWithTheirLine)
{
    const std::string header
        = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
          "end_header\n";
    const std::string faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
    auto with_vertex_2 = [&](const std::string& line) {
        return header + "0 0 0\n" + line + "\n0 1 0\n0 0 1\n" + faces;
    };
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(write("good.ply", with_vertex_2("1 0 0")), mesh, error)) << error;
    struct Case {
        const char* line;
        std::string error;
    };
    const Case cases[] = {
        { "nan 0 0",
            "line 11: 'nan 0 0': vertex 2's x: 'nan' is not a finite number of PLY "
            "type float" },
        { "1 inf 0",
            "line 11: '1 inf 0': vertex 2's y: 'inf' is not a finite number of PLY "
            "type float" },
        { "1 0 1e39",
            "line 11: '1 0 1e39': vertex 2's z: '1e39' is not a finite number of "
            "PLY type float" },
        { "x 0 0",
            "line 11: 'x 0 0': vertex 2's x: 'x' is not a finite number of PLY type "
            "float" },
        { "1 0", "line 11: '1 0': the line ends before vertex 2's z (one element per line)" },
        { "1 0 0 0",
            "line 11: '1 0 0 0': vertex 2 has more values than the header's "
            "properties (one element per line)" },
    };
    for (const Case& c : cases)
        for (int repeat = 0; repeat < 3; ++repeat) // the same answer every time
            EXPECT_EQ(read_error("bad.ply", with_vertex_2(c.line)), c.error) << c.line;

    const std::string triangle = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                 "property float y\nproperty float z\nelement face 1\n"
                                 "property list uchar int vertex_indices\nend_header\n"
                                 "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(read_error("minus.ply", triangle + "3 0 -1 2\n"),
        "face 1 has the vertex index -1 (PLY counts from 0)");
    EXPECT_EQ(read_error("half.ply", triangle + "3 0 1.5 2\n"),
        "line 13: '3 0 1.5 2': face 1's vertex_indices: '1.5' is not an integer of PLY type "
        "int");
    EXPECT_EQ(read_error("count.ply", triangle + "300 0 1 2\n"),
        "line 13: '300 0 1 2': face 1's vertex_indices count: '300' is not an integer of PLY "
        "type uchar");
    EXPECT_EQ(read_error("long.ply", triangle + std::string(kMaxMeshLineBytes + 1, '1')),
        "line 13: '" + std::string(48, '1') + "...': longer than 16 MiB (not PLY data?)");
}

TEST_F(SurfaceMeshTest, IndicesBeyondAnyIntAreNamedAsGiven)
{
    EXPECT_EQ(read_error("far.obj", triangle_obj + "f 1 2 3000000000\n"),
        "face 1 refers to vertex 3000000000, but the file has 3 vertices");
    EXPECT_EQ(read_error("long.obj", triangle_obj + "f 1 2 " + std::string(kMaxMeshLineBytes, '3')),
        "line 4: 'f 1 2 " + std::string(42, '3') + "...': longer than 16 MiB (not an OBJ file?)");
    EXPECT_EQ(read_error("nanuv.obj", triangle_obj + "vt nan 0\nf 1/1 2/1 3/1\n"),
        "line 4: 'vt nan 0': a texture coordinate needs one or two finite numbers (u v)");
}

TEST_F(SurfaceMeshTest, PlyListCountsOfAnyIntegerTypeAndMeshLabTexcoordsAreRead)
{
    // A quad and a triangle, counts as ushort (and char), corner UVs as MeshLab writes them.
    for (const char* count : { "ushort", "char", "uint8", "int" }) {
        const std::string ply = write("meshlab.ply",
            std::string("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 2\nproperty list ")
                + count + " int vertex_indices\nproperty list " + count
                + " float texcoord\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n"
                  "4 0 1 2 3 8 0 0 0.5 0 0.5 1 0 1\n3 1 4 2 6 0.5 0 1 0 0.5 1\n");
        SurfaceMesh mesh;
        std::string error;
        ASSERT_TRUE(read_surface_mesh(ply, mesh, error)) << count << ": " << error;
        ASSERT_EQ(mesh.faces.size(), 3u) << count;
        ASSERT_EQ(mesh.face_uvs.size(), 3u) << count;
        EXPECT_EQ(mesh.uvs.size(), 5u) << count; // (0.5,0) and (0.5,1) are shared
        for (size_t f = 0; f < 2; ++f)           // the quad's corners: u is x / 2, v is y
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(mesh.uvs[mesh.face_uvs[f][k]],
                    Imath::V2f(
                        mesh.vertices[mesh.faces[f][k]].x / 2, mesh.vertices[mesh.faces[f][k]].y))
                    << count;
        EXPECT_EQ(mesh.uvs[mesh.face_uvs[2][1]], Imath::V2f(1, 0)) << count;
    }
    EXPECT_EQ(read_error("odd.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "property list uchar float texcoord\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                  "3 0 1 2 4 0 0 1 0\n"),
        "face 1 has 3 corners but 4 texcoord values (two per corner)");
}

TEST_F(SurfaceMeshTest, BigEndianPlyReadsAsLittleEndian)
{
    const std::string data = binary_tetrahedron(true, 2);
    const std::string ply = write("big.ply",
        "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 4\n"
        "property list ushort uint vertex_indices\nend_header\n"
            + data);
    SurfaceMesh mesh;
    std::string error;
    ASSERT_TRUE(read_surface_mesh(ply, mesh, error)) << error;
    SurfaceMesh tetrahedron;
    ASSERT_TRUE(read_surface_mesh(write("tetra.obj", tetrahedron_obj), tetrahedron, error));
    EXPECT_EQ(mesh.vertices, tetrahedron.vertices);
    EXPECT_EQ(mesh.faces, tetrahedron.faces);
}

TEST_F(SurfaceMeshTest, MissingFilesAndFoldersAreNamed)
{
    SurfaceMesh mesh;
    std::string error;
    const std::string missing = (dir / "missing.obj").string();
    EXPECT_FALSE(read_surface_mesh(missing, mesh, error));
    EXPECT_EQ(error, missing + ": no such file");
    EXPECT_FALSE(read_surface_mesh(dir.string(), mesh, error));
    EXPECT_EQ(error, dir.string() + ": is a directory, not a mesh");
}

// --- face-colour PLY ------------------------------------------------------------------

TEST_F(SurfaceMeshTest, FaceColourPlyRoundTripsThroughOpenMeshAndByteByByte)
{
    const SurfaceMesh cow = bundled("cow.obj");
    const size_t nf = cow.faces.size();
    std::vector<std::vector<float>> channels(3, std::vector<float>(nf));
    std::vector<std::array<uint8_t, 3>> display(nf);
    for (size_t f = 0; f < nf; ++f) {
        for (int c = 0; c < 3; ++c)
            channels[c][f] = float(f % 97) * 0.125f + float(c) - 0.5f; // exact in float
        display[f] = { uint8_t(f % 251), uint8_t((f * 7) % 256), uint8_t(255 - f % 256) };
    }
    const std::string path = (dir / "cow_texture.ply").string();
    std::string error;
    ASSERT_TRUE(write_face_colour_ply(
        path, cow.vertices, cow.faces, channels, { "r", "g", "b" }, &display, error))
        << error;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
        << "no temporary file is left";

    // texsyn's own reader (OpenMesh underneath) gives the geometry back exactly.
    SurfaceMesh back;
    ASSERT_TRUE(read_surface_mesh(path, back, error)) << error;
    EXPECT_EQ(back.vertices, cow.vertices);
    EXPECT_EQ(back.faces, cow.faces);

    // OpenMesh's mesh reader, as a viewer reads it, finds the display colours on the faces.
    OpenMesh::TriMesh_ArrayKernelT<> om;
    om.request_face_colors();
    OpenMesh::IO::Options options = OpenMesh::IO::Options::FaceColor;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(om, path, options));
    ASSERT_TRUE(options.check(OpenMesh::IO::Options::FaceColor));
    ASSERT_EQ(om.n_faces(), nf);
    for (size_t f = 0; f < nf; f += 101) {
        const auto colour = om.color(OpenMesh::FaceHandle(int(f)));
        EXPECT_EQ(colour[0], display[f][0]);
        EXPECT_EQ(colour[1], display[f][1]);
        EXPECT_EQ(colour[2], display[f][2]);
    }

    // The bytes: the header names texsyn and the colour spaces; each face record holds the
    // float channels exactly.
    std::ifstream in(path, std::ios::binary);
    PlyHeader header;
    ASSERT_TRUE(read_ply_header(in, header, error)) << error;
    ASSERT_GE(header.comments.size(), 3u);
    EXPECT_EQ(header.comments[0].rfind("texsyn ", 0), 0u);
    EXPECT_NE(header.comments[1].find("r g b: float, scene-linear"), std::string::npos);
    EXPECT_NE(header.comments[2].find("red green blue: 8-bit sRGB"), std::string::npos);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t record = 1 + 12 + 12 + 3;
    ASSERT_EQ(bytes.size(), cow.vertices.size() * 12 + nf * record);
    for (size_t f = 0; f < nf; ++f) {
        const char* r = bytes.data() + cow.vertices.size() * 12 + f * record;
        ASSERT_EQ(r[0], 3);
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(le32(r + 1 + 4 * c), cow.faces[f][c]);
            ASSERT_EQ(le_float(r + 13 + 4 * c), channels[c][f]);
        }
    }
}

TEST_F(SurfaceMeshTest, FaceColourPlyRefusesBadArgumentsAndLeavesNoFile)
{
    const std::vector<Imath::V3f> vertices { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    const std::vector<std::array<uint32_t, 3>> faces { { 0, 1, 2 } };
    const std::vector<std::vector<float>> one { { 0.5f } };
    const std::string path = (dir / "out.ply").string();
    auto refused = [&](const std::string& p, const std::vector<std::array<uint32_t, 3>>& f,
                       const std::vector<std::vector<float>>& channels,
                       const std::vector<std::string>& names,
                       const std::vector<std::array<uint8_t, 3>>* rgb) {
        std::string error;
        EXPECT_FALSE(write_face_colour_ply(p, vertices, f, channels, names, rgb, error));
        EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
        return error;
    };
    const std::vector<std::array<uint8_t, 3>> two_colours(2);
    EXPECT_EQ(refused(path, faces, one, { "r g" }, nullptr),
        path
            + ": cannot write (channel_names[0]='r g' is not a PLY property name (letters, "
              "digits and '_'))");
    EXPECT_EQ(refused(path, faces, one, { "red" }, &two_colours),
        path + ": cannot write (channel_names[0]='red' is already a face property of this file)");
    EXPECT_EQ(refused(path, faces, one, { "q" }, &two_colours),
        path + ": cannot write (display_rgb has 2 colours for 1 faces)");
    EXPECT_EQ(refused(path, faces, { { 1, 2 } }, { "q" }, nullptr),
        path + ": cannot write (face_channels[0] has 2 values for 1 faces)");
    EXPECT_EQ(refused(path, { { 0, 1, 3 } }, {}, {}, nullptr),
        path + ": cannot write (faces[0] refers to vertex 3, but there are 3)");
    EXPECT_EQ(refused((dir / "out.obj").string(), faces, {}, {}, nullptr),
        (dir / "out.obj").string() + ": cannot write (a face-colour mesh is written as .ply)");
    const std::string nowhere = (dir / "no" / "out.ply").string();
    EXPECT_EQ(refused(nowhere, faces, {}, {}, nullptr),
        nowhere + ": cannot write (directory " + (dir / "no").string() + " does not exist)");
}

// --- closest points -----------------------------------------------------------------------

// The projector's answer lies on the face it names and no sampled point of any face (a
// 16 x 16 barycentric grid on each) is closer: an oracle that shares no code with it.
TEST_F(SurfaceMeshTest, ClosestPointsAreOnTheSurfaceAndNoSampleIsCloser)
{
    const SurfaceMesh cow = bundled("cow.obj");
    const SurfaceProjector projector(cow);
    std::vector<Imath::V3f> samples;
    for (const auto& f : cow.faces)
        for (int i = 0; i <= 16; ++i)
            for (int j = 0; i + j <= 16; ++j) {
                const float u = float(i) / 16, v = float(j) / 16;
                samples.push_back(cow.vertices[f[0]] * (1 - u - v) + cow.vertices[f[1]] * u
                    + cow.vertices[f[2]] * v);
            }
    uint32_t state = 12345;
    auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
    for (int q = 0; q < 200; ++q) {
        const Imath::V3f p(next() * 1.4f - 0.7f, next() * 0.9f - 0.45f, next() * 0.6f - 0.3f);
        const SurfacePoint s = projector.closest_point(p);
        const auto& f = cow.faces[s.face];
        const Imath::V3f& b = s.barycentric;
        EXPECT_GE(std::min({ b.x, b.y, b.z }), 0.0f);
        EXPECT_NEAR(b.x + b.y + b.z, 1.0f, 1e-6f);
        const Imath::V3f on_face
            = cow.vertices[f[0]] * b.x + cow.vertices[f[1]] * b.y + cow.vertices[f[2]] * b.z;
        EXPECT_LT((on_face - s.position).length(), 1e-6f);
        EXPECT_NEAR((p - s.position).length(), s.distance, 1e-6f);
        float nearest_sample = std::numeric_limits<float>::max();
        for (const Imath::V3f& x : samples)
            nearest_sample = std::min(nearest_sample, (p - x).length());
        // float rounding of the sample positions and of the distances
        EXPECT_LE(s.distance, nearest_sample + 1e-6f) << "query " << q;

        // Among the faces facing the way the found face does, that face is still the
        // closest; facing the other way, the answer is a face that faces that way.
        const Imath::V3f normal
            = (cow.vertices[f[1]] - cow.vertices[f[0]]) % (cow.vertices[f[2]] - cow.vertices[f[0]]);
        SurfacePoint same, opposite;
        ASSERT_TRUE(projector.closest_facing_point(p, normal, same));
        EXPECT_EQ(same.face, s.face);
        EXPECT_EQ(same.distance, s.distance);
        ASSERT_TRUE(projector.closest_facing_point(p, -normal, opposite));
        const auto& g = cow.faces[opposite.face];
        EXPECT_LT(
            ((cow.vertices[g[1]] - cow.vertices[g[0]]) % (cow.vertices[g[2]] - cow.vertices[g[0]]))
                ^ normal,
            0.0f);
        EXPECT_GE(opposite.distance, s.distance);
    }
}

TEST_F(SurfaceMeshTest, BoundaryPointsLieOnTheBoundary)
{
    SurfacePoint s;
    EXPECT_FALSE(SurfaceProjector(bundled("sphere.obj")).closest_boundary_point({ 0, 0, 0 }, s));
    const SurfaceMesh mushroom = bundled("mushroom.obj");
    const SurfaceProjector projector(mushroom);
    // The vertices of edges with one face.
    std::set<uint32_t> boundary_vertices;
    const std::vector<EdgeUse> uses = sorted_edge_uses(mushroom.faces);
    for (size_t i = 0; i < uses.size(); i = edge_end(uses, i))
        if (edge_end(uses, i) == i + 1)
            boundary_vertices.insert({ uses[i].a, uses[i].b });
    ASSERT_EQ(boundary_vertices.size(), 64u); // one loop of 64 edges
    for (uint32_t v : boundary_vertices) {
        const Imath::V3f p = mushroom.vertices[v] + Imath::V3f(0.01f, -0.02f, 0.03f);
        ASSERT_TRUE(projector.closest_boundary_point(p, s));
        const Imath::V3f& b = s.barycentric;
        EXPECT_TRUE(b.x == 0 || b.y == 0 || b.z == 0); // on an edge of its face
        float nearest_vertex = std::numeric_limits<float>::max();
        for (uint32_t w : boundary_vertices)
            nearest_vertex = std::min(nearest_vertex, (p - mushroom.vertices[w]).length());
        EXPECT_LE(s.distance, nearest_vertex + 1e-6f);
    }
}

// --- remeshing ------------------------------------------------------------------------
// Measured (10 iterations), input -> output:
//   cow 4000:      5804 -> 3956 faces, min angle 2.8 -> 10.7 deg, faces with an angle under
//                  30 deg 49% -> 0.25% (all on the tail, thinner than the target edge),
//                  edge spread 0.63 -> 0.12
//   sphere 3000:   1620 -> 2988 faces, min angle 54.1 -> 41.3, spread 0.048 -> 0.091
//   mushroom 3000: 4608 -> 2962 faces, min angle 8.9 -> 22.0, under 30 deg 27% -> 0.24%,
//                  spread 0.39 -> 0.12
//   torus 1500:    2304 -> 1490 faces, min angle 31.0 -> 32.4, spread 0.28 -> 0.14
// Every output vertex lies within 2e-8 x the bounding-box diagonal of the input surface.

namespace {

struct RemeshResult {
    SurfaceMesh mesh;
    MeshQuality before, after;
    double worst_distance = 0, diagonal = 0;
};

RemeshResult remeshed(const std::string& name, size_t target)
{
    RemeshResult r;
    const SurfaceMesh input = bundled(name);
    std::string error;
    EXPECT_TRUE(remesh_isotropic(input, target, r.mesh, error)) << error;
    r.before = mesh_quality(input);
    r.after = mesh_quality(r.mesh);
    r.diagonal = bounding_box_diagonal(input.vertices);
    const SurfaceProjector projector(input);
    for (const Imath::V3f& v : r.mesh.vertices)
        r.worst_distance = std::max(r.worst_distance, distance_to_surface(projector, v));
    std::cout << name << " -> " << target << " faces: " << input.faces.size() << " -> "
              << r.mesh.faces.size() << " faces; min angle " << r.before.min_angle_degrees << " -> "
              << r.after.min_angle_degrees << " deg; under 30 deg " << r.before.small_angle_share
              << " -> " << r.after.small_angle_share << "; edge spread " << r.before.edge_spread
              << " -> " << r.after.edge_spread << "; area " << r.before.area << " -> "
              << r.after.area << "; worst distance / diagonal " << r.worst_distance / r.diagonal
              << "\n";
    // The face count follows the target (the brief allows 15%; measured within 1.5%).
    EXPECT_NEAR(double(r.mesh.faces.size()), double(target), 0.05 * double(target)) << name;
    // On the input surface: float rounding of the projected positions.
    EXPECT_LT(r.worst_distance, 1e-4 * r.diagonal) << name;
    EXPECT_EQ(surface_topology(r.mesh).components, 1u) << name;
    return r;
}

} // namespace

// The bounds leave margin under the measured values above.
TEST_F(SurfaceMeshTest, RemeshingTheCowMakesEvenTrianglesOnTheSameSurface)
{
    const RemeshResult r = remeshed("cow.obj", 4000);
    EXPECT_GT(r.after.min_angle_degrees, 5.0);
    EXPECT_LT(r.after.small_angle_share, 0.01);
    EXPECT_LT(r.after.edge_spread, 0.15);
    const SurfaceTopology t = surface_topology(r.mesh);
    EXPECT_EQ(t.boundary_loops, 0u);
    EXPECT_EQ(t.euler_characteristic(), 2);
}

TEST_F(SurfaceMeshTest, RemeshingTheSphereKeepsItEven)
{
    const RemeshResult r = remeshed("sphere.obj", 3000);
    EXPECT_GT(r.after.min_angle_degrees, 35.0);
    EXPECT_LT(r.after.edge_spread, 0.12);
    EXPECT_EQ(surface_topology(r.mesh).euler_characteristic(), 2);
}

TEST_F(SurfaceMeshTest, RemeshingKeepsBoundaryLoopsAndGenus)
{
    const RemeshResult mushroom = remeshed("mushroom.obj", 3000);
    EXPECT_GT(mushroom.after.min_angle_degrees, 15.0);
    EXPECT_LT(mushroom.after.edge_spread, 0.15);
    const SurfaceTopology t = surface_topology(mushroom.mesh);
    EXPECT_EQ(t.boundary_loops, 1u);
    EXPECT_EQ(t.euler_characteristic(), 1);

    const RemeshResult torus = remeshed("torus_uv.obj", 1500);
    EXPECT_GT(torus.after.min_angle_degrees, 25.0);
    EXPECT_LT(torus.after.edge_spread, 0.2);
    EXPECT_TRUE(torus.mesh.uvs.empty() && torus.mesh.face_uvs.empty());
    EXPECT_EQ(surface_topology(torus.mesh).euler_characteristic(), 0);
}

TEST_F(SurfaceMeshTest, RemeshingIsDeterministic)
{
    const SurfaceMesh cow = bundled("cow.obj");
    SurfaceMesh a, b;
    std::string error;
    ASSERT_TRUE(remesh_isotropic(cow, 2000, a, error, 4)) << error;
    ASSERT_TRUE(remesh_isotropic(cow, 2000, b, error, 4)) << error;
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.faces, b.faces);
}

// CGAL's isotropic_remeshing (GPL, only in -DTEXSYN_WITH_CGAL=ON builds: the gpl_backends
// test builds one) against texsyn's own on the cow. Measured at 4000 faces:
//   texsyn: 3956 faces, min angle 10.7 deg, under 30 deg 0.25%, edge spread 0.124
//   CGAL:   4000 faces, min angle 15.0 deg, under 30 deg 0.65%, edge spread 0.136
// (mushroom at 3000: ours min angle 22.0, spread 0.120; CGAL 30.2, 0.135.)
TEST_F(SurfaceMeshTest, CgalBackendAndOurRemesherAgreeOnTheCow)
{
    SurfaceMesh out;
    std::string error;
    if (!remesh_backend_available(RemeshBackend::Cgal)) {
        EXPECT_FALSE(
            remesh_isotropic(bundled("cow.obj"), 4000, out, error, 10, RemeshBackend::Cgal));
        EXPECT_EQ(error,
            "remesh_isotropic: the CGAL backend is not built into this texsyn "
            "(configure with -DTEXSYN_WITH_CGAL=ON)");
        GTEST_SKIP() << "built without -DTEXSYN_WITH_CGAL=ON";
    }
    const SurfaceMesh cow = bundled("cow.obj");
    SurfaceMesh ours, cgal;
    ASSERT_TRUE(remesh_isotropic(cow, 4000, ours, error)) << error;
    ASSERT_TRUE(remesh_isotropic(cow, 4000, cgal, error, 10, RemeshBackend::Cgal)) << error;
    const MeshQuality q = mesh_quality(ours), c = mesh_quality(cgal);
    std::cout << "cow -> 4000 faces: ours " << ours.faces.size() << " faces, min angle "
              << q.min_angle_degrees << ", under 30 deg " << q.small_angle_share << ", spread "
              << q.edge_spread << "; CGAL " << cgal.faces.size() << " faces, min angle "
              << c.min_angle_degrees << ", under 30 deg " << c.small_angle_share << ", spread "
              << c.edge_spread << "\n";
    EXPECT_NEAR(double(cgal.faces.size()), 4000.0, 0.05 * 4000);
    EXPECT_EQ(surface_topology(cgal).euler_characteristic(), 2);
    EXPECT_GT(c.min_angle_degrees, 5.0);
    // Ours is at least as even (with margin under the measured values above).
    EXPECT_LT(q.edge_spread, 1.1 * c.edge_spread);
    EXPECT_LT(q.small_angle_share, 2 * c.small_angle_share);
}

TEST_F(SurfaceMeshTest, RemeshingRefusesBadArguments)
{
    const SurfaceMesh cow = bundled("cow.obj");
    SurfaceMesh out;
    std::string error;
    EXPECT_FALSE(remesh_isotropic(cow, 4, out, error));
    EXPECT_EQ(error, "remesh_isotropic: target_faces=4 is outside 8..50000000");
    EXPECT_FALSE(remesh_isotropic(cow, 1000, out, error, 0));
    EXPECT_EQ(error, "remesh_isotropic: iterations=0 is outside 1..100");
    SurfaceMesh two = cow;
    two.faces.push_back({ 0, 1, 2 });
    EXPECT_FALSE(remesh_isotropic(two, 1000, out, error));
    EXPECT_EQ(error.rfind("remesh_isotropic: the input mesh: ", 0), 0u) << error;
    EXPECT_TRUE(out.faces.empty());
}
