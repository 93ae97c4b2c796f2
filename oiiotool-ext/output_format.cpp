// SPDX-License-Identifier: Apache-2.0
#include "output_format.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/strutil.h>

#include "cli_error.h"

namespace texsyn::cli {

namespace {

struct FormatTypes {
    std::vector<std::string> extensions;
    std::vector<OIIO::TypeDesc> types;
};

// The pixel types of the formats texsyn knows; the first is the default.
const std::vector<FormatTypes>& format_table()
{
    using OIIO::TypeFloat;
    using OIIO::TypeHalf;
    using OIIO::TypeUInt16;
    using OIIO::TypeUInt8;
    static const std::vector<FormatTypes> table = {
        { { "exr", "sxr", "mxr" }, { TypeHalf, TypeFloat } },
        { { "hdr", "rgbe" }, { TypeFloat } },
        { { "vdb" }, { TypeFloat } },
        { { "png" }, { TypeUInt8, TypeUInt16 } },
        { { "jpg", "jpeg", "jpe", "jfif" }, { TypeUInt8 } },
        { { "tif", "tiff", "tx" }, { TypeUInt8, TypeUInt16, TypeHalf, TypeFloat } },
    };
    return table;
}

std::string extension(const std::string& filename)
{
    return OIIO::Strutil::lower(OIIO::Filesystem::extension(filename, false));
}

} // namespace

OIIO::TypeDesc output_pixel_type(
    const std::string& filename, OIIO::TypeDesc requested, OIIO::TypeDesc input_type)
{
    // Formats not in the table: uint8 unless -d asks for more (OIIO converts as it can).
    std::vector<OIIO::TypeDesc> types = { OIIO::TypeUInt8 };
    bool known = false;
    const std::string ext = extension(filename);
    for (const FormatTypes& f : format_table())
        if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) {
            types = f.types;
            known = true;
        }
    if (!known)
        return requested != OIIO::TypeUnknown ? requested : OIIO::TypeUInt8;
    auto holds
        = [&](OIIO::TypeDesc t) { return std::find(types.begin(), types.end(), t) != types.end(); };
    if (requested != OIIO::TypeUnknown) {
        if (holds(requested))
            return requested;
        std::string names;
        for (OIIO::TypeDesc t : types)
            names += (names.empty() ? "" : ", ") + std::string(t.c_str());
        throw CliError(
            "-d " + std::string(requested.c_str()) + " : ." + ext + " files hold " + names);
    }
    return holds(input_type) ? input_type : types.front();
}

ValueRange value_range(const OIIO::ImageBuf& image, int nthreads)
{
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(image, {}, nthreads);
    ValueRange range;
    if (stats.min.empty())
        return range;
    range.low = *std::min_element(stats.min.begin(), stats.min.end());
    range.high = *std::max_element(stats.max.begin(), stats.max.end());
    return range;
}

OIIO::TypeDesc type_holding(
    ValueRange range, OIIO::TypeDesc type, OIIO::TypeDesc requested, const std::string& filename)
{
    constexpr float half_max = 65504.0f;
    const float largest = std::max(std::abs(range.low), std::abs(range.high));
    if (type != OIIO::TypeHalf || largest <= half_max)
        return type;
    if (requested == OIIO::TypeHalf)
        throw CliError("-o " + filename + " : has values up to "
            + OIIO::Strutil::fmt::format("{:g}", largest)
            + ", beyond what half holds (65504): write it with -d float");
    return OIIO::TypeFloat;
}

bool is_linear_type(OIIO::TypeDesc type)
{
    return type.is_floating_point();
}

bool stores_associated_alpha(const std::string& filename)
{
    const std::string ext = extension(filename);
    return ext == "exr" || ext == "sxr" || ext == "mxr" || ext == "tx";
}

} // namespace texsyn::cli
