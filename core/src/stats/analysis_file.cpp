// SPDX-License-Identifier: Apache-2.0
// Analysis files (.tsa), format version 2 (docs/analysis-files.md; version 1 differs only
// in its checksum's offset basis and is still read):
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

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <OpenImageIO/strutil.h>
#include <OpenImageIO/typedesc.h>

#include <texsyn/error_text.h>
#include <texsyn/io.h>
#include <texsyn/options.h>

#include "recipe/json_strict_pvt.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "analysis files are little-endian");

namespace texsyn {

namespace {

constexpr char magic[] = "texsyn-analysis\n"; // 16 bytes without the terminator
constexpr size_t magic_size = sizeof(magic) - 1;
constexpr uint64_t max_header_bytes = 16u << 20;
constexpr int max_side = 1 << 16;

// FNV-1a 64's offset basis, and the mistyped one (a digit short) version 1 files used.
constexpr uint64_t fnv_basis = 14695981039346656037ull;
constexpr uint64_t legacy_fnv_basis = 1469598103934665603ull;

uint64_t fnv1a(const char* data, size_t n, uint64_t basis = fnv_basis)
{
    uint64_t h = basis;
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

// `v` as a count: a non-negative integer ("16384.5" or "-1" are refused, not rounded or
// wrapped). Throws std::runtime_error naming `what`.
size_t count_of(const nlohmann::json& v, const std::string& what)
{
    if (!v.is_number_unsigned())
        throw std::runtime_error(what + " is not a count (" + v.dump() + ")");
    return v.get<size_t>();
}

std::vector<size_t> counts_of(const nlohmann::json& v, const std::string& what)
{
    if (!v.is_array())
        throw std::runtime_error(what + " is not a list of counts");
    std::vector<size_t> counts;
    for (const auto& e : v)
        counts.push_back(count_of(e, what));
    return counts;
}

// `v` as an int: an integer within int's range, or throws naming `what`.
int integer_of(const nlohmann::json& v, const std::string& what)
{
    if (!v.is_number_integer() || v.get<int64_t>() < INT32_MIN || v.get<int64_t>() > INT32_MAX
        || (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT32_MAX)))
        throw std::runtime_error(what + " is not an integer from " + std::to_string(INT32_MIN)
            + " to " + std::to_string(INT32_MAX) + " (" + v.dump() + ")");
    return v.get<int>();
}

// Reads the header into `s` (no tables yet) and the table sizes, in payload order, and
// returns the format version (1 or 2). Throws std::runtime_error with the message on
// anything inconsistent.
int parse_header(const nlohmann::json& j, TextureStatistics& s, std::vector<size_t>& sizes)
{
    auto fail = [](const std::string& m) { throw std::runtime_error(m); };
    const int version = integer_of(j.at("version"), "version");
    if (version != 1 && version != analysis_file_version)
        fail("version " + std::to_string(version) + " (this texsyn reads versions 1 to "
            + std::to_string(analysis_file_version) + ")");
    const auto& sample = j.at("sample");
    s.sample_width = integer_of(sample.at("width"), "width");
    s.sample_height = integer_of(sample.at("height"), "height");
    s.source = sample.at("source").get<std::string>();
    s.colorspace = sample.at("colorspace").get<std::string>();
    s.sample_format = sample.at("format").get<std::string>();
    if (!s.sample_format.empty() && OIIO::TypeDesc(s.sample_format) == OIIO::TypeUnknown)
        fail("sample format '" + s.sample_format
            + "' is not a pixel type (uint8, uint16, half, "
              "float, ...)");
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
    s.scales = integer_of(pyr.at("scales"), "scales");
    s.orientations = integer_of(pyr.at("orientations"), "orientations");
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
    s.alpha_channel = integer_of(j.at("alpha_channel"), "alpha_channel");
    if (s.alpha_channel != -1 && (s.alpha_channel < 1 || s.alpha_channel >= nc))
        fail("alpha_channel=" + std::to_string(s.alpha_channel) + " is not a channel");
    s.unassociated_alpha = j.at("unassociated_alpha").get<bool>();

    const auto& color = j.at("color");
    ColorTransform& ct = s.color;
    ct.n = integer_of(color.at("n"), "n");
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
        const size_t npix = count_of(jc.at("pixels"), "pixels");
        const auto bands = counts_of(jc.at("bands"), "bands");
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
    const auto channels = counts_of(j.at("channel_tables"), "channel_tables");
    if (channels.size() != size_t(nc))
        fail("expected " + std::to_string(nc) + " channel tables");
    for (size_t n : channels) {
        if (n != pixels)
            fail("a channel table has " + std::to_string(n) + " values, the sample "
                + std::to_string(pixels) + " pixels");
        sizes.push_back(n);
    }
    return version;
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
    std::string header;
    try {
        header = header_of(stats).dump();
    } catch (const nlohmann::json::type_error&) { // JSON text is UTF-8
        error = filename
            + ": cannot write the analysis file (the sample's file name or a channel name is "
              "not valid UTF-8)";
        return false;
    }
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

    if (!check_output_destination(filename, error))
        return false;
    const std::string temporary = temporary_path_for(filename);
    std::string reason;
    if (!write_bytes(temporary, bytes, reason)) {
        discard_temporary(temporary);
        error = filename + ": cannot write the analysis file (" + reason + ")";
        return false;
    }
    return commit_file(temporary, filename, error);
}

bool parse_statistics(
    const std::string& bytes, const std::string& name, TextureStatistics& stats, std::string& error)
{
    auto fail = [&](const std::string& what) {
        error = printable_text(name + ": " + what);
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
    const uint64_t stored = read_u64(bytes.data() + checksum_at);
    const bool legacy = fnv1a(bytes.data(), checksum_at, legacy_fnv_basis) == stored;
    if (!legacy && fnv1a(bytes.data(), checksum_at) != stored)
        return fail("corrupted or truncated analysis file (checksum mismatch)");
    nlohmann::json header;
    try {
        header = detail::parse_json_strict(
            std::string_view(bytes.data() + header_at, size_t(header_size)), 64); // needs 3
    } catch (const std::exception& e) {
        return fail(std::string("malformed header: ") + e.what());
    }
    TextureStatistics s;
    std::vector<size_t> sizes;
    try {
        // Version 1 files carry the checksum with version 1's basis, later ones FNV-1a's.
        if ((parse_header(header, s, sizes) == 1) != legacy)
            return fail("corrupted or truncated analysis file (checksum mismatch)");
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
