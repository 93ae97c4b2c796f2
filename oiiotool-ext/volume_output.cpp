// SPDX-License-Identifier: Apache-2.0
// Writing solid textures: OpenVDB or a multi-part EXR of z slices, scene-linear float by
// default (docs/solid.md).
#include "cli_state.h"
#include "output_format.h"
#include "quiet_stderr.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

void write_volume_output(CliState& state, const std::string& filename)
{
    StackImage& img = state.top("-o");
    const ColorConfig& cc = state.colors();
    const std::string space
        = cc.resolve(img.output_colorspace.empty() ? cc.scene_linear() : img.output_colorspace);
    if (space.empty())
        throw CliError("--tocolorspace : unknown colour space '" + img.output_colorspace + "'");

    PlanarVolume& synthesized = *img.volume;
    synthesized.attributes.attribute("synth:sample", sample_names(img));
    synthesized.attributes.attribute("synth:colorspace", space);
    synthesized.attributes.attribute("synth:commandline", state.command_line);
    std::string error;
    PlanarVolume converted; // only when the output is not scene-linear
    if (space != cc.scene_linear()) {
        converted = synthesized;
        PlanarImage planes;
        swap_voxel_planes(converted, planes);
        const bool ok = cc.convert(planes, cc.scene_linear(), space, error, state.threads);
        swap_voxel_planes(converted, planes);
        if (!ok)
            throw CliError("-o " + filename + " : " + error);
    }
    const PlanarVolume& v = space != cc.scene_linear() ? converted : synthesized;

    const std::string tmp = temporary_path_for(filename);
    state.pending_outputs.emplace_back(tmp, filename);
    bool ok;
    {
        QuietStderr quiet;
        ok = OIIO::Strutil::iends_with(filename, ".vdb")
            ? write_volume_vdb(tmp, v, error)
            : write_volume_exr(
                tmp, v, output_pixel_type(filename, state.data_format, img.input_format), error);
    }
    if (!ok)
        throw CliError("-o " + filename + " : "
            + error.substr(error.find(": ") == std::string::npos ? 0 : error.find(": ") + 2));
}

} // namespace texsyn::cli
