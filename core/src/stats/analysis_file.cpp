// SPDX-License-Identifier: Apache-2.0
// Analysis files (.tsa), format version 1 (docs/analysis-files.md):
//
//   "texsyn-analysis\n"            16 bytes, the magic
//   header length                  uint64, little-endian
//   header                         UTF-8 JSON (settings, colour transform, table sizes)
//   tables                         float32 little-endian, in the order the header lists
//   checksum                       uint64 little-endian FNV-1a of every byte before it
//
// Tables are the sorted values of each component's histogram and subbands, then of each
// sample channel, so a synthesis from the file is bit-identical to one from the sample.
#include <texsyn/stats.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

#include "recipe/json_depth_pvt.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "analysis files are little-endian");

namespace texsyn {

namespace {

constexpr char magic[] = "texsyn-analysis\n"; // 16 bytes without the terminator
constexpr size_t magic_size = sizeof(magic) - 1;
constexpr uint64_t max_header_bytes = 16u << 20;
constexpr int max_side = 1 << 16;

uint64_t fnv1a(const char* data, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; ++i) {
        h ^= uint8_t(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

void append_u64(std::string& out, uint64_t v)
{
    char b[8];
    std::memcpy(b, &v, 8);
    out.append(b, 8);
}

uint64_t read_u64(const char* p)
{
    uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

void append_table(std::string& out, const QuantileTable& t)
{
    out.append(reinterpret_cast<const char*>(t.sorted().data()), t.sorted().size() * sizeof(float));
}

nlohmann::ordered_json header_of(const TextureStatistics& s)
{
    nlohmann::ordered_json j;
    j["version"] = analysis_file_version;
    j["sample"] = { { "width", s.sample_width }, { "height", s.sample_height },
        { "source", s.source }, { "colorspace", s.colorspace }, { "format", s.sample_format },
        { "flattened", s.flattened } };
    j["pyramid"] = { { "kind", pyramid_kind_name(s.pyramid) }, { "scales", s.scales },
        { "orientations", s.orientations }, { "bands", s.band_names } };
    j["channels"] = s.channel_names;
    j["alpha_channel"] = s.alpha_channel;
    j["unassociated_alpha"] = s.unassociated_alpha;
    std::vector<bool> constant(s.color.constant.begin(), s.color.constant.end());
    j["color"] = { { "n", s.color.n }, { "mean", s.color.mean }, { "forward", s.color.forward },
        { "inverse", s.color.inverse }, { "constant", constant } };
    nlohmann::ordered_json comps = nlohmann::ordered_json::array();
    for (const ComponentStatistics& c : s.components) {
        std::vector<size_t> bands;
        for (const QuantileTable& t : c.bands)
            bands.push_back(t.sorted().size());
        comps.push_back({ { "name", c.name }, { "constant", c.constant }, { "mean", c.mean },
            { "pixels", c.pixels.sorted().size() }, { "bands", bands } });
    }
    j["components"] = comps;
    std::vector<size_t> channels;
    for (const QuantileTable& t : s.channels)
        channels.push_back(t.sorted().size());
    j["channel_tables"] = channels;
    return j;
}

// The band names a pyramid of this kind and size has (pyramid.h's naming rule).
std::vector<std::string> expected_band_names(PyramidKind kind, int scales, int orientations)
{
    std::vector<std::string> names;
    if (kind == PyramidKind::Steerable) {
        names.push_back("highpass");
        for (int s = 0; s < scales; ++s)
            for (int o = 0; o < orientations; ++o)
                names.push_back("s" + std::to_string(s) + ".o" + std::to_string(o));
    } else {
        for (int s = 0; s < scales; ++s)
            names.push_back("L" + std::to_string(s));
    }
    names.push_back("lowpass");
    return names;
}

// Reads the header into `s` (no tables yet) and the table sizes, in payload order.
// Throws std::runtime_error with the message on anything inconsistent.
void parse_header(const nlohmann::json& j, TextureStatistics& s, std::vector<size_t>& sizes)
{
    auto fail = [](const std::string& m) { throw std::runtime_error(m); };
    const int version = j.at("version").get<int>();
    if (version != analysis_file_version)
        fail("version " + std::to_string(version) + " (this texsyn reads version "
            + std::to_string(analysis_file_version) + ")");
    const auto& sample = j.at("sample");
    s.sample_width = sample.at("width").get<int>();
    s.sample_height = sample.at("height").get<int>();
    s.source = sample.at("source").get<std::string>();
    s.colorspace = sample.at("colorspace").get<std::string>();
    s.sample_format = sample.at("format").get<std::string>();
    s.flattened = sample.at("flattened").get<bool>();
    if (s.sample_width < 16 || s.sample_height < 16 || s.sample_width > max_side
        || s.sample_height > max_side)
        fail("sample size " + std::to_string(s.sample_width) + "x" + std::to_string(s.sample_height)
            + " is out of range (16..65536)");
    const auto& pyr = j.at("pyramid");
    const std::string kind = pyr.at("kind").get<std::string>();
    if (kind != "steerable" && kind != "laplacian")
        fail("pyramid kind '" + kind + "' is not steerable or laplacian");
    s.pyramid = kind == "steerable" ? PyramidKind::Steerable : PyramidKind::Laplacian;
    s.scales = pyr.at("scales").get<int>();
    s.orientations = pyr.at("orientations").get<int>();
    if (s.scales < 1 || s.scales > max_pyramid_scales(s.sample_width, s.sample_height))
        fail("scales=" + std::to_string(s.scales) + " does not fit the sample size");
    if (s.orientations < 1 || s.orientations > 8)
        fail("orientations=" + std::to_string(s.orientations) + " is out of range (1..8)");
    s.band_names = pyr.at("bands").get<std::vector<std::string>>();
    if (s.band_names != expected_band_names(s.pyramid, s.scales, s.orientations))
        fail("the band list does not match the pyramid settings");
    s.channel_names = j.at("channels").get<std::vector<std::string>>();
    const int nc = s.nchannels();
    if (nc < 1 || nc > 64)
        fail(std::to_string(nc) + " channels (expected 1..64)");
    s.alpha_channel = j.at("alpha_channel").get<int>();
    if (s.alpha_channel != -1 && (s.alpha_channel < 1 || s.alpha_channel >= nc))
        fail("alpha_channel=" + std::to_string(s.alpha_channel) + " is not a channel");
    s.unassociated_alpha = j.at("unassociated_alpha").get<bool>();

    const auto& color = j.at("color");
    ColorTransform& ct = s.color;
    ct.n = color.at("n").get<int>();
    const int ncolor = s.alpha_channel >= 0 ? s.alpha_channel : nc;
    if (ct.n != ncolor)
        fail("the colour transform has " + std::to_string(ct.n) + " channels, expected "
            + std::to_string(ncolor));
    ct.mean = color.at("mean").get<std::vector<double>>();
    ct.forward = color.at("forward").get<std::vector<double>>();
    ct.inverse = color.at("inverse").get<std::vector<double>>();
    const auto constant = color.at("constant").get<std::vector<bool>>();
    ct.constant.assign(constant.begin(), constant.end());
    if (ct.mean.size() != size_t(ct.n) || ct.forward.size() != size_t(ct.n * ct.n)
        || ct.inverse.size() != size_t(ct.n * ct.n) || ct.constant.size() != size_t(ct.n))
        fail("the colour transform's arrays have the wrong sizes");
    for (const auto* v : { &ct.mean, &ct.forward, &ct.inverse })
        for (double x : *v)
            if (!std::isfinite(x))
                fail("the colour transform has a non-finite value");

    const size_t pixels = size_t(s.sample_width) * size_t(s.sample_height);
    const auto& comps = j.at("components");
    if (!comps.is_array() || comps.size() != size_t(nc))
        fail("expected " + std::to_string(nc) + " components");
    s.components.clear();
    for (const auto& jc : comps) {
        ComponentStatistics c;
        c.name = jc.at("name").get<std::string>();
        c.constant = jc.at("constant").get<bool>();
        c.mean = jc.at("mean").get<float>();
        if (!std::isfinite(c.mean))
            fail("component " + c.name + " has a non-finite mean");
        const size_t npix = jc.at("pixels").get<size_t>();
        const auto bands = jc.at("bands").get<std::vector<size_t>>();
        if (c.constant) {
            if (npix != 0 || !bands.empty())
                fail("constant component " + c.name + " has tables");
        } else {
            if (npix != pixels)
                fail("component " + c.name + "'s histogram has " + std::to_string(npix)
                    + " values, the sample " + std::to_string(pixels) + " pixels");
            if (bands.size() != s.band_names.size())
                fail("component " + c.name + " has " + std::to_string(bands.size())
                    + " band tables, the pyramid " + std::to_string(s.band_names.size())
                    + " bands");
            sizes.push_back(npix);
            for (size_t n : bands) {
                if (n < 1 || n > pixels)
                    fail("component " + c.name + " has a band table of " + std::to_string(n)
                        + " values");
                sizes.push_back(n);
            }
        }
        s.components.push_back(std::move(c));
    }
    const auto channels = j.at("channel_tables").get<std::vector<size_t>>();
    if (channels.size() != size_t(nc))
        fail("expected " + std::to_string(nc) + " channel tables");
    for (size_t n : channels) {
        if (n != pixels)
            fail("a channel table has " + std::to_string(n) + " values, the sample "
                + std::to_string(pixels) + " pixels");
        sizes.push_back(n);
    }
}

// A table of `n` floats at `p`: finite and sorted ascending, or throws.
QuantileTable read_table(const char* p, size_t n)
{
    std::vector<float> v(n);
    std::memcpy(v.data(), p, n * sizeof(float));
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i]) || (i > 0 && v[i] < v[i - 1]))
            throw std::runtime_error("a table is not finite and sorted");
    return QuantileTable::from_sorted(std::move(v));
}

} // namespace

bool is_analysis_filename(const std::string& filename)
{
    return OIIO::Strutil::iends_with(filename, ".tsa");
}

bool write_statistics(
    const std::string& filename, const TextureStatistics& stats, std::string& error)
{
    std::string bytes(magic, magic_size);
    const std::string header = header_of(stats).dump();
    append_u64(bytes, header.size());
    bytes += header;
    for (const ComponentStatistics& c : stats.components) {
        if (c.constant)
            continue;
        append_table(bytes, c.pixels);
        for (const QuantileTable& t : c.bands)
            append_table(bytes, t);
    }
    for (const QuantileTable& t : stats.channels)
        append_table(bytes, t);
    append_u64(bytes, fnv1a(bytes.data(), bytes.size()));

    const std::string temporary = temporary_path_for(filename);
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out) {
            std::remove(temporary.c_str());
            error = filename + ": could not write the analysis file";
            return false;
        }
    }
    return commit_file(temporary, filename, error);
}

