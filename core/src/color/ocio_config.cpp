// SPDX-License-Identifier: Apache-2.0
// ColorConfig: a thin, exception-free layer over an OCIO 2.1 config.
#include <texsyn/color.h>
#include <texsyn/io.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>
#include <utility>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/parallel.h>
#include <OpenImageIO/strutil.h>

#include "lut_files_pvt.h"

namespace OCIO = OCIO_NAMESPACE;

// Generated from ocio-configs/config.ocio by ocio-configs/embed.cmake.
extern const char* const texsyn_bundled_ocio_config;

namespace texsyn {

struct ColorConfig::Impl {
    OCIO::ConstConfigRcPtr config;
    std::string source;
    std::string origin;
    bool bundled = false;
};

namespace {

// Whether the file at `path` holds exactly `text` (sizes are compared first).
bool file_holds(const std::string& path, const char* text)
{
    const size_t n = std::strlen(text);
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) != n || ec)
        return false;
    std::ifstream in(path, std::ios::binary);
    std::string bytes(n, '\0');
    return in.read(bytes.data(), std::streamsize(n)) && bytes == text;
}

} // namespace

ColorConfig::ColorConfig(std::unique_ptr<Impl> impl)
    : m_impl(std::move(impl))
{ }
ColorConfig::~ColorConfig() = default;
ColorConfig::ColorConfig(ColorConfig&&) noexcept = default;
ColorConfig& ColorConfig::operator=(ColorConfig&&) noexcept = default;

const char* ColorConfig::bundled_config_text()
{
    return texsyn_bundled_ocio_config;
}

std::unique_ptr<ColorConfig> ColorConfig::load(const std::string& explicit_path, std::string& error)
{
    auto impl = std::make_unique<Impl>();
    std::string path = explicit_path;
    impl->origin = "--colorconfig";
    if (path.empty()) {
        const char* env = std::getenv("OCIO");
        impl->origin = env && *env ? "$OCIO" : "default";
        if (env && *env)
            path = env;
    }
    if (path == bundled_name)
        path.clear();
    impl->source = path.empty() ? bundled_name : path;
    if (!path.empty() && !check_regular_file(path, "an OCIO config", error)) {
        error = "colour config '" + path + "': " + error.substr(path.size() + 2);
        return nullptr;
    }
    try {
        if (path.empty()) {
            std::istringstream text(texsyn_bundled_ocio_config);
            impl->config = OCIO::Config::CreateFromStream(text);
            impl->bundled = true;
        } else {
            impl->config = OCIO::Config::CreateFromFile(path.c_str());
            impl->bundled = file_holds(path, texsyn_bundled_ocio_config);
        }
        impl->config->validate();
        if (!detail::check_lut_files(impl->config, error)) {
            error = "colour config '" + impl->source + "': " + error;
            return nullptr;
        }
    } catch (const std::exception& e) { // OCIO::Exception is a std::runtime_error
        error = "colour config '" + impl->source + "': " + e.what();
        return nullptr;
    } catch (...) {
        error = "colour config '" + impl->source + "': unknown error";
        return nullptr;
    }
    return std::unique_ptr<ColorConfig>(new ColorConfig(std::move(impl)));
}

const std::string& ColorConfig::source() const
{
    return m_impl->source;
}

bool ColorConfig::is_bundled() const
{
    return m_impl->bundled;
}

const std::string& ColorConfig::origin() const
{
    return m_impl->origin;
}

std::string ColorConfig::resolve(const std::string& name) const
{
    if (name.empty())
        return "";
    // getColorSpace() accepts names, aliases and roles.
    OCIO::ConstColorSpaceRcPtr cs = m_impl->config->getColorSpace(name.c_str());
    return cs ? cs->getName() : "";
}

std::string ColorConfig::scene_linear() const
{
    return resolve(OCIO::ROLE_SCENE_LINEAR);
}

bool ColorConfig::is_data(const std::string& name) const
{
    if (name.empty())
        return false;
    OCIO::ConstColorSpaceRcPtr cs = m_impl->config->getColorSpace(name.c_str());
    return cs && cs->isData();
}

