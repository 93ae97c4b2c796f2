// SPDX-License-Identifier: Apache-2.0
// Analysis files: exact round trip, synthesis from a file bit-identical to synthesis from
// the sample, and rejection of every kind of damaged file (plus a mutation fuzz).
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/stats.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "test_samples.h"

using namespace texsyn;
namespace fs = std::filesystem;

namespace {

constexpr size_t magic_size = 16;

OIIO::ImageBuf small_sample(int size)
{
    OIIO::ImageBuf full = test::linear_sample("rust.png");
    return OIIO::ImageBufAlgo::cut(full, OIIO::ROI(0, size, 0, size));
}

TextureStatistics analysis_of(const OIIO::ImageBuf& sample, const PyramidOptions& opt)
{
    TextureStatistics stats;
    std::string error;
    EXPECT_TRUE(analyze_texture(sample, opt, stats, error)) << error;
    stats.source = "rust.png";
    stats.colorspace = "sRGB - Texture";
    stats.sample_format = "uint8";
    return stats;
}

std::string file_bytes(const TextureStatistics& stats)
{
    const fs::path p = fs::temp_directory_path() / "texsyn_stats_test.tsa";
    std::string error;
    EXPECT_TRUE(write_statistics(p.string(), stats, error)) << error;
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(p);
    return ss.str();
}

// FNV-1a 64 with the standard offset basis (version 2), or version 1's mistyped one.
uint64_t fnv1a(const std::string& s, size_t n, uint64_t basis = 14695981039346656037ull)
{
    uint64_t h = basis;
    for (size_t i = 0; i < n; ++i) {
        h ^= uint8_t(s[i]);
        h *= 1099511628211ull;
    }
    return h;
}

// Recomputes the trailing checksum, so that a test reaches the checks behind it.
std::string with_valid_checksum(std::string bytes)
{
    if (bytes.size() < 8)
        return bytes;
    const uint64_t h = fnv1a(bytes, bytes.size() - 8);
    std::memcpy(&bytes[bytes.size() - 8], &h, 8);
    return bytes;
}

// The file with its JSON header replaced by `header` (length and checksum fixed up).
std::string with_header(const std::string& bytes, const std::string& header)
{
    uint64_t old_size = 0;
    std::memcpy(&old_size, bytes.data() + magic_size, 8);
    std::string out = bytes.substr(0, magic_size);
    const uint64_t n = header.size();
    out.append(reinterpret_cast<const char*>(&n), 8);
    out += header;
    out += bytes.substr(magic_size + 8 + old_size);
    return with_valid_checksum(out);
}

std::string header_of(const std::string& bytes)
{
    uint64_t n = 0;
    std::memcpy(&n, bytes.data() + magic_size, 8);
    return bytes.substr(magic_size + 8, n);
}

std::string replace_once(std::string s, const std::string& from, const std::string& to)
{
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

// Parses and expects failure with a message containing `what`.
void expect_rejected(const std::string& bytes, const std::string& what)
{
    TextureStatistics stats;
    std::string error;
    EXPECT_FALSE(parse_statistics(bytes, "x.tsa", stats, error));
    EXPECT_NE(error.find(what), std::string::npos) << error;
    EXPECT_EQ(error.rfind("x.tsa: ", 0), 0u) << error;
}

class AnalysisFile : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        PyramidOptions opt;
        opt.scales = 2;
        stats = new TextureStatistics(analysis_of(small_sample(48), opt));
        bytes = new std::string(file_bytes(*stats));
    }
    static void TearDownTestSuite()
    {
        delete stats;
        delete bytes;
    }
    static TextureStatistics* stats;
    static std::string* bytes;
};
TextureStatistics* AnalysisFile::stats = nullptr;
std::string* AnalysisFile::bytes = nullptr;

} // namespace

