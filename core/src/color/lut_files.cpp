// SPDX-License-Identifier: Apache-2.0
#include "lut_files_pvt.h"

#include <filesystem>

#include <texsyn/io.h>
#include <texsyn/memory.h>

namespace texsyn::detail {

namespace OCIO = OCIO_NAMESPACE;

namespace {

bool check_transform(
    const OCIO::ConstConfigRcPtr& config, const OCIO::ConstTransformRcPtr& t, std::string& error)
{
    if (!t)
        return true;
    if (auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t)) {
        for (int i = 0; i < group->getNumTransforms(); ++i)
            if (!check_transform(config, group->getTransform(i), error))
                return false;
        return true;
    }
    auto file = OCIO::DynamicPtrCast<const OCIO::FileTransform>(t);
    if (!file || !file->getSrc() || !*file->getSrc())
        return true;
    std::string path;
    try {
        path = config->getCurrentContext()->resolveFileLocation(file->getSrc());
    } catch (const std::exception&) {
        return true; // not found: OCIO says so if the transform is used
    }
    if (!check_regular_file(path, "a LUT file", error)) {
        error = "its FileTransform '" + std::string(file->getSrc()) + "': " + error;
        return false;
    }
    // OCIO reads a LUT whole, and parses for minutes a file of gigabytes (a sparse one is
    // made in an instant), beyond any memory limit.
    std::error_code ec;
    const uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > max_lut_file_bytes) {
        error = "its FileTransform '" + std::string(file->getSrc()) + "': " + path + " is "
            + format_bytes(double(bytes)) + ", more than any LUT texsyn reads ("
            + format_bytes(double(max_lut_file_bytes)) + ")";
        return false;
    }
    return true;
}

} // namespace

bool check_lut_files(const OCIO::ConstConfigRcPtr& config, std::string& error)
{
    const int spaces
        = config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
    for (int i = 0; i < spaces; ++i) {
        OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(config->getColorSpaceNameByIndex(
            OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
        if (cs
            && (!check_transform(config, cs->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE), error)
                || !check_transform(
                    config, cs->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE), error)))
            return false;
    }
    for (int i = 0; i < config->getNumLooks(); ++i) {
        OCIO::ConstLookRcPtr look = config->getLook(config->getLookNameByIndex(i));
        if (look
            && (!check_transform(config, look->getTransform(), error)
                || !check_transform(config, look->getInverseTransform(), error)))
            return false;
    }
    for (int i = 0; i < config->getNumViewTransforms(); ++i) {
        OCIO::ConstViewTransformRcPtr vt
            = config->getViewTransform(config->getViewTransformNameByIndex(i));
        if (vt
            && (!check_transform(
                    config, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE), error)
                || !check_transform(
                    config, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE), error)))
            return false;
    }
    for (int i = 0; i < config->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i) {
        OCIO::ConstNamedTransformRcPtr nt = config->getNamedTransform(
            config->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i));
        if (nt
            && (!check_transform(config, nt->getTransform(OCIO::TRANSFORM_DIR_FORWARD), error)
                || !check_transform(config, nt->getTransform(OCIO::TRANSFORM_DIR_INVERSE), error)))
            return false;
    }
    return true;
}

} // namespace texsyn::detail
