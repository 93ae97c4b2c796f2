// SPDX-License-Identifier: Apache-2.0
#include <texsyn/error_text.h>
#include <texsyn/options.h>
#include <texsyn/pyramid_synthesis.h>

#include <gtest/gtest.h>

using namespace texsyn;

TEST(Options, ParsesEveryPyramidOptionByName)
{
    PyramidOptions opt;
    std::string error;
    const auto& t = PyramidOptions::table();
    ASSERT_TRUE(t.set(opt, "size", "640x480", error)) << error;
    ASSERT_TRUE(t.set(opt, "iterations", "3", error)) << error;
    ASSERT_TRUE(t.set(opt, "pyramid", "laplacian", error)) << error;
    ASSERT_TRUE(t.set(opt, "scales", "3", error)) << error;
    ASSERT_TRUE(t.set(opt, "orientations", "6", error)) << error;
    ASSERT_TRUE(t.set(opt, "histogram", "bins256", error)) << error;
    EXPECT_EQ(opt.width, 640);
    EXPECT_EQ(opt.height, 480);
    EXPECT_EQ(opt.iterations, 3);
    EXPECT_EQ(opt.pyramid, PyramidKind::Laplacian);
    EXPECT_EQ(opt.orientations, 6);
    EXPECT_EQ(opt.histogram, HistogramMode::Bins256);
    EXPECT_EQ(t.format(opt),
        "size=640x480:iterations=3:pyramid=laplacian:scales=3:"
        "orientations=6:histogram=bins256:fft=kiss:gain=1:balance=0:flatten=0");
}

TEST(Options, DefaultsAreThePapers)
{
    PyramidOptions opt;
    EXPECT_EQ(opt.iterations, 5);
    EXPECT_EQ(opt.orientations, 4);
    EXPECT_EQ(opt.pyramid, PyramidKind::Steerable);
    EXPECT_EQ(opt.histogram, HistogramMode::Exact);
    std::string error;
    EXPECT_TRUE(opt.validate(error)) << error;
}

TEST(Options, RejectsMalformedValuesWithoutChangingTheStruct)
{
    PyramidOptions opt;
    std::string error;
    const auto& t = PyramidOptions::table();
    EXPECT_FALSE(t.set(opt, "size", "abc", error));
    EXPECT_EQ(error, "size=abc : not a size (expected WxH, e.g. 1024x1024)");
    EXPECT_FALSE(t.set(opt, "size", "0x10", error));
    EXPECT_EQ(error, "size=0x10 : out of range 1..1048576 (each side)");
    EXPECT_FALSE(t.set(opt, "iterations", "-1", error));
    EXPECT_EQ(error, "iterations=-1 : out of range 0..100");
    EXPECT_FALSE(t.set(opt, "orientations", "99", error));
    EXPECT_EQ(error, "orientations=99 : out of range 1..8");
    EXPECT_FALSE(t.set(opt, "iterations", "5x", error));
    EXPECT_EQ(error, "iterations=5x : not an integer");
    // Numbers too large for their type are out of range, not malformed.
    EXPECT_FALSE(t.set(opt, "iterations", "99999999999999999999999", error));
    EXPECT_EQ(error, "iterations=99999999999999999999999 : out of range 0..100");
    EXPECT_FALSE(t.set(opt, "size", "99999999999x8", error));
    EXPECT_EQ(error, "size=99999999999x8 : out of range 1..1048576 (each side)");
    EXPECT_FALSE(t.set(opt, "gain", "1e99", error));
    EXPECT_EQ(error, "gain=1e99 : out of range 0..16");
    EXPECT_FALSE(t.set(opt, "pyramid", "gaussian", error));
    EXPECT_EQ(error, "pyramid=gaussian : not one of steerable|laplacian");
    EXPECT_FALSE(t.set(opt, "levels", "3", error));
    EXPECT_EQ(error.find("levels=3 : unknown option (known: size, iterations,"), 0u) << error;
    EXPECT_EQ(opt.iterations, 5);
    EXPECT_EQ(opt.width, 0);
}

TEST(Options, SplitsModifierStrings)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    ASSERT_TRUE(split_option_string("size=8x8:iterations=2", pairs, error));
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[1].first, "iterations");
    EXPECT_EQ(pairs[1].second, "2");
    ASSERT_TRUE(split_option_string("", pairs, error));
    EXPECT_TRUE(pairs.empty());
    EXPECT_FALSE(split_option_string("size=8x8:iterations", pairs, error));
    EXPECT_EQ(error, "malformed option 'iterations' (expected name=value)");
    EXPECT_FALSE(split_option_string("=3", pairs, error));
}

TEST(Options, FftwIsRefusedWhenNotBuiltIn)
{
    PyramidOptions opt;
    opt.fft = FftBackend::Fftw;
    std::string error;
    EXPECT_EQ(opt.validate(error), fft_backend_available(FftBackend::Fftw));
}

