// SPDX-License-Identifier: Apache-2.0
// The fixture of the end-to-end tests: runs the built `texsyn` tool in a scratch directory
// holding a copy of stucco_yellow.png, and checks failures (exit code, first stderr line, no
// output written, input unchanged).
#pragma once

#include <texsyn/io.h>
#include <texsyn/recipe.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace texsyn;

namespace {

struct CliRun {
    int status = -1;
    std::string out, err;
    std::string first_err_line() const { return err.substr(0, err.find('\n')); }
};

std::string quote(const std::string& s)
{
    return "'" + s + "'";
}

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

[[maybe_unused]] void spit(const fs::path& p, const std::string& bytes)
{
    std::ofstream(p, std::ios::binary) << bytes;
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path()
            / (std::string("texsyn_cli_") + info->test_suite_name() + "_" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy_file(sample_path("stucco_yellow.png"), dir / "stucco.png");
    }
    void TearDown() override { fs::remove_all(dir); }

    static std::string sample_path(const std::string& name)
    {
        return std::string(TEXSYN_TEST_DATA) + "/" + name;
    }

    // Runs the built tool with `args` in the test directory, `env` (NAME=value ...) set.
    CliRun texsyn(const std::string& args, const std::string& env = "")
    {
        return run_in_dir(env + " " + quote(TEXSYN_EXE) + " " + args);
    }

    // Runs the shell command `command` in the test directory: stock OIIO tools as
    // installed, with texsyn's plugin on their search path.
    CliRun shell(const std::string& command)
    {
        return run_in_dir(
            "export OIIO_LIBRARY_PATH=" + quote(TEXSYN_PLUGIN_DIR) + " && " + command);
    }

    // Runs `command` in the test directory, capturing its exit status, stdout and stderr.
    CliRun run_in_dir(const std::string& command)
    {
        std::string cmd
            = "cd " + quote(dir.string()) + " && " + command + " > stdout.txt 2> stderr.txt";
        CliRun r;
        int rc = std::system(cmd.c_str());
        r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
        r.out = slurp(dir / "stdout.txt");
        r.err = slurp(dir / "stderr.txt");
        fs::remove(dir / "stdout.txt");
        fs::remove(dir / "stderr.txt");
        return r;
    }

    // Files in the test directory other than the given inputs.
    std::vector<std::string> outputs(std::initializer_list<std::string> inputs = { "stucco.png" })
    {
        std::vector<std::string> names;
        for (auto& e : fs::directory_iterator(dir)) {
            std::string n = e.path().filename().string();
            if (std::find(inputs.begin(), inputs.end(), n) == inputs.end())
                names.push_back(n);
        }
        return names;
    }

    void expect_failure(const std::string& args, const std::string& first_line,
        std::initializer_list<std::string> inputs = { "stucco.png" })
    {
        expect_failure_starting(args, first_line, inputs, true);
    }

    // expect_failure for a message whose end depends on the machine (memory sizes): the
    // first stderr line starts with `prefix` (or is it, with `whole_line`).
    void expect_failure_starting(const std::string& args, const std::string& prefix,
        std::initializer_list<std::string> inputs = { "stucco.png" }, bool whole_line = false)
    {
        std::string before = slurp(dir / "stucco.png");
        CliRun r = texsyn(args);
        EXPECT_EQ(r.status, 1) << args;
        if (whole_line)
            EXPECT_EQ(r.first_err_line(), prefix) << args;
        else
            EXPECT_EQ(r.first_err_line().find(prefix), 0u) << args << ": " << r.err;
        EXPECT_TRUE(outputs(inputs).empty()) << args << ": left " << outputs(inputs)[0];
        EXPECT_EQ(slurp(dir / "stucco.png"), before) << args << " modified its input";
    }

    OIIO::ImageBuf read(const std::string& name)
    {
        OIIO::ImageBuf buf;
        std::string error;
        EXPECT_TRUE(read_image((dir / name).string(), buf, error)) << error;
        return buf;
    }

    // The pixel type stored in the file.
    OIIO::TypeDesc file_type(const std::string& name)
    {
        auto in = OIIO::ImageInput::open((dir / name).string());
        return in ? in->spec().format : OIIO::TypeUnknown;
    }

    // The pixels of an image as stored, hashed.
    static std::string pixel_hash(const OIIO::ImageBuf& buf)
    {
        std::vector<float> px(size_t(buf.spec().image_pixels()) * size_t(buf.nchannels()));
        EXPECT_TRUE(buf.get_pixels(buf.roi(), OIIO::TypeFloat, px.data()));
        return OIIO::Strutil::fmt::format("{:016x}",
            OIIO::Strutil::strhash(std::string_view(
                reinterpret_cast<const char*>(px.data()), px.size() * sizeof(float))));
    }

    // Checks the source map `map` written with `image`, a synthesis of `sample` stored in
    // the same encoding: a 2-channel float "x", "y" OpenEXR naming the sample and its size,
    // each pixel naming the sample pixel `image` holds there (exactly), which --apply-map
    // turns the sample into `image`.
    void expect_source_map(const std::string& map, const std::string& image,
        const std::string& sample, const std::string& method)
    {
        OIIO::ImageBuf out = read(image), coords = read(map), in = read(sample);
        ASSERT_EQ(coords.nchannels(), 2);
        EXPECT_EQ(coords.spec().channelnames, (std::vector<std::string> { "x", "y" }));
        EXPECT_EQ(file_type(map), OIIO::TypeFloat);
        EXPECT_EQ(coords.spec().get_string_attribute("synth:sample_size"),
            std::to_string(in.spec().width) + "x" + std::to_string(in.spec().height));
        EXPECT_EQ(coords.spec().get_string_attribute("synth:sample"), sample);
        EXPECT_EQ(coords.spec().get_string_attribute("synth:method"), method);
        const int nc = out.nchannels();
        ASSERT_EQ(in.nchannels(), nc);
        std::vector<float> a(static_cast<size_t>(nc)), b(a);
        for (int y = 0; y < out.spec().height; ++y)
            for (int x = 0; x < out.spec().width; ++x) {
                float xy[2];
                coords.getpixel(x, y, xy, 2);
                out.getpixel(x, y, a.data(), nc);
                in.getpixel(int(xy[0]), int(xy[1]), b.data(), nc);
                ASSERT_EQ(a, b) << image << " " << x << "," << y;
            }
        const std::string again = "again_" + image;
        CliRun r = texsyn("--apply-map " + map + " " + sample + " -o " + again);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(pixel_hash(read(again)), pixel_hash(out));
        fs::remove(dir / again);
    }

    // Runs `args`: a synthesis of stucco.png by `method`, with map=, written by
    // `-d float -o out.exr --recipe r.texsyn`. Checks that the recipe names the method but not
    // the tool's map=, and that run_recipe() makes out.exr's pixels and synth:options;
    // returns the recipe.
    Recipe expect_recipe_remakes_the_output(const std::string& args, const std::string& method)
    {
        Recipe recipe;
        CliRun r = texsyn(args);
        EXPECT_EQ(r.status, 0) << r.err;
        const std::string json = slurp(dir / "r.texsyn");
        EXPECT_NE(json.find("\"method\": \"" + method + "\""), std::string::npos) << json;
        EXPECT_EQ(json.find("map"), std::string::npos) << json; // the tool's, not the method's
        std::string error;
        EXPECT_TRUE(recipe_from_filename((dir / "r.texsyn").string(), recipe, error)) << error;
        EXPECT_EQ(recipe.method, method);
        EXPECT_EQ(recipe.samples, (std::vector<std::string> { (dir / "stucco.png").string() }));
        EXPECT_FALSE(recipe.subbands);
        OIIO::ImageBuf again, out = read("out.exr");
        EXPECT_TRUE(run_recipe(recipe, again, nullptr, error)) << error;
        EXPECT_EQ(pixel_hash(again), pixel_hash(out));
        EXPECT_EQ(again.spec().get_string_attribute("synth:options"),
            out.spec().get_string_attribute("synth:options"));
        return recipe;
    }

    void write_sample(
        const std::string& name, int nchannels, OIIO::TypeDesc type, float special = 0.0f)
    {
        OIIO::ImageSpec spec(32, 32, nchannels, OIIO::TypeFloat);
        OIIO::ImageBuf buf(spec);
        OIIO::ImageBufAlgo::noise(buf, "uniform", 0.1f, 0.9f, false, 5);
        if (special != 0.0f) {
            std::vector<float> px(nchannels, special);
            buf.setpixel(3, 4, px.data());
        }
        ASSERT_TRUE(buf.write((dir / name).string(), type)) << buf.geterror();
    }

    fs::path dir;
};

} // namespace
