// SPDX-License-Identifier: Apache-2.0
// --choosy-surface end to end: the PLY it writes, determinism at any thread count, and bad
// meshes and settings refused with one line, exit 1 and no output.
#include <cstring>
#include <sys/stat.h>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace {

std::string mesh_path(const std::string& name)
{
    return (fs::path(TEXSYN_TEST_DATA).parent_path() / "meshes" / name).string();
}

// A PLY file's header (up to end_header) and the size of what follows.
struct PlyFile {
    std::string header;
    size_t body_bytes = 0;
};

PlyFile split_ply(const std::string& bytes)
{
    const size_t end = bytes.find("end_header\n");
    if (end == std::string::npos)
        return {};
    return { bytes.substr(0, end + 11), bytes.size() - end - 11 };
}

} // namespace

class SurfaceCli : public Cli {
protected:
    void SetUp() override
    {
        Cli::SetUp();
        fs::copy_file(sample_path("flowers.png"), dir / "flowers.png");
        fs::copy_file(mesh_path("sphere.obj"), dir / "sphere.obj");
    }
};

// The mesh is the sphere's 1,620 faces subdivided twice; each face carries the sample's
// channels as floats and 8-bit sRGB colours for viewers.
TEST_F(SurfaceCli, WritesAFaceColouredPly)
{
    CliRun r = texsyn("-v flowers.png --choosy-surface:mesh=sphere.obj:levels=3 -o sphere.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("25920 faces from 1620"), std::string::npos) << r.err;
    const PlyFile ply = split_ply(slurp(dir / "sphere.ply"));
    ASSERT_FALSE(ply.header.empty());
    EXPECT_NE(ply.header.find("format binary_little_endian 1.0\n"), std::string::npos);
    EXPECT_NE(ply.header.find("element face 25920\n"), std::string::npos) << ply.header;
    for (const char* property : { "property float R\n", "property float G\n", "property float B\n",
             "property uchar red\n", "property uchar blue\n" })
        EXPECT_NE(ply.header.find(property), std::string::npos) << property << ply.header;
    // Vertices: V - E + F = 2 for a sphere, E = 3F/2.
    const size_t vertices = 25920 / 2 + 2;
    EXPECT_NE(
        ply.header.find("element vertex " + std::to_string(vertices) + "\n"), std::string::npos)
        << ply.header;
    EXPECT_EQ(ply.body_bytes, vertices * 12 + 25920 * (1 + 12 + 12 + 3));
}

TEST_F(SurfaceCli, SameSeedSameMeshAtAnyThreadCount)
{
    const std::string run = "flowers.png --choosy-surface:mesh=sphere.obj:levels=3 -o ";
    ASSERT_EQ(texsyn("--seed 5 --threads 1 " + run + "one.ply").status, 0);
    ASSERT_EQ(texsyn("--seed 5 --threads 2 " + run + "two.ply").status, 0);
    ASSERT_EQ(texsyn("--seed 6 --threads 2 " + run + "other.ply").status, 0);
    EXPECT_EQ(slurp(dir / "one.ply"), slurp(dir / "two.ply"));
    EXPECT_NE(slurp(dir / "one.ply"), slurp(dir / "other.ply"));
}

// Every bad mesh the issue lists: one line naming the file and the fault, exit 1, no
// output file, the inputs untouched.
TEST_F(SurfaceCli, BadMeshesAreRefusedWithOneLine)
{
    struct Case {
        const char* name;
        std::string text;  // the OBJ file
        const char* fault; // part of the message
    };
    const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    const std::vector<Case> cases = {
        { "empty.obj", "", "no faces" },
        { "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n",
            "line 3" },
        { "missing.obj", tetra + "f 1 3 2\nf 1 2 4\nf 2 3 9\nf 3 1 4\n", "vertex 9" },
        { "zero_area.obj", tetra + "v 2 0 0\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 1 2 5\n", "" },
        { "nonmanifold.obj", tetra + "v 1 1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 1 2 5\n", "" },
        { "two_parts.obj",
            tetra
                + "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
                  "f 5 7 6\nf 5 6 8\nf 6 7 8\nf 7 5 8\n",
            "component" },
        { "truncated.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty "
            "float x\nproperty float y\nproperty float z\nelement face 4\nproperty "
            "list uchar int vertex_indices\nend_header\n\x01\x02",
            "" },
        { "mesh.stl", tetra, "" },
        { "nan.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1e39 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n",
            "line 12: '0 1e39 0': vertex 3's y: '1e39' is not a finite number" },
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        spit(dir / c.name, c.text);
        const std::string args
            = std::string("flowers.png --choosy-surface:mesh=") + c.name + ":levels=2 -o out.ply";
        CliRun r = texsyn(args);
        EXPECT_EQ(r.status, 1) << r.err;
        const std::string line = r.first_err_line();
        EXPECT_EQ(r.err, line + "\n") << "more than one line";
        EXPECT_EQ(
            line.find(std::string("texsyn ERROR: --choosy-surface : mesh=") + c.name + " : "), 0u)
            << line;
        EXPECT_NE(line.find(c.fault), std::string::npos) << line;
        EXPECT_FALSE(fs::exists(dir / "out.ply"));
        fs::remove(dir / c.name);
    }
}

// An OBJ's material library is never opened (issue #34): one naming a FIFO hung the run.
TEST_F(SurfaceCli, MaterialLibrariesTheMeshNamesAreNotRead)
{
    ASSERT_EQ(mkfifo((dir / "skin.mtl").c_str(), 0600), 0);
    spit(dir / "tetra.obj",
        "mtllib skin.mtl\nusemtl skin\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
    CliRun r = texsyn("flowers.png --choosy-surface:mesh=tetra.obj:levels=2 -o tetra.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(dir / "tetra.ply"));
}

// Quads are split into triangles: a cube of 6 quads grows like a mesh of 12 triangles.
TEST_F(SurfaceCli, PolygonsAreTriangulated)
{
    spit(dir / "cube.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    CliRun r = texsyn("-v flowers.png --choosy-surface:mesh=cube.obj:levels=2 -o cube.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("48 faces from 12"), std::string::npos) << r.err;
}

TEST_F(SurfaceCli, BadSettingsAreRefusedBeforeTheWork)
{
    fs::copy_file(sample_path("bricks.png"), dir / "bricks.png");
    const std::initializer_list<std::string> in
        = { "bricks.png", "flowers.png", "sphere.obj", "stucco.png" };
    expect_failure("flowers.png --choosy-surface -o out.ply",
        "texsyn ERROR: --choosy-surface : mesh= : a mesh file is needed (OBJ or PLY)", in);
    expect_failure("flowers.png --choosy-surface:mesh=none.obj -o out.ply",
        "texsyn ERROR: --choosy-surface : mesh=none.obj : no such file", in);
    fs::create_symlink("loop2.obj", dir / "loop1.obj");
    fs::create_symlink("loop1.obj", dir / "loop2.obj");
    expect_failure("flowers.png --choosy-surface:mesh=loop1.obj -o out.ply",
        "texsyn ERROR: --choosy-surface : mesh=loop1.obj : is a loop of symbolic links",
        { "bricks.png", "flowers.png", "sphere.obj", "stucco.png", "loop1.obj", "loop2.obj" });
    fs::remove(dir / "loop1.obj");
    fs::remove(dir / "loop2.obj");
    expect_failure("flowers.png --choosy-surface:mesh=. -o out.ply",
        "texsyn ERROR: --choosy-surface : mesh=. : is a directory, not a mesh", in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:levels=8 -o out.ply",
        "texsyn ERROR: --choosy-surface : levels=8 is too many for the sample (128x128): it "
        "needs about 7 x 2^(levels-1) = 896 pixels a side",
        in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:remesh=3 -o out.ply",
        "texsyn ERROR: --choosy-surface : remesh=3 : expected 0 (no remesh), 8 and more faces, "
        "or auto",
        in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:remesh=8 -o out.ply",
        "texsyn ERROR: --choosy-surface : remesh=8 : too few faces for this shape: the remeshed "
        "surface is a closed surface whose faces face inwards (negative enclosed volume); faces "
        "must be counter-clockwise seen from outside; ask for more faces",
        in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:isotropic=1 -o out.ply",
        "texsyn ERROR: --choosy-surface : isotropic=1 : unknown option (known: mesh, levels, "
        "iterations, penalty, search, dims, eps, remesh, bake, boundary)",
        in);
    // 51M faces at the finest level: refused from the counts alone, before remeshing.
    expect_failure("bricks.png --choosy-surface:mesh=sphere.obj:levels=6:remesh=50000 -o out.ply",
        "texsyn ERROR: --choosy-surface : levels=6 on 50000 faces (51200000 at the finest level) : "
        "more than 50000000 faces; use fewer levels or remesh= to fewer faces",
        in);
    // A mesh is written as .ply or baked; an image is not a mesh.
    expect_failure("flowers.png -o out.ply",
        "texsyn ERROR: -o out.ply : .ply holds textured meshes (from --choosy-surface); the "
        "current item is an image",
        in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:levels=2 -o out.tsa",
        "texsyn ERROR: -o out.tsa : .tsa holds analyses (from --analyze); the current item is "
        "a textured mesh",
        in);
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:levels=2 --choosy -o out.png",
        "texsyn ERROR: --choosy : the current image is a textured mesh (from --choosy-surface); "
        "it needs a 2-D image",
        in);
    // The sphere has no UVs: no image to write.
    expect_failure("flowers.png --choosy-surface:mesh=sphere.obj:levels=2 -o out.png",
        "texsyn ERROR: -o out.png : the choosy-surface synthesis of flowers.png has no UV bake "
        "(its mesh has no UVs, or bake=0x0); write it as .ply",
        in);
}

// A mesh given as a .ply input is never overwritten by -o.
TEST_F(SurfaceCli, NeverOverwritesTheMesh)
{
    ASSERT_EQ(
        texsyn("flowers.png --choosy-surface:mesh=sphere.obj:levels=1 -o base.ply").status, 0);
    const std::string before = slurp(dir / "base.ply");
    CliRun r = texsyn("flowers.png --choosy-surface:mesh=base.ply:levels=2 -o base.ply");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.first_err_line().find("-o base.ply"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "base.ply"), before);
}

// A mesh with UVs: an image -o receives the UV bake (bake=WxH), tagged like every output,
// in the same run as the PLY.
TEST_F(SurfaceCli, BakesTheUvTexture)
{
    fs::copy_file(mesh_path("torus_uv.obj"), dir / "torus_uv.obj");
    CliRun r = texsyn("-v flowers.png --choosy-surface:mesh=torus_uv.obj:levels=3:bake=96x64 -o "
                      "torus.ply -o torus.exr -o torus.png");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("baked into 1 UDIM tile (100% of the texels"), std::string::npos) << r.err;
    OIIO::ImageBuf exr = read("torus.exr");
    const OIIO::ImageSpec& spec = exr.spec();
    EXPECT_EQ(spec.width, 96);
    EXPECT_EQ(spec.height, 64);
    EXPECT_EQ(spec.channelnames, (std::vector<std::string> { "R", "G", "B" }));
    EXPECT_EQ(spec.get_string_attribute("synth:method"), "choosy-surface");
    EXPECT_EQ(spec.get_string_attribute("synth:sample"), "flowers.png");
    EXPECT_EQ(spec.get_int_attribute("synth:udim"), 1001);
    // The bake's values are the faces' colours, interpolated: within the PLY's range.
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(exr);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(stats.min[c], 0.0f);
        EXPECT_LE(stats.max[c], 1.0f);
        EXPECT_GT(stats.stddev[c], 0.02f) << "a texture, not a flat colour";
    }
    EXPECT_EQ(read("torus.png").spec().width, 96);
    EXPECT_TRUE(fs::exists(dir / "torus.ply"));
}