bool parse_statistics(
    const std::string& bytes, const std::string& name, TextureStatistics& stats, std::string& error)
{
    auto fail = [&](const std::string& what) {
        error = name + ": " + what;
        return false;
    };
    if (bytes.size() < magic_size || bytes.compare(0, magic_size, magic) != 0)
        return fail("not a texsyn analysis file (no texsyn-analysis signature)");
    if (bytes.size() < magic_size + 16)
        return fail("truncated analysis file");
    const uint64_t header_size = read_u64(bytes.data() + magic_size);
    const size_t header_at = magic_size + 8;
    if (header_size > max_header_bytes || header_size > bytes.size() - header_at - 8)
        return fail("truncated analysis file (header)");
    const size_t payload_at = header_at + size_t(header_size);
    const size_t checksum_at = bytes.size() - 8;
    if (fnv1a(bytes.data(), checksum_at) != read_u64(bytes.data() + checksum_at))
        return fail("corrupted or truncated analysis file (checksum mismatch)");
    constexpr size_t max_depth = 64; // a header needs 3
    if (detail::json_nesting_depth(
            std::string_view(
                reinterpret_cast<const char*>(bytes.data()) + header_at, size_t(header_size)),
            max_depth)
        > max_depth)
        return fail("malformed header: nested more than 64 deep");
    TextureStatistics s;
    std::vector<size_t> sizes;
    try {
        const nlohmann::json header = nlohmann::json::parse(
            bytes.begin() + std::ptrdiff_t(header_at), bytes.begin() + std::ptrdiff_t(payload_at));
        parse_header(header, s, sizes);
    } catch (const nlohmann::json::exception& e) {
        return fail(std::string("malformed header: ") + e.what());
    } catch (const std::exception& e) {
        return fail(std::string("invalid header: ") + e.what());
    }
    size_t total = 0;
    for (size_t n : sizes)
        total += n;
    if (total * sizeof(float) != checksum_at - payload_at)
        return fail("the tables hold " + std::to_string((checksum_at - payload_at) / 4)
            + " values, the header lists " + std::to_string(total));
    const char* p = bytes.data() + payload_at;
    size_t next = 0;
    try {
        auto take = [&]() {
            const size_t n = sizes[next++];
            QuantileTable t = read_table(p, n);
            p += n * sizeof(float);
            return t;
        };
        for (ComponentStatistics& c : s.components) {
            if (c.constant)
                continue;
            c.pixels = take();
            c.bands.resize(s.band_names.size());
            for (QuantileTable& t : c.bands)
                t = take();
        }
        for (int c = 0; c < s.nchannels(); ++c)
            s.channels.push_back(take());
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    stats = std::move(s);
    return true;
}

bool read_statistics(const std::string& filename, TextureStatistics& stats, std::string& error)
{
    if (!check_regular_file(filename, "an analysis file", error))
        return false;
    std::error_code ec;
    const auto size = std::filesystem::file_size(filename, ec);
    if (!ec && size > (uint64_t(8) << 30)) {
        error = filename + ": " + std::to_string(size >> 30)
            + " GB is too large for an analysis file (at most 8 GB)";
        return false;
    }
    std::ifstream in(filename, std::ios::binary);
    if (!in) {
        error = filename + ": cannot open the analysis file";
        return false;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) {
        error = filename + ": could not read the analysis file";
        return false;
    }
    return parse_statistics(ss.str(), filename, stats, error);
}

} // namespace texsyn