TEST_F(AnalysisFile, RoundTripIsExact)
{
    TextureStatistics back;
    std::string error;
    ASSERT_TRUE(parse_statistics(*bytes, "x.tsa", back, error)) << error;
    EXPECT_EQ(back.sample_width, 48);
    EXPECT_EQ(back.scales, 2);
    EXPECT_EQ(back.band_names, stats->band_names);
    EXPECT_EQ(back.channel_names, stats->channel_names);
    EXPECT_EQ(back.source, "rust.png");
    EXPECT_EQ(back.colorspace, "sRGB - Texture");
    EXPECT_EQ(back.sample_format, "uint8");
    EXPECT_EQ(back.color.forward, stats->color.forward);
    EXPECT_EQ(back.color.inverse, stats->color.inverse);
    EXPECT_EQ(back.color.mean, stats->color.mean);
    ASSERT_EQ(back.components.size(), stats->components.size());
    for (size_t c = 0; c < back.components.size(); ++c) {
        EXPECT_EQ(back.components[c].mean, stats->components[c].mean);
        EXPECT_EQ(back.components[c].pixels.sorted(), stats->components[c].pixels.sorted());
        ASSERT_EQ(back.components[c].bands.size(), stats->components[c].bands.size());
        for (size_t b = 0; b < back.components[c].bands.size(); ++b)
            EXPECT_EQ(back.components[c].bands[b].sorted(), stats->components[c].bands[b].sorted());
        EXPECT_EQ(back.channels[c].sorted(), stats->channels[c].sorted());
    }
}

TEST(AnalysisFileSynthesis, FromTheFileIsBitIdenticalToFromTheSample)
{
    const OIIO::ImageBuf sample = small_sample(64);
    for (PyramidKind kind : { PyramidKind::Steerable, PyramidKind::Laplacian }) {
        PyramidOptions analysis;
        analysis.pyramid = kind;
        TextureStatistics stats;
        std::string error;
        ASSERT_TRUE(
            parse_statistics(file_bytes(analysis_of(sample, analysis)), "x.tsa", stats, error))
            << error;
        // An output larger than the sample: the sample decides the scales either way.
        PyramidOptions opt = analysis;
        opt.width = 160;
        opt.height = 96;
        opt.iterations = 2;
        opt.seed = 7;
        OIIO::ImageBuf from_file, from_sample;
        ASSERT_TRUE(synthesize_from_statistics(from_file, stats, opt)) << from_file.geterror();
        ASSERT_TRUE(pyramid_synthesize(from_sample, sample, opt)) << from_sample.geterror();
        EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(from_file),
            OIIO::ImageBufAlgo::computePixelHashSHA1(from_sample));
    }
}

TEST_F(AnalysisFile, SettingsThatDisagreeWithTheAnalysisAreRefused)
{
    PyramidOptions opt;
    opt.iterations = 1;
    OIIO::ImageBuf out;
    opt.pyramid = PyramidKind::Laplacian;
    EXPECT_FALSE(synthesize_from_statistics(out, *stats, opt));
    EXPECT_EQ(out.geterror(), "pyramid=laplacian : differs from the analysis (pyramid=steerable)");
    opt = PyramidOptions();
    opt.scales = 3;
    EXPECT_FALSE(synthesize_from_statistics(out, *stats, opt));
    EXPECT_EQ(out.geterror(), "scales=3 : differs from the analysis (scales=2)");
    opt = PyramidOptions();
    opt.width = opt.height = 3;
    EXPECT_FALSE(synthesize_from_statistics(out, *stats, opt));
    EXPECT_EQ(out.geterror(), "size=3x3 is too small for 2 scales (each side at least 4)");
}

TEST_F(AnalysisFile, DamagedFilesAreRejected)
{
    expect_rejected("P6\n32 32\n255\n", "not a texsyn analysis file");
    expect_rejected("", "not a texsyn analysis file");
    expect_rejected(bytes->substr(0, 20), "truncated");
    for (size_t cut : { bytes->size() - 1, bytes->size() / 2, size_t(40), size_t(magic_size + 8) })
        expect_rejected(bytes->substr(0, cut), "");
    std::string flipped = *bytes;
    flipped[flipped.size() / 2] ^= 0x40;
    expect_rejected(flipped, "checksum mismatch");
    // A truncated file whose checksum happens to fit is caught by the sizes.
    expect_rejected(with_valid_checksum(bytes->substr(0, bytes->size() - 12)), "the tables hold");
}

