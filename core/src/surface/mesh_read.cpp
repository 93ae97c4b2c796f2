// SPDX-License-Identifier: Apache-2.0
// OBJ and PLY through OpenMesh's readers, into plain arrays. OpenMesh reads into an
// importer of ours that records what the file says (polygons, per-corner texture
// coordinates) without building a half-edge mesh: OpenMesh's own mesh importer would
// re-attach a non-manifold face to copies of its vertices, and that repair must be refused
// (check_surface_mesh), not hidden.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <unordered_map>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;
using OpenMesh::Attributes::StatusInfo;

// What OpenMesh's readers report, as they report it: every vertex, every polygon with the
// indices the file gives (valid or not), per-corner and per-vertex texture coordinates.
// Everything else a reader may pass (normals, colours, materials) is ignored.
class RecordingImporter : public OpenMesh::IO::BaseImporter {
public:
    std::vector<Imath::V3f> points;
    std::vector<int> corners; // polygon vertex indices, polygon after polygon
    std::vector<size_t> polygon_start { 0 };
    std::vector<Imath::V2f> corner_uvs; // one per corner, valid where corner_has_uv
    std::vector<char> corner_has_uv;
    std::vector<Imath::V2f> vertex_uvs;
    size_t vertices_with_uv = 0;

    size_t polygons() const { return polygon_start.size() - 1; }

    VertexHandle add_vertex(const OpenMesh::Vec3f& p) override
    {
        points.emplace_back(p[0], p[1], p[2]);
        return VertexHandle(int(points.size() - 1));
    }
    VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3f(0, 0, 0)); }
    void set_point(VertexHandle v, const OpenMesh::Vec3f& p) override
    {
        if (v.is_valid() && size_t(v.idx()) < points.size())
            points[v.idx()] = Imath::V3f(p[0], p[1], p[2]);
    }
    FaceHandle add_face(const VHandles& vertices) override
    {
        for (VertexHandle v : vertices)
            corners.push_back(v.idx());
        polygon_start.push_back(corners.size());
        corner_uvs.resize(corners.size());
        corner_has_uv.resize(corners.size(), 0);
        return FaceHandle(int(polygons() - 1));
    }
    // `uvs` start at the polygon's corner on vertex `first`.
    void add_face_texcoords(
        FaceHandle f, VertexHandle first, const std::vector<OpenMesh::Vec2f>& uvs) override
    {
        if (!f.is_valid() || size_t(f.idx()) >= polygons() || uvs.empty())
            return;
        const size_t begin = polygon_start[f.idx()], n = polygon_start[f.idx() + 1] - begin;
        size_t start = 0;
        while (start < n && corners[begin + start] != first.idx())
            ++start;
        for (size_t k = 0; k < uvs.size() && k < n; ++k) {
            const size_t c = begin + (start + k) % n;
            corner_uvs[c] = Imath::V2f(uvs[k][0], uvs[k][1]);
            corner_has_uv[c] = 1;
        }
    }
    void set_texcoord(VertexHandle v, const OpenMesh::Vec2f& uv) override
    {
        if (!v.is_valid() || size_t(v.idx()) >= points.size())
            return;
        if (vertex_uvs.size() < points.size())
            vertex_uvs.resize(points.size(), Imath::V2f(NAN, NAN));
        vertices_with_uv += std::isnan(vertex_uvs[v.idx()].x);
        vertex_uvs[v.idx()] = Imath::V2f(uv[0], uv[1]);
    }
    size_t n_vertices() const override { return points.size(); }
    size_t n_faces() const override { return polygons(); }
    size_t n_edges() const override { return 0; }

    // Ignored.
    HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
    FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override
    { }
    void set_face_texindex(FaceHandle, int) override { }
    void set_halfedge(VertexHandle, HalfedgeHandle) override { }
    void set_normal(VertexHandle, const OpenMesh::Vec3f&) override { }
    void set_normal(VertexHandle, const OpenMesh::Vec3d&) override { }
    void set_color(VertexHandle, const OpenMesh::Vec3uc&) override { }
    void set_color(VertexHandle, const OpenMesh::Vec4uc&) override { }
    void set_color(VertexHandle, const OpenMesh::Vec3f&) override { }
    void set_color(VertexHandle, const OpenMesh::Vec4f&) override { }
    void set_status(VertexHandle, const StatusInfo&) override { }
    void set_next(HalfedgeHandle, HalfedgeHandle) override { }
    void set_face(HalfedgeHandle, FaceHandle) override { }
    void request_face_texcoords2D() override { }
    void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override { }
    void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override { }
    void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override { }
    void set_status(HalfedgeHandle, const StatusInfo&) override { }
    void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override { }
    void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override { }
    void set_color(EdgeHandle, const OpenMesh::Vec3f&) override { }
    void set_color(EdgeHandle, const OpenMesh::Vec4f&) override { }
    void set_status(EdgeHandle, const StatusInfo&) override { }
    void set_normal(FaceHandle, const OpenMesh::Vec3f&) override { }
    void set_normal(FaceHandle, const OpenMesh::Vec3d&) override { }
    void set_color(FaceHandle, const OpenMesh::Vec3uc&) override { }
    void set_color(FaceHandle, const OpenMesh::Vec4uc&) override { }
    void set_color(FaceHandle, const OpenMesh::Vec3f&) override { }
    void set_color(FaceHandle, const OpenMesh::Vec4f&) override { }
    void set_status(FaceHandle, const StatusInfo&) override { }
    void add_texture_information(int, std::string) override { }
};

