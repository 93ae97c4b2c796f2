// SPDX-License-Identifier: Apache-2.0
// The fixture of the end-to-end tests: runs the built `texsyn` tool in a scratch directory
// holding a copy of stucco_yellow.png, and checks failures (exit code, first stderr line, no
// output written, input unchanged).
#pragma once

#include <texsyn/io.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

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

    CliRun texsyn(const std::string& args, const std::string& env = "")
    {
        std::string cmd = "cd " + quote(dir.string()) + " && " + env + " " + quote(TEXSYN_EXE) + " "
            + args + " > stdout.txt 2> stderr.txt";
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
