// SPDX-License-Identifier: Apache-2.0
// map=FILE.exr of the commands that copy sample pixels (--neighborhood, --choosy): the
// tool's own modifier, and the source map written beside -o.
#include "cli_state.h"

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

std::string take_map_modifier(
    const std::string& command, const std::string& modifiers, std::string& map)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (!split_option_string(modifiers, pairs, error))
        throw CliError(command + " : " + error);
    std::string rest;
    for (auto& [name, value] : pairs) {
        if (name != "map") {
            rest += (rest.empty() ? "" : ":") + name + "=" + value;
            continue;
        }
        if (!map.empty())
            throw CliError(command + " : map is given twice");
        if (!OIIO::Strutil::iends_with(value, ".exr"))
            throw CliError(command + " : map=" + value
                + " : the source map is a 2-channel float OpenEXR; name it *.exr");
        map = value;
    }
    return rest;
}

void write_source_map_output(CliState& state, const std::string& command, const StackImage& sample,
    OIIO::ImageBuf& map, const std::string& filename)
{
    map.specmod().attribute("synth:sample", sample_names(sample));
    map.specmod().attribute("synth:commandline", state.command_line);
    const std::string tmp = temporary_path_for(filename);
    state.pending_outputs.emplace_back(tmp, filename);
    std::string error;
    if (!write_image_atomic(map, tmp, OIIO::TypeFloat, error))
        throw CliError(command + " : map=" + filename + " : could not write the source map");
}

} // namespace texsyn::cli