TEST(Options, NumberListsParseAndRoundTrip)
{
    PyramidOptions opt;
    std::string error;
    ASSERT_TRUE(PyramidOptions::table().set(opt, "gain", "1,0.5,1.25", error)) << error;
    EXPECT_EQ(opt.gain, (std::vector<float> { 1.0f, 0.5f, 1.25f }));
    EXPECT_NE(PyramidOptions::table().format(opt).find(":gain=1,0.5,1.25:"), std::string::npos);
    EXPECT_FALSE(PyramidOptions::table().set(opt, "gain", "1,,2", error));
    EXPECT_EQ(error, "gain=1,,2 : not a list of numbers (expected e.g. 1,1,1.5)");
    EXPECT_FALSE(PyramidOptions::table().set(opt, "gain", "1,20", error));
    EXPECT_EQ(error, "gain=1,20 : 20 is out of range 0..16");
    EXPECT_FALSE(PyramidOptions::table().set(opt, "balance", "nan", error));
    EXPECT_EQ(error, "balance=nan : out of range -1..1");
    EXPECT_FALSE(
        PyramidOptions::table().set(opt, "balance", "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0", error));
    EXPECT_EQ(error, "balance=0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 : 17 values (at most 16)");
    EXPECT_EQ(opt.gain, (std::vector<float> { 1.0f, 0.5f, 1.25f })); // unchanged on failure
}

namespace {

struct Inner {
    int n = 1;
};
struct Outer {
    Inner inner;
    std::optional<int> index;
    std::vector<float> list;
};

const OptionTable<Outer>& outer_table()
{
    static const OptionTable<Outer> t = [] {
        static OptionTable<Inner> inner;
        inner.integer("n", &Inner::n, 0, 9, "a number");
        OptionTable<Outer> t;
        t.include(&Outer::inner, inner, { { "n", "the inner number" } });
        t.optional_integer("index", &Outer::index, 0, 3, "an index");
        t.numbers("list", &Outer::list, 0.0f, 1.0f, 4, "none", "a list");
        return t;
    }();
    return t;
}

} // namespace

TEST(Options, IncludedOptionalAndEmptyListFieldsRoundTrip)
{
    const auto& t = outer_table();
    Outer o;
    EXPECT_EQ(t.format(o), "n=1:index=none:list=none");
    EXPECT_EQ(t.fields()[0].help, "the inner number");
    EXPECT_EQ(t.fields()[1].allowed, "0..3|none");
    std::string error;
    ASSERT_TRUE(t.set(o, "n", "7", error)) << error;
    ASSERT_TRUE(t.set(o, "index", "2", error)) << error;
    ASSERT_TRUE(t.set(o, "list", "0.5,0.25", error)) << error;
    EXPECT_EQ(o.inner.n, 7);
    EXPECT_EQ(o.index, 2);
    EXPECT_EQ(t.format(o), "n=7:index=2:list=0.5,0.25");
    EXPECT_FALSE(t.set(o, "index", "4", error));
    EXPECT_EQ(error, "index=4 : out of range 0..3");
    EXPECT_FALSE(t.set(o, "n", "10", error));
    EXPECT_EQ(o.inner.n, 7); // unchanged on failure
    ASSERT_TRUE(t.set(o, "index", "none", error));
    ASSERT_TRUE(t.set(o, "list", "none", error));
    EXPECT_FALSE(o.index.has_value());
    EXPECT_TRUE(o.list.empty());
}

// Error messages echo what the user gave: control characters and bytes that are not UTF-8
// are written as \xHH (valid UTF-8 stays), and words longer than 120 characters are cut
// with their length (a colon ending the word is kept and not counted).
TEST(Options, EchoedTextIsPrintableAndCut)
{
    EXPECT_EQ(printable_text("a\nb\tc"), "a\\x0ab\\x09c");
    EXPECT_EQ(printable_text("caf\xc3\xa9 \xff\xfe \xe2\x82"), "caf\xc3\xa9 \\xff\\xfe \\xe2\\x82");
    EXPECT_EQ(printable_text("\xed\xa0\x80"), "\\xed\\xa0\\x80"); // a UTF-16 surrogate
    const std::string name(5004, 'a');
    EXPECT_EQ(readable_message(name + ": no such file"),
        std::string(60, 'a') + "...(5004 characters): no such file");
    EXPECT_EQ(readable_message("unknown key '" + name + "'"),
        "unknown key '" + std::string(60, 'a') + "...(5004 characters)'");
    EXPECT_EQ(readable_message("short words stay"), "short words stay");
}

// "Did you mean …?" suggests the nearest name within max(2, length/3) edits; a swap of two
// neighbours is one edit, case is ignored, and nothing is suggested for a far word.
TEST(Options, ClosestNameSuggestsANearName)
{
    const std::vector<std::string> options = { "size", "iterations", "scales", "seed" };
    EXPECT_EQ(closest_name("sise", options), "size");
    EXPECT_EQ(closest_name("iteartions", options), "iterations"); // a swap
    EXPECT_EQ(closest_name("Scales", options), "scales");
    EXPECT_EQ(closest_name("itrations", options), "iterations");
    EXPECT_EQ(closest_name("levels", options), "");
    EXPECT_EQ(closest_name("size", options), "");   // a known name needs no suggestion
    EXPECT_EQ(closest_name("sz", options), "size"); // 2 edits, the least limit
    EXPECT_EQ(closest_name("", {}), "");
    const std::vector<std::string> commands = { "--pyramid", "--neighborhood", "--seed" };
    EXPECT_EQ(closest_name("--neighbourhood", commands), "--neighborhood");
    EXPECT_EQ(closest_name("--frobnicate", commands), "");
    EXPECT_EQ(closest_name(std::string(1000, 'a'), commands), "");
}