std::vector<std::string> ColorConfig::colorspace_names() const
{
    const OCIO::ConstConfigRcPtr& cfg = m_impl->config;
    const int n = cfg->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
    std::vector<std::string> names;
    names.reserve(size_t(n));
    for (int i = 0; i < n; ++i)
        names.emplace_back(cfg->getColorSpaceNameByIndex(
            OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
    return names;
}

namespace {

// Runs fn(y0, y1) over blocks of ~16k pixels in parallel and returns the first error
// message ("" if none): exceptions must not escape a pool thread.
std::string for_row_blocks(
    int width, int height, int nthreads, const std::function<void(int64_t, int64_t)>& fn)
{
    std::mutex mutex;
    std::string error;
    OIIO::parallel_for_chunked(
        0, height, std::max<int64_t>(1, (int64_t(1) << 14) / std::max(1, width)),
        [&](int64_t y0, int64_t y1) {
            try {
                fn(y0, y1);
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(mutex);
                if (error.empty())
                    error = e.what();
            }
        },
        OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y, 1));
    return error;
}

std::string convert_rgb(
    const OCIO::ConstCPUProcessorRcPtr& cpu, Plane& r, Plane& g, Plane& b, int nthreads)
{
    const int w = r.width();
    return for_row_blocks(w, r.height(), nthreads, [&](int64_t y0, int64_t y1) {
        OCIO::PlanarImageDesc desc(
            r.row(int(y0)), g.row(int(y0)), b.row(int(y0)), nullptr, w, long(y1 - y0));
        cpu->apply(desc);
    });
}

// Grey is converted as the colour (g, g, g); the result's mean is the new grey.
std::string convert_grey(const OCIO::ConstCPUProcessorRcPtr& cpu, Plane& grey, int nthreads)
{
    const int w = grey.width();
    return for_row_blocks(w, grey.height(), nthreads, [&](int64_t y0, int64_t y1) {
        const size_t npix = size_t(w) * size_t(y1 - y0);
        float* g = grey.row(int(y0));
        std::vector<float> rgb(3 * npix);
        for (size_t i = 0; i < npix; ++i)
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = g[i];
        OCIO::PackedImageDesc desc(rgb.data(), long(npix), 1, 3);
        cpu->apply(desc);
        for (size_t i = 0; i < npix; ++i)
            g[i] = (rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2]) * (1.0f / 3.0f);
    });
}

} // namespace

bool ColorConfig::convert(PlanarImage& image, const std::string& from, const std::string& to,
    std::string& error, int nthreads) const
{
    for (const std::string* name : { &from, &to }) {
        if (resolve(*name).empty()) {
            error = "unknown colour space '" + *name
                + "' (known: " + OIIO::Strutil::join(colorspace_names(), ", ") + ")";
            return false;
        }
    }
    const std::string src = resolve(from), dst = resolve(to);
    if (src == dst || is_data(src) || is_data(dst))
        return true;
    const int ncolor = image.ncolor();
    if (ncolor < 1 || image.width() < 1 || image.height() < 1)
        return true;
    // Converted copies are swapped in only on success: the image is untouched on failure.
    const int nconv = ncolor >= 3 ? 3 : 1;
    std::vector<Plane> planes(image.channels.begin(), image.channels.begin() + nconv);
    std::string ocio_error;
    try {
        // Lossless: no fast approximations of pow/log, so statistics see exact values.
        OCIO::ConstProcessorRcPtr processor
            = m_impl->config->getProcessor(src.c_str(), dst.c_str());
        OCIO::ConstCPUProcessorRcPtr cpu = processor->getOptimizedCPUProcessor(
            OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_LOSSLESS);
        ocio_error = nconv == 3 ? convert_rgb(cpu, planes[0], planes[1], planes[2], nthreads)
                                : convert_grey(cpu, planes[0], nthreads);
    } catch (const std::exception& e) {
        ocio_error = e.what();
    }
    if (!ocio_error.empty()) {
        error = "colour conversion '" + src + "' -> '" + dst + "': " + ocio_error;
        return false;
    }
    for (int c = 0; c < nconv; ++c)
        image.channels[size_t(c)] = std::move(planes[size_t(c)]);
    return true;
}

std::string ColorConfig::guess_colorspace(const OIIO::ImageSpec& spec) const
{
    const std::string tag = spec.get_string_attribute("oiio:ColorSpace");
    // OIIO reads untagged float files back as "Linear": that is this config's scene_linear.
    if (OIIO::Strutil::iequals(tag, "linear"))
        return scene_linear();
    if (const std::string known = resolve(tag); !known.empty())
        return known;
    switch (spec.format.basetype) {
    case OIIO::TypeDesc::UINT8:
    case OIIO::TypeDesc::INT8:
    case OIIO::TypeDesc::UINT16:
    case OIIO::TypeDesc::INT16:
        return resolve("sRGB - Texture");
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
    case OIIO::TypeDesc::DOUBLE:
        return scene_linear();
    default:
        return "";
    }
}

} // namespace texsyn