// OpenMesh's readers keep state in process-wide singletons and print to its own global
// streams: one read at a time, with those streams off (the caller reports one line).
class QuietOpenMeshRead {
public:
    QuietOpenMeshRead()
        : m_lock(mutex())
    {
        for (int k = 0; k < 3; ++k) {
            m_enabled[k] = stream(k).is_enabled();
            stream(k).disable();
        }
    }
    ~QuietOpenMeshRead()
    {
        for (int k = 0; k < 3; ++k)
            if (m_enabled[k])
                stream(k).enable();
    }

private:
    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
    static OpenMesh::mostream& stream(int k)
    {
        return k == 0 ? ::omlog() : k == 1 ? ::omout() : ::omerr();
    }
    std::lock_guard<std::mutex> m_lock;
    bool m_enabled[3] = {};
};

// Checks the importer's polygons against what the first pass counted, and their indices.
bool check_polygons(const RecordingImporter& in, const MeshFileCounts& counts, std::string& what)
{
    if (in.points.size() != counts.vertices || in.polygons() != counts.faces) {
        what = "is truncated or malformed: it announces " + std::to_string(counts.vertices)
            + " vertices and " + std::to_string(counts.faces) + " faces, but "
            + std::to_string(in.points.size()) + " and " + std::to_string(in.polygons())
            + " could be read";
        return false;
    }
    uint64_t triangles = 0;
    for (size_t f = 0; f < in.polygons(); ++f) {
        const size_t begin = in.polygon_start[f], n = in.polygon_start[f + 1] - begin;
        auto face = [f] { return "face " + std::to_string(f + 1); };
        if (n < 3) {
            what = face() + " has " + std::to_string(n) + " vertices (at least 3)";
            return false;
        }
        triangles += n - 2;
        std::vector<int> sorted(in.corners.begin() + begin, in.corners.begin() + begin + n);
        std::sort(sorted.begin(), sorted.end());
        for (size_t k = 0; k < n; ++k) {
            const int v = in.corners[begin + k];
            if (v < 0 || size_t(v) >= in.points.size()) {
                what = face() + " refers to vertex " + std::to_string(int64_t(v) + 1)
                    + ", but the file has " + std::to_string(in.points.size()) + " vertices";
                return false;
            }
            if (k > 0 && sorted[k] == sorted[k - 1]) {
                what = face() + " lists vertex " + std::to_string(sorted[k] + 1) + " twice";
                return false;
            }
            if (counts.face_texcoords && !in.corner_has_uv[begin + k]) {
                what = face() + " refers to a texture coordinate the file does not have (it has "
                    + std::to_string(counts.texcoords) + " vt lines)";
                return false;
            }
        }
    }
    if (triangles > kMaxMeshElements) {
        what = "has more than " + std::to_string(kMaxMeshElements)
            + " triangles (texsyn's limit for one surface)";
        return false;
    }
    return true;
}

