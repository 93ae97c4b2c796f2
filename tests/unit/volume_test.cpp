// SPDX-License-Identifier: Apache-2.0
// Volumes: layout, slices, and the two file formats read back with stock APIs (OpenVDB,
// OpenImageIO) and stock tools (oiiotool).
#include <texsyn/volume.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace texsyn;

namespace {

// A value that names its voxel and channel, exactly representable as a float.
float voxel_value(int c, int x, int y, int z)
{
    return float(c * 1000000 + z * 10000 + y * 100 + x) / 1024.0f;
}

PlanarVolume test_volume(int w, int h, int d, std::vector<std::string> names, int alpha)
{
    PlanarVolume v;
    v.channel_names = names;
    v.alpha_channel = alpha;
    for (int c = 0; c < int(names.size()); ++c) {
        Volume ch(w, h, d);
        for (int z = 0; z < d; ++z)
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    ch(x, y, z) = c == alpha ? 0.25f + 0.5f * float((x + y + z) % 2)
                                             : voxel_value(c, x, y, z);
        v.channels.push_back(std::move(ch));
    }
    v.attributes.attribute("synth:method", "solid");
    v.attributes.attribute("synth:seed", 7);
    return v;
}

class VolumeFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / (std::string("texsyn_volume_") + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string path(const std::string& name) const { return (dir / name).string(); }
    fs::path dir;
};

} // namespace

TEST(Volume, LayoutIsXFastestThenYThenZ)
{
    Volume v(4, 3, 2);
    v(1, 2, 1) = 5.0f;
    EXPECT_EQ(v.data()[(1 * 3 + 2) * 4 + 1], 5.0f);
    EXPECT_EQ(v.slab(1)[2 * 4 + 1], 5.0f);
    EXPECT_EQ(v.voxels().width(), 4);
    EXPECT_EQ(v.voxels().height(), 6);
}

TEST(Volume, SlicesOfEveryAxis)
{
    const PlanarVolume pv = test_volume(5, 4, 3, { "R" }, -1);
    const Volume& v = pv.channels[0];
    EXPECT_EQ(slice_count(v, SliceAxis::X), 5);
    EXPECT_EQ(slice_count(v, SliceAxis::Y), 4);
    EXPECT_EQ(slice_count(v, SliceAxis::Z), 3);
    Plane s;
    extract_slice(v, SliceAxis::Z, 2, s); // xy at z = 2
    ASSERT_EQ(s.width(), 5);
    ASSERT_EQ(s.height(), 4);
    EXPECT_EQ(s(3, 1), v(3, 1, 2));
    extract_slice(v, SliceAxis::Y, 1, s); // xz at y = 1
    ASSERT_EQ(s.width(), 5);
    ASSERT_EQ(s.height(), 3);
    EXPECT_EQ(s(4, 2), v(4, 1, 2));
    extract_slice(v, SliceAxis::X, 3, s); // yz at x = 3
    ASSERT_EQ(s.width(), 4);
    ASSERT_EQ(s.height(), 3);
    EXPECT_EQ(s(2, 1), v(3, 2, 1));

    // Adding every slice of an axis once adds the volume to itself.
    for (SliceAxis axis : { SliceAxis::X, SliceAxis::Y, SliceAxis::Z }) {
        Volume sum(5, 4, 3);
        for (int i = 0; i < slice_count(v, axis); ++i) {
            extract_slice(v, axis, i, s);
            add_slice(s, axis, i, sum);
        }
        EXPECT_TRUE(std::equal(v.data(), v.data() + v.size(), sum.data())) << slice_axis_name(axis);
    }
}

TEST(Volume, ExrPartNames)
{
    EXPECT_EQ(volume_exr_part_name(5, 128), "z0005");
    EXPECT_EQ(volume_exr_part_name(9999, 10000), "z9999");
    EXPECT_EQ(volume_exr_part_name(12, 10001), "z00012");
}

TEST_F(VolumeFiles, VdbReadsBackThroughTheOpenVdbApi)
{
    const int w = 12, h = 9, d = 5;
    const PlanarVolume v = test_volume(w, h, d, { "R", "G", "B", "A" }, 3);
    std::string error;
    ASSERT_TRUE(write_volume_vdb(path("v.vdb"), v, error)) << error;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
        << "a temporary file was left behind";

    openvdb::initialize();
    openvdb::io::File file(path("v.vdb"));
    file.open();
    auto meta = file.getMetadata();
    EXPECT_EQ(meta->metaValue<std::string>("synth:method"), "solid");
    EXPECT_EQ(meta->metaValue<int32_t>("synth:seed"), 7);
    auto cd = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("Cd"));
    auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    file.close();
    ASSERT_TRUE(cd);
    ASSERT_TRUE(density);
    EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
    // Dense: every voxel of the block is active, including those equal to the background.
    EXPECT_EQ(cd->activeVoxelCount(), openvdb::Index64(w * h * d));
    EXPECT_EQ(density->activeVoxelCount(), openvdb::Index64(w * h * d));
    const openvdb::CoordBBox bounds = cd->evalActiveVoxelBoundingBox();
    EXPECT_EQ(bounds.min(), openvdb::Coord(0, 0, 0));
    EXPECT_EQ(bounds.max(), openvdb::Coord(w - 1, h - 1, d - 1));
    EXPECT_EQ(cd->voxelSize(), openvdb::Vec3d(1.0));
    auto acc = cd->getConstAccessor();
    auto dacc = density->getConstAccessor();
    for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const openvdb::Coord ijk(x, y, z);
                const openvdb::Vec3s c = acc.getValue(ijk);
                for (int k = 0; k < 3; ++k)
                    ASSERT_EQ(c[k], voxel_value(k, x, y, z)) << x << " " << y << " " << z;
                ASSERT_EQ(dacc.getValue(ijk), v.channels[3](x, y, z));
            }
}

