// SPDX-License-Identifier: Apache-2.0
#include <texsyn/image.h>
#include <texsyn/io.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

using namespace texsyn;

TEST(Image, WrapCoordinateCircular)
{
    EXPECT_EQ(wrap_coordinate(-1, 5, Boundary::Circular), 4);
    EXPECT_EQ(wrap_coordinate(5, 5, Boundary::Circular), 0);
    EXPECT_EQ(wrap_coordinate(-11, 5, Boundary::Circular), 4);
    EXPECT_EQ(wrap_coordinate(3, 5, Boundary::Circular), 3);
}

TEST(Image, WrapCoordinateReflectDoesNotRepeatEdge)
{
    // ... 2 1 | 0 1 2 3 4 | 3 2 ...
    EXPECT_EQ(wrap_coordinate(-1, 5, Boundary::Reflect), 1);
    EXPECT_EQ(wrap_coordinate(-2, 5, Boundary::Reflect), 2);
    EXPECT_EQ(wrap_coordinate(5, 5, Boundary::Reflect), 3);
    EXPECT_EQ(wrap_coordinate(6, 5, Boundary::Reflect), 2);
    EXPECT_EQ(wrap_coordinate(-9, 5, Boundary::Reflect), 1);
    EXPECT_EQ(wrap_coordinate(7, 1, Boundary::Reflect), 0);
}

TEST(Image, RoundTripThroughImageBufKeepsValuesAndNames)
{
    OIIO::ImageSpec spec(4, 3, 4, OIIO::TypeFloat);
    spec.channelnames = { "R", "G", "B", "A" };
    spec.alpha_channel = 3;
    OIIO::ImageBuf buf(spec);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            float a = 0.25f * float(x + 1);
            float px[4] = { 0.1f * x * a, 0.2f * y * a, 0.3f * a, a }; // associated
            buf.setpixel(x, y, px);
        }
    PlanarImage planes;
    std::string error;
    ASSERT_TRUE(planes_from_imagebuf(buf, planes, error)) << error;
    EXPECT_EQ(planes.alpha_channel, 3);
    EXPECT_EQ(planes.ncolor(), 3);
    EXPECT_EQ(planes.channel_names[1], "G");
    // Un-associated on the way in (float rounding of a divide).
    EXPECT_NEAR(planes.channels[2](1, 1), 0.3f, 1e-6f);
    EXPECT_NEAR(planes.channels[0](2, 0), 0.2f, 1e-6f);
    OIIO::ImageBuf back;
    imagebuf_from_planes(planes, back);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(back.getchannel(x, y, 0, c), buf.getchannel(x, y, 0, c), 1e-6f);
}

TEST(Image, NonFinitePixelsAreRejectedWithTheirPosition)
{
    OIIO::ImageBuf buf(OIIO::ImageSpec(3, 3, 1, OIIO::TypeFloat));
    float nan = std::nanf("");
    buf.setpixel(2, 1, &nan);
    PlanarImage planes;
    std::string error;
    EXPECT_FALSE(planes_from_imagebuf(buf, planes, error));
    EXPECT_NE(error.find("pixel (2, 1)"), std::string::npos) << error;
    EXPECT_NE(error.find("NaN"), std::string::npos) << error;
}

TEST(Image, ReadImageReportsMissingAndTruncatedFiles)
{
    OIIO::ImageBuf buf;
    std::string error;
    EXPECT_FALSE(read_image("/nonexistent/x.png", buf, error));
    EXPECT_NE(error.find("no such file"), std::string::npos) << error;

    std::string full = std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png";
    std::string cut = (std::filesystem::temp_directory_path() / "texsyn_truncated.png").string();
    {
        std::ifstream in(full, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream out(cut, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size() / 2));
    }
    EXPECT_FALSE(read_image(cut, buf, error));
    EXPECT_EQ(error.find(cut + ": cannot read image"), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
    std::filesystem::remove(cut);
}

TEST(Image, AtomicWriteLeavesNoTemporaryAndRefusesUnknownFormats)
{
    auto dir = std::filesystem::temp_directory_path() / "texsyn_atomic_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    OIIO::ImageBuf buf(OIIO::ImageSpec(8, 8, 3, OIIO::TypeFloat));
    std::string error;
    ASSERT_TRUE(write_image_atomic(buf, (dir / "a.exr").string(), OIIO::TypeHalf, error)) << error;
    EXPECT_FALSE(
        write_image_atomic(buf, (dir / "a.nosuchformat").string(), OIIO::TypeUnknown, error));
    EXPECT_FALSE(
        write_image_atomic(buf, (dir / "missing" / "a.exr").string(), OIIO::TypeUnknown, error));
    int files = 0;
    for (auto& e : std::filesystem::directory_iterator(dir))
        files += e.path().filename() == "a.exr" ? 1 : 100;
    EXPECT_EQ(files, 1);
    std::filesystem::remove_all(dir);
}
