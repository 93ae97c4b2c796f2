// SPDX-License-Identifier: Apache-2.0
// A face level's derived members: adjacency across edges, faces around vertices,
// centroids, normals, areas and the distances §3.6 and §3.10 use.
#include "face_level_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

void finish_level(FaceLevel& level)
{
    const size_t nf = level.faces.size(), nv = level.vertices.size();
    level.centroid.resize(nf);
    level.normal.resize(nf);
    level.area.resize(nf);
    double edge_sum = 0.0;
    for (size_t f = 0; f < nf; ++f) {
        const Imath::V3f& a = level.vertices[level.faces[f][0]];
        const Imath::V3f& b = level.vertices[level.faces[f][1]];
        const Imath::V3f& c = level.vertices[level.faces[f][2]];
        level.centroid[f] = (a + b + c) / 3.0f;
        const Imath::V3f n = (b - a).cross(c - a);
        const float len = n.length();
        level.area[f] = 0.5f * len;
        level.normal[f] = len > 0.0f ? n / len : Imath::V3f(0.0f, 0.0f, 1.0f);
        edge_sum += double((b - a).length() + (c - b).length() + (a - c).length());
    }
    level.mean_edge_length = nf ? edge_sum / double(3 * nf) : 0.0;

    // Faces around each vertex, in face order.
    level.vertex_face_start.assign(nv + 1, 0);
    for (const auto& face : level.faces)
        for (uint32_t v : face)
            ++level.vertex_face_start[v + 1];
    for (size_t v = 0; v < nv; ++v)
        level.vertex_face_start[v + 1] += level.vertex_face_start[v];
    level.vertex_faces.resize(level.vertex_face_start[nv]);
    std::vector<uint32_t> fill(level.vertex_face_start.begin(), level.vertex_face_start.end() - 1);
    for (size_t f = 0; f < nf; ++f)
        for (uint32_t v : level.faces[f])
            level.vertex_faces[fill[v]++] = uint32_t(f);

    // The face across each edge: the face around its first vertex with the reversed edge.
    level.across.assign(nf, { kNoFace, kNoFace, kNoFace });
    double sum = 0.0, largest = 0.0;
    size_t pairs = 0;
    for (size_t f = 0; f < nf; ++f)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = level.faces[f][size_t(e)], b = level.faces[f][size_t((e + 1) % 3)];
            for (uint32_t i = level.vertex_face_start[a]; i < level.vertex_face_start[a + 1]; ++i) {
                const uint32_t g = level.vertex_faces[i];
                if (g == f)
                    continue;
                const auto& other = level.faces[g];
                for (int k = 0; k < 3; ++k)
                    if (other[size_t(k)] == b && other[size_t((k + 1) % 3)] == a)
                        level.across[f][size_t(e)] = g;
            }
            const uint32_t g = level.across[f][size_t(e)];
            if (g != kNoFace && g > f) {
                const double d = double((level.centroid[f] - level.centroid[g]).length());
                sum += d;
                largest = std::max(largest, d);
                ++pairs;
            }
        }
    level.mean_adjacent_distance = pairs ? sum / double(pairs) : 0.0;
    level.max_adjacent_distance = largest;
}

FacePyramid build_face_pyramid(FaceLevel base, int levels, EdgePoints rule)
{
    FacePyramid pyramid;
    finish_level(base);
    pyramid.colour_conflicts = two_colour(base);
    pyramid.levels.push_back(std::move(base));
    for (int l = 1; l < levels; ++l) {
        FaceLevel finer = subdivide(pyramid.levels.back(), rule);
        pyramid.levels.push_back(std::move(finer));
    }
    return pyramid;
}

} // namespace texsyn::detail