TEST_F(AnalysisFile, TheChecksumIsStandardFnv1a64)
{
    // The last 8 bytes are FNV-1a 64 (offset basis 14695981039346656037) of the rest: the
    // hash any standard implementation computes.
    uint64_t stored = 0;
    std::memcpy(&stored, bytes->data() + bytes->size() - 8, 8);
    EXPECT_EQ(stored, fnv1a(*bytes, bytes->size() - 8));
    EXPECT_NE(header_of(*bytes).find("\"version\":2"), std::string::npos);
}

TEST_F(AnalysisFile, VersionOneFilesWithTheirOldChecksumAreStillRead)
{
    std::string v1
        = with_header(*bytes, replace_once(header_of(*bytes), "\"version\":2", "\"version\":1"));
    const uint64_t old = fnv1a(v1, v1.size() - 8, 1469598103934665603ull);
    std::memcpy(&v1[v1.size() - 8], &old, 8);
    TextureStatistics back;
    std::string error;
    EXPECT_TRUE(parse_statistics(v1, "v1.tsa", back, error)) << error;
    // A version 1 header under a version 2 checksum (or the reverse) is damage.
    expect_rejected(
        with_header(*bytes, replace_once(header_of(*bytes), "\"version\":2", "\"version\":1")),
        "checksum mismatch");
}

TEST_F(AnalysisFile, WrongVersionsAndInconsistentHeadersAreRejected)
{
    const std::string h = header_of(*bytes);
    expect_rejected(with_header(*bytes, replace_once(h, "\"format\":\"", "\"format\":\"int128")),
        "invalid header: sample format 'int128");
    expect_rejected(with_header(*bytes, replace_once(h, "\"version\":2", "\"version\":3")),
        "version 3 (this texsyn reads versions 1 to 2)");
    expect_rejected(with_header(*bytes, replace_once(h, "\"version\":2", "\"version\":\"2\"")),
        "invalid header: version is not an integer");
    expect_rejected(with_header(*bytes, h.substr(0, h.size() - 1)), "malformed header");
    expect_rejected(
        with_header(*bytes, replace_once(h, "\"orientations\":4", "\"orientations\":3")),
        "the band list does not match the pyramid settings");
    expect_rejected(with_header(*bytes, replace_once(h, "\"width\":48", "\"width\":47")),
        "values, the sample 2256 pixels");
    expect_rejected(with_header(*bytes, replace_once(h, "\"scales\":2", "\"scales\":3")),
        "invalid header: scales=3 does not fit the sample size");
    expect_rejected(
        with_header(*bytes, replace_once(h, "\"kind\":\"steerable\"", "\"kind\":\"wavelet\"")),
        "pyramid kind 'wavelet'");
    expect_rejected(
        with_header(*bytes, replace_once(h, "\"alpha_channel\":-1", "\"alpha_channel\":7")),
        "alpha_channel=7 is not a channel");
    expect_rejected(with_header(*bytes, replace_once(h, "\"n\":3", "\"n\":2")),
        "the colour transform has 2 channels, expected 3");
}

TEST_F(AnalysisFile, CountsMustBeNonNegativeIntegersAndKeysUnique)
{
    const std::string h = header_of(*bytes);
    expect_rejected(with_header(*bytes, replace_once(h, "\"pixels\":2304", "\"pixels\":2304.5")),
        "invalid header: pixels is not a count (2304.5)");
    expect_rejected(with_header(*bytes, replace_once(h, "\"pixels\":2304", "\"pixels\":-1")),
        "invalid header: pixels is not a count (-1)");
    expect_rejected(with_header(*bytes, replace_once(h, "\"width\":48", "\"width\":48.0")),
        "invalid header: width is not an integer from -2147483648 to 2147483647 (48.0)");
    expect_rejected(
        with_header(*bytes, replace_once(h, "\"width\":48", "\"width\":1000000000000000000")),
        "invalid header: width is not an integer from -2147483648 to 2147483647 "
        "(1000000000000000000)");
    expect_rejected(
        with_header(*bytes, replace_once(h, "\"version\":2", "\"version\":2,\"version\":2")),
        "malformed header: duplicate key \"version\"");
}