// UVs over several UDIM tiles: one file per tile, named by <UDIM>; a name without it is
// refused (and nothing is written).
TEST_F(SurfaceCli, UdimTilesNeedUdimInTheName)
{
    // A tetrahedron whose first two faces lie in tile 1001 and the other two in 1002.
    spit(dir / "tetra.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        "vt 0.1 0.1\nvt 0.9 0.1\nvt 0.1 0.9\nvt 1.1 0.1\nvt 1.9 0.1\nvt 1.1 0.9\n"
        "f 1/1 3/2 2/3\nf 1/1 2/2 4/3\nf 2/4 3/5 4/6\nf 3/4 1/5 4/6\n");
    const std::string run = "flowers.png --choosy-surface:mesh=tetra.obj:levels=2:bake=32x32 ";
    CliRun r = texsyn(run + "-o tetra.exr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line(),
        "texsyn ERROR: -o tetra.exr : the mesh's UVs span UDIM tiles 1001, 1002; put <UDIM> in "
        "the name (e.g. texture_<UDIM>.exr) for one file per tile");
    EXPECT_FALSE(fs::exists(dir / "tetra.exr"));
    r = texsyn(run + "-o 'tetra_<UDIM>.exr'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("tetra_1001.exr").spec().get_int_attribute("synth:udim"), 1001);
    EXPECT_EQ(read("tetra_1002.exr").spec().get_int_attribute("synth:udim"), 1002);
}

// The bake is what a recipe of choosy-surface gives: stock oiiotool opens it through the
// plugin with the pixels of the tool's own run.
TEST_F(SurfaceCli, RecipesOpenAsTheBake)
{
    fs::copy_file(mesh_path("torus_uv.obj"), dir / "torus_uv.obj");
    CliRun r = texsyn("--seed 3 flowers.png --choosy-surface:mesh=torus_uv.obj:levels=3:bake=64x64 "
                      "-d float -o torus.exr --recipe torus.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    r = shell("oiiotool torus.texsyn -d float -o again.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(pixel_hash(read("again.exr")), pixel_hash(read("torus.exr")));
    // A mesh without UVs makes no image: refused when the recipe is opened.
    r = shell("iinfo 'flowers.png.texsyn?method=choosy-surface&mesh=sphere.obj'");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("mesh=sphere.obj : has no UVs"), std::string::npos) << r.err;
}

// remesh=auto remeshes an uneven mesh (the cow) to its own face count and keeps an even
// one (the sphere); remesh=0 keeps the cow, with a warning.
TEST_F(SurfaceCli, UnevenMeshesAreRemeshedUnlessTold)
{
    fs::copy_file(mesh_path("cow.obj"), dir / "cow.obj");
    CliRun r = texsyn("-v flowers.png --choosy-surface:mesh=cow.obj:levels=1 -o cow.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string uneven = "the mesh's faces are far from equal, equilateral triangles "
                               "(areas 82x apart, angles 62 degrees apart at the median)";
    EXPECT_NE(r.err.find("remesh=auto: " + uneven
                  + ", so it was first remeshed to 5708 even faces (remesh=0 keeps it)"),
        std::string::npos)
        << r.err;
    r = texsyn("-v flowers.png --choosy-surface:mesh=cow.obj:levels=1:remesh=0 -o cow0.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("5804 faces from 5804"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("WARNING: " + uneven), std::string::npos) << r.err;
    r = texsyn("-v flowers.png --choosy-surface:mesh=sphere.obj:levels=1 -o sphere.ply");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("1620 faces from 1620 (54 same-coloured adjacent base faces)\n"),
        std::string::npos)
        << r.err;
}

// boundary=: the mushroom (one boundary loop) grows differently with wildcards than with the
// face's own value (the default). (A closed mesh grows the same either way:
// SurfaceBoundary.ClosedMeshUnchanged.)
TEST_F(SurfaceCli, BoundarySlotsChangeAMeshWithABoundary)
{
    fs::copy_file(mesh_path("mushroom.obj"), dir / "mushroom.obj");
    for (const char* boundary : { "own", "wildcards" }) {
        CliRun r = texsyn(std::string("--seed 2 flowers.png --choosy-surface:mesh=mushroom.obj:")
            + "levels=2:boundary=" + boundary + " -o " + boundary + ".ply");
        ASSERT_EQ(r.status, 0) << r.err;
    }
    EXPECT_NE(slurp(dir / "own.ply"), slurp(dir / "wildcards.ply"));
}
