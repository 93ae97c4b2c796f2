// SPDX-License-Identifier: Apache-2.0
// Mesh files (OBJ and PLY, ASCII and binary): any bytes are refused with one line or read
// into a mesh that passes check_surface_mesh. The first input byte picks the extension
// (even: .obj, odd: .ply); the rest is the file, which the readers take by name.
#include "fuzz_target.h"

#include <unistd.h>

#include <fstream>

#include "surface/surface_mesh_pvt.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    static const std::string stem = "/tmp/texsyn-fuzz-mesh-" + std::to_string(getpid());
    const std::string path = stem + (data[0] % 2 == 0 ? ".obj" : ".ply");
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data) + 1, std::streamsize(size - 1));
    texsyn::detail::SurfaceMesh mesh;
    std::string error;
    const bool read = texsyn::detail::read_surface_mesh(path, mesh, error);
    std::remove(path.c_str());
    if (!read)
        texsyn::fuzz::expect_one_line(error, "mesh");
    else if (!texsyn::detail::check_surface_mesh(mesh, path, error))
        std::abort(); // a mesh read is a mesh checked
    return 0;
}