TEST_F(AnalysisFile, UnsortedOrNonFiniteTablesAreRejected)
{
    const size_t payload = magic_size + 8 + header_of(*bytes).size();
    std::string unsorted = *bytes;
    const float big = 1e30f;
    std::memcpy(&unsorted[payload], &big, 4); // the first value of the first table
    expect_rejected(with_valid_checksum(unsorted), "a table is not finite and sorted");
    std::string nan = *bytes;
    const float qnan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&nan[payload + 40], &qnan, 4);
    expect_rejected(with_valid_checksum(nan), "a table is not finite and sorted");
}

TEST_F(AnalysisFile, RandomMutationsNeverCrashAndAreReportedOrConsistent)
{
    // A deterministic mutation fuzz: byte flips, truncations, insertions and header
    // edits, half of them with the checksum repaired so the deeper checks run. Every
    // result must be a clean failure with a message, or a file that parses into
    // consistent statistics.
    uint64_t state = 12345;
    auto next = [&](uint64_t n) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return n ? (state >> 33) % n : 0;
    };
    const size_t header_end = magic_size + 8 + header_of(*bytes).size();
    int accepted = 0;
    for (int i = 0; i < 3000; ++i) {
        std::string m = *bytes;
        switch (next(4)) {
        case 0: // flip bytes anywhere
            for (uint64_t k = 0, n = 1 + next(4); k < n; ++k)
                m[next(m.size())] ^= char(1 + next(255));
            break;
        case 1: // flip bytes in the header
            for (uint64_t k = 0, n = 1 + next(3); k < n; ++k)
                m[magic_size + next(header_end - magic_size)] = char(next(256));
            break;
        case 2: // truncate
            m.resize(next(m.size()));
            break;
        default: // insert bytes
            m.insert(next(m.size()), std::string(1 + next(8), char(next(256))));
            break;
        }
        if (next(2))
            m = with_valid_checksum(m);
        TextureStatistics s;
        std::string error;
        if (parse_statistics(m, "fuzz.tsa", s, error)) {
            ++accepted;
            EXPECT_EQ(int(s.components.size()), s.nchannels());
            EXPECT_EQ(s.channels.size(), s.components.size());
        } else {
            EXPECT_FALSE(error.empty());
            EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        }
    }
    // Most mutations must be caught (the accepted ones changed only free text or values).
    EXPECT_LT(accepted, 300);
}

TEST(AnalysisFileIo, MissingFilesAndNamesAreReported)
{
    TextureStatistics stats;
    std::string error;
    EXPECT_FALSE(read_statistics("/nonexistent/x.tsa", stats, error));
    EXPECT_EQ(error, "/nonexistent/x.tsa: no such file");
    EXPECT_TRUE(is_analysis_filename("a/b/rust.TSA"));
    EXPECT_FALSE(is_analysis_filename("rust.tsa.png"));
}

TEST(AnalysisFileSynthesis, AFlattenedAnalysisSaysSoInTheSynthesisOptions)
{
    PyramidOptions opt;
    opt.scales = 2;
    opt.flatten = 1;
    TextureStatistics stats;
    std::string error;
    ASSERT_TRUE(
        parse_statistics(file_bytes(analysis_of(small_sample(48), opt)), "x.tsa", stats, error))
        << error;
    EXPECT_TRUE(stats.flattened);
    PyramidOptions synth;
    synth.iterations = 1;
    OIIO::ImageBuf out;
    ASSERT_TRUE(synthesize_from_statistics(out, stats, synth)) << out.geterror();
    EXPECT_NE(
        out.spec().get_string_attribute("synth:options").find(":flatten=1"), std::string::npos);
}