TEST_F(VolumeFiles, GreyVdbFillsCdAndExtraChannelsGetTheirOwnGrids)
{
    const PlanarVolume v = test_volume(4, 4, 4, { "Y", "A", "Z" }, 1);
    std::string error;
    ASSERT_TRUE(write_volume_vdb(path("g.vdb"), v, error)) << error;
    openvdb::initialize();
    openvdb::io::File file(path("g.vdb"));
    file.open();
    auto cd = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("Cd"));
    auto z = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("Z"));
    EXPECT_TRUE(file.hasGrid("density"));
    file.close();
    ASSERT_TRUE(cd && z);
    const openvdb::Vec3s c = cd->getConstAccessor().getValue(openvdb::Coord(1, 2, 3));
    EXPECT_EQ(c, openvdb::Vec3s(voxel_value(0, 1, 2, 3)));
    EXPECT_EQ(z->getConstAccessor().getValue(openvdb::Coord(1, 2, 3)), voxel_value(2, 1, 2, 3));
}

TEST_F(VolumeFiles, StockOiiotoolReadsTheVdb)
{
    const PlanarVolume v = test_volume(16, 8, 4, { "R", "G", "B" }, -1);
    std::string error;
    ASSERT_TRUE(write_volume_vdb(path("v.vdb"), v, error)) << error;
    const std::string out = path("info.txt");
    ASSERT_EQ(std::system(("oiiotool --info -v " + path("v.vdb") + " > " + out).c_str()), 0);
    std::string info;
    {
        FILE* f = std::fopen(out.c_str(), "r");
        char buf[4096];
        size_t n;
        while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0)
            info.append(buf, n);
        std::fclose(f);
    }
    // OIIO's first line gives the index bounds rounded up to its tiles; the display size
    // and the voxel count are the block's.
    EXPECT_NE(info.find("channel list: Cd.r, Cd.g, Cd.b"), std::string::npos) << info;
    EXPECT_NE(info.find("full/display size: 16 x 8 x 4"), std::string::npos) << info;
    EXPECT_NE(info.find("openvdb:file_voxel_count: 512"), std::string::npos) << info;
}

TEST_F(VolumeFiles, SliceExrReadsBackThroughOiio)
{
    const int w = 6, h = 5, d = 11;
    const PlanarVolume v = test_volume(w, h, d, { "R", "G", "B", "A" }, 3);
    std::string error;
    ASSERT_TRUE(write_volume_exr(path("v.exr"), v, OIIO::TypeFloat, error)) << error;
    auto in = OIIO::ImageInput::open(path("v.exr"));
    ASSERT_TRUE(in);
    int parts = 0;
    while (in->seek_subimage(parts, 0)) {
        const OIIO::ImageSpec& spec = in->spec();
        EXPECT_EQ(spec.get_string_attribute("oiio:subimagename"), volume_exr_part_name(parts, d));
        EXPECT_EQ(spec.width, w);
        EXPECT_EQ(spec.height, h);
        EXPECT_EQ(spec.full_width, w);
        EXPECT_EQ(spec.channelnames, (std::vector<std::string> { "R", "G", "B", "A" }));
        EXPECT_EQ(spec.get_string_attribute("synth:method"), "solid");
        EXPECT_EQ(spec.get_int_attribute("synth:seed"), 7);
        std::vector<float> px(size_t(w) * h * 4);
        ASSERT_TRUE(in->read_image(parts, 0, 0, 4, OIIO::TypeFloat, px.data()));
        const int z = parts;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float* p = &px[(size_t(y) * w + x) * 4];
                const float a = v.channels[3](x, y, z);
                ASSERT_EQ(p[3], a);
                // OpenEXR stores colour associated with alpha.
                for (int c = 0; c < 3; ++c)
                    ASSERT_EQ(p[c], voxel_value(c, x, y, z) * a);
            }
        ++parts;
    }
    EXPECT_EQ(parts, d);
}

TEST_F(VolumeFiles, UnwritableFilesFailWithAMessage)
{
    const PlanarVolume v = test_volume(4, 4, 4, { "R", "G", "B" }, -1);
    std::string error;
    EXPECT_FALSE(write_volume_vdb(path("no/such/dir/v.vdb"), v, error));
    EXPECT_NE(error.find("no/such/dir/v.vdb"), std::string::npos) << error;
    EXPECT_FALSE(write_volume_exr(path("no/such/dir/v.exr"), v, OIIO::TypeHalf, error));
    EXPECT_NE(error.find("no/such/dir/v.exr"), std::string::npos) << error;
}
