// SPDX-License-Identifier: Apache-2.0
// The optional backend of remesh_isotropic: CGAL's isotropic_remeshing, which is
// GPL-3.0-or-later. Compiled only with -DTEXSYN_WITH_CGAL=ON (a build that is then GPL),
// to compare texsyn's own remesher with it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

void remesh_with_cgal(const SurfaceMesh& input, double length, int iterations, SurfaceMesh& output)
{
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
    Mesh mesh;
    std::vector<Mesh::Vertex_index> handles;
    handles.reserve(input.vertices.size());
    for (const Imath::V3f& v : input.vertices)
        handles.push_back(mesh.add_vertex(Kernel::Point_3(v.x, v.y, v.z)));
    for (const auto& f : input.faces)
        mesh.add_face(handles[f[0]], handles[f[1]], handles[f[2]]);

    // Boundary edges are constraints to CGAL; relaxing them, as texsyn's remesher does,
    // lets their vertices slide along the boundary.
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::isotropic_remeshing(faces(mesh), length, mesh,
        PMP::parameters::number_of_iterations(unsigned(iterations)).relax_constraints(true));
    mesh.collect_garbage();

    output = SurfaceMesh();
    output.vertices.reserve(mesh.number_of_vertices());
    for (Mesh::Vertex_index v : mesh.vertices()) {
        const Kernel::Point_3& p = mesh.point(v);
        output.vertices.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    }
    output.faces.reserve(mesh.number_of_faces());
    for (Mesh::Face_index f : mesh.faces()) {
        std::array<uint32_t, 3> corners {};
        int k = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            corners[k++] = uint32_t(v.idx());
        output.faces.push_back(corners);
    }
}

} // namespace texsyn::detail
