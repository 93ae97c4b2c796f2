// SPDX-License-Identifier: Apache-2.0
// OBJ and PLY files into a SurfaceMesh: the readers (obj_read.cpp, ply_read.cpp) record
// what the file says; here its polygons are checked and fanned into triangles. Nothing is
// repaired: a face another reader would drop or re-attach to copies of its vertices is
// refused (check_surface_mesh), not hidden.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

// Checks the polygons' corners: at least 3, in range, none repeated.
bool check_polygons(const MeshRecord& in, std::string& what)
{
    uint64_t triangles = 0;
    for (size_t f = 0; f < in.polygons(); ++f) {
        const size_t begin = in.polygon_start[f], n = in.polygon_start[f + 1] - begin;
        auto face = [f] { return "face " + std::to_string(f + 1); };
        if (n < 3) {
            what = face() + " has " + std::to_string(n) + " vertices (at least 3)";
            return false;
        }
        triangles += n - 2;
        std::vector<int64_t> sorted(in.corners.begin() + begin, in.corners.begin() + begin + n);
        std::sort(sorted.begin(), sorted.end());
        for (size_t k = 0; k < n; ++k) {
            const int64_t v = in.corners[begin + k];
            if (v < 0 || uint64_t(v) >= in.points.size()) {
                what = face() + " refers to vertex " + std::to_string(v + 1) + ", but the file has "
                    + std::to_string(in.points.size()) + " vertices";
                return false;
            }
            if (k > 0 && sorted[k] == sorted[k - 1]) {
                what = face() + " lists vertex " + std::to_string(sorted[k] + 1) + " twice";
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
void build_mesh(const MeshRecord& in, SurfaceMesh& mesh)
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
            if (!in.corner_uvs.empty())
                mesh.face_uvs.push_back(
                    { uv_of_corner(c[0]), uv_of_corner(c[1]), uv_of_corner(c[2]) });
        }
    }
    if (in.corner_uvs.empty() && in.vertex_uvs.size() == in.points.size() && !in.points.empty()) {
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
    MeshRecord record;
    if (!(obj ? read_obj_record(path, record, what) : read_ply_record(path, record, what))
        || !check_polygons(record, what))
        return false;
    build_mesh(record, mesh);
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