// Polygons into triangle fans; corner UVs into one list (equal values shared).
void build_mesh(const RecordingImporter& in, bool corner_uvs, SurfaceMesh& mesh)
{
    mesh = SurfaceMesh();
    mesh.vertices = in.points;
    std::unordered_map<uint64_t, uint32_t> uv_index;
    auto uv_of_corner = [&](size_t c) {
        const Imath::V2f uv = in.corner_uvs[c];
        uint32_t bits[2];
        std::memcpy(bits, &uv, sizeof(bits));
        const auto inserted
            = uv_index.emplace((uint64_t(bits[0]) << 32) | bits[1], uint32_t(mesh.uvs.size()));
        if (inserted.second)
            mesh.uvs.push_back(uv);
        return inserted.first->second;
    };
    for (size_t f = 0; f < in.polygons(); ++f) {
        const size_t begin = in.polygon_start[f], n = in.polygon_start[f + 1] - begin;
        for (size_t k = 1; k + 1 < n; ++k) {
            const size_t c[3] = { begin, begin + k, begin + k + 1 };
            mesh.faces.push_back({ uint32_t(in.corners[c[0]]), uint32_t(in.corners[c[1]]),
                uint32_t(in.corners[c[2]]) });
            if (corner_uvs)
                mesh.face_uvs.push_back(
                    { uv_of_corner(c[0]), uv_of_corner(c[1]), uv_of_corner(c[2]) });
        }
    }
    if (!corner_uvs && in.vertices_with_uv == in.points.size() && !in.points.empty()) {
        mesh.uvs = in.vertex_uvs;
        mesh.face_uvs = mesh.faces;
    }
}

bool read_checked_mesh(const std::string& path, SurfaceMesh& mesh, std::string& what)
{
    const bool obj = OIIO::Strutil::iends_with(path, ".obj");
    if (!obj && !OIIO::Strutil::iends_with(path, ".ply")) {
        what = "is not a mesh texsyn reads (.obj or .ply)";
        return false;
    }
    MeshFileCounts counts;
    if (!(obj ? prescan_obj(path, counts, what) : prescan_ply(path, counts, what)))
        return false;

    RecordingImporter importer;
    OpenMesh::IO::Options options
        = obj ? OpenMesh::IO::Options::FaceTexCoord : OpenMesh::IO::Options::VertexTexCoord;
    bool read;
    {
        QuietOpenMeshRead quiet;
        read = OpenMesh::IO::IOManager().read(path, importer, options);
    }
    if (!read) {
        what = std::string("cannot be read as ") + (obj ? "OBJ" : "PLY") + " by OpenMesh";
        return false;
    }
    if (!check_polygons(importer, counts, what))
        return false;
    build_mesh(importer, counts.face_texcoords, mesh);
    return true;
}

} // namespace

bool read_surface_mesh(const std::string& path, SurfaceMesh& mesh, std::string& error)
{
    mesh = SurfaceMesh();
    if (!check_regular_file(path, "a mesh", error))
        return false;
    std::string what;
    bool ok;
    try {
        ok = read_checked_mesh(path, mesh, what);
    } catch (const std::bad_alloc&) {
        ok = false;
        what = "is too large to read into memory";
    } catch (const std::exception& e) {
        ok = false;
        what = std::string("cannot be read (") + e.what() + ")";
    }
    if (ok && check_surface_mesh(mesh, path, error))
        return true;
    if (!ok) {
        // Messages quote the file (a line, a header keyword): its control characters, a
        // binary file's bytes, are shown as '?' so that the message stays one line.
        for (char& c : what)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                c = '?';
        error = path + ": " + what;
    }
    mesh = SurfaceMesh();
    return false;
}

} // namespace texsyn::detail
