// SPDX-License-Identifier: Apache-2.0
// ColorConfig: a thin, exception-free layer over an OCIO 2.1 config (its pixel conversions are
// in image_conversion.cpp).
#include <texsyn/color.h>
#include <texsyn/error_text.h>
#include <texsyn/io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <OpenColorIO/OpenColorIO.h>

#include <OpenImageIO/strutil.h>

#include "color_config_pvt.h"
#include "lut_files_pvt.h"

namespace OCIO = OCIO_NAMESPACE;

// Generated from ocio-configs/config.ocio by ocio-configs/embed.cmake.
extern const char* const texsyn_bundled_ocio_config;

namespace texsyn {

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

std::string ColorConfig::unknown_colorspace(const std::string& name) const
{
    std::vector<std::string> names = colorspace_names();
    const OCIO::ConstConfigRcPtr& cfg = m_impl->config;
    std::vector<std::string> candidates = names;
    for (const std::string& n : names)
        if (OCIO::ConstColorSpaceRcPtr cs = cfg->getColorSpace(n.c_str()))
            for (size_t i = 0; i < cs->getNumAliases(); ++i)
                candidates.emplace_back(cs->getAlias(i));
    const std::string near = closest_name(name, candidates);
    return "unknown colour space '" + name + "'"
        + (near.empty() ? "" : ", did you mean '" + near + "'?")
        + " (known: " + OIIO::Strutil::join(names, ", ") + "; texsyn --colorspaces describes them)";
}

std::string ColorConfig::describe() const
{
    const OCIO::ConstConfigRcPtr& cfg = m_impl->config;
    std::string text = "Colour config " + source() + " (" + origin() + ")\nColour spaces:\n";
    for (const std::string& n : colorspace_names()) {
        OCIO::ConstColorSpaceRcPtr cs = cfg->getColorSpace(n.c_str());
        text += "  " + n;
        std::vector<std::string> aliases;
        for (size_t i = 0; i < cs->getNumAliases(); ++i)
            aliases.emplace_back(cs->getAlias(i));
        if (!aliases.empty())
            text += " (aliases: " + OIIO::Strutil::join(aliases, ", ") + ")";
        std::vector<std::string> what;
        if (*cs->getFamily())
            what.emplace_back(std::string("family ") + cs->getFamily());
        if (*cs->getEncoding())
            what.emplace_back(std::string("encoding ") + cs->getEncoding());
        if (cs->isData())
            what.emplace_back("data: never converted");
        if (!what.empty())
            text += " — " + OIIO::Strutil::join(what, ", ");
        text += "\n";
    }
    text += "Roles:\n";
    for (int i = 0; i < cfg->getNumRoles(); ++i) {
        const char* role = cfg->getRoleName(i);
        OCIO::ConstColorSpaceRcPtr cs = cfg->getColorSpace(role);
        text += std::string("  ") + role + ": " + (cs ? cs->getName() : "?") + "\n";
    }
    return text;
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

bool ColorConfig::chromaticities(const std::string& name, float xy[8]) const
{
    const std::string space = resolve(name);
    const std::string xyz = resolve(OCIO::ROLE_INTERCHANGE_DISPLAY);
    if (space.empty() || xyz.empty() || is_data(space))
        return false;
    try {
        OCIO::ConstCPUProcessorRcPtr cpu
            = m_impl->config->getProcessor(space.c_str(), xyz.c_str())->getDefaultCPUProcessor();
        const float rgbw[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
        for (int i = 0; i < 4; ++i) {
            float v[3] = { rgbw[i][0], rgbw[i][1], rgbw[i][2] };
            cpu->applyRGB(v);
            const float sum = v[0] + v[1] + v[2];
            if (!(std::abs(sum) > 1e-6f))
                return false;
            xy[2 * i] = v[0] / sum;
            xy[2 * i + 1] = v[1] / sum;
        }
    } catch (const std::exception&) {
        return false;
    }
    return true;
}

void ColorConfig::tag_colorspace(OIIO::ImageSpec& spec, const std::string& name) const
{
    spec.attribute("oiio:ColorSpace", name);
    spec.attribute("synth:colorspace", name);
    spec.erase_attribute("chromaticities");
    spec.erase_attribute("Exif:ColorSpace");
    if (is_data(name))
        return;
    const bool srgb = name == resolve("sRGB") || name == resolve("sRGB - Texture");
    spec.attribute("Exif:ColorSpace", srgb ? 1 : 65535);
    if (float xy[8]; chromaticities(name, xy))
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), xy);
}

bool ColorConfig::is_generic_name(const std::string& name) const
{
    if (OIIO::Strutil::iequals(name, "linear"))
        return true;
    const OCIO::ConstConfigRcPtr& cfg = m_impl->config;
    for (int i = 0; i < cfg->getNumRoles(); ++i)
        if (OIIO::Strutil::iequals(name, cfg->getRoleName(i)))
            return true;
    return false;
}

ColorConfig::Guess ColorConfig::guess_colorspace(const OIIO::ImageSpec& spec) const
{
    // texsyn's own outputs: the tag, or where the format keeps no tag (TIFF), the description.
    const std::string own = spec.get_string_attribute("synth:colorspace");
    if (std::string known = resolve(own); !known.empty())
        return { std::move(known), "its synth:colorspace tag", "" };
    const std::string description = spec.get_string_attribute("ImageDescription");
    if (const size_t at = description.rfind(", colorspace ");
        OIIO::Strutil::starts_with(description, "texsyn ") && at != std::string::npos) {
        const std::string named = OIIO::Strutil::strip(description.substr(at + 13));
        if (std::string known = resolve(named); !known.empty())
            return { std::move(known), "its texsyn ImageDescription (the format keeps no tag)",
                "" };
    }
    const std::string tag = spec.get_string_attribute("oiio:ColorSpace");
    const std::string known = resolve(tag);
    if (!tag.empty() && is_generic_name(tag)) {
        // OIIO reads every OpenEXR file as "Linear": this config's scene_linear.
        const std::string space = known.empty() ? scene_linear() : known;
        return { space, "its oiio:ColorSpace tag '" + tag + "'",
            "the tag '" + tag
                + "' is a generic name that says nothing of the primaries (OIIO tags every "
                  "OpenEXR file 'Linear', ACEScg ones too): give --iscolorspace NAME before "
                  "the file if it is not "
                + space };
    }
    if (!known.empty())
        return { known, "its oiio:ColorSpace tag '" + tag + "'", "" };
    std::string untagged
        = tag.empty() ? "no colour tag" : "a tag '" + tag + "' the config does not know";
    switch (spec.format.basetype) {
    case OIIO::TypeDesc::UINT8:
    case OIIO::TypeDesc::INT8:
    case OIIO::TypeDesc::UINT16:
    case OIIO::TypeDesc::INT16:
        return { resolve("sRGB - Texture"),
            untagged + ": 8- and 16-bit integer files are taken as sRGB-encoded", "" };
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
    case OIIO::TypeDesc::DOUBLE:
        return { scene_linear(), untagged + ": floating-point files are taken as scene-linear",
            "" };
    default:
        return { "", untagged + ", and its pixel type says nothing", "" };
    }
}

} // namespace texsyn
