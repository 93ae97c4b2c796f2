// SPDX-License-Identifier: Apache-2.0
// Writing solid textures: OpenVDB or a multi-part EXR of z slices, scene-linear float by
// default (docs/solid.md).
#include "cli_error.h"
#include "commands.h"
#include "output_format.h"
#include "quiet_stderr.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

void write_volume_output(CliState& state, StackItem& img, const std::string& filename)
{
    const ColorConfig& cc = state.colors();
    const std::string space
        = cc.resolve(img.output_colorspace.empty() ? cc.scene_linear() : img.output_colorspace);
    if (space.empty())
        throw CliError("--tocolorspace : " + cc.unknown_colorspace(img.output_colorspace));

    PlanarVolume synthesized;
    std::string error;
    if (!volume_from_imagebuf(img.buf, synthesized, error))
        throw CliError("-o " + filename + " : " + error);
    OIIO::ImageSpec tags;
    cc.tag_colorspace(tags, space);
    for (const OIIO::ParamValue& tag : tags.extra_attribs)
        synthesized.attributes.add_or_replace(tag);
    synthesized.attributes.attribute("synth:commandline", state.command_line);
    if (space != cc.scene_linear()) {
        PlanarImage planes;
        swap_voxel_planes(synthesized, planes);
        const bool ok = cc.convert(planes, cc.scene_linear(), space, error, state.threads);
        swap_voxel_planes(synthesized, planes);
        if (!ok)
            throw CliError("-o " + filename + " : " + error);
    }
    const PlanarVolume& v = synthesized;

    const std::string tmp = state.outputs.add(filename);
    bool ok;
    {
        QuietStderr quiet("-o " + filename);
        ok = OIIO::Strutil::iends_with(filename, ".vdb")
            ? write_volume_vdb(tmp, v, error)
            : write_volume_exr(
                tmp, v, output_pixel_type(filename, state.data_format, img.input_format), error);
    }
    if (!ok)
        throw CliError("-o " + filename + " : "
            + state.outputs.final_names(
                error.substr(error.find(": ") == std::string::npos ? 0 : error.find(": ") + 2)));
}

} // namespace texsyn::cli
