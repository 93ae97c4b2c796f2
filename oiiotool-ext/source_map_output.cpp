// SPDX-License-Identifier: Apache-2.0
// map=FILE.exr of the commands that copy sample pixels (--neighborhood, --choosy): the
// tool's own modifier, and the source map written beside -o.
#include "cli_state.h"

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

std::string take_file_modifier(const std::string& command, const std::string& modifiers,
    const std::string& name, std::string& file)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (!split_option_string(modifiers, pairs, error))
        throw CliError(command + " : " + error);
    std::string rest;
    for (auto& [key, value] : pairs) {
        if (key != name) {
            rest += (rest.empty() ? "" : ":") + key + "=" + value;
            continue;
        }
        if (!file.empty())
            throw CliError(command + " : " + name + " is given twice");
        if (value.empty())
            throw CliError(command + " : " + name + "= needs a file name");
        file = value;
    }
    return rest;
}

std::string take_map_modifier(
    const std::string& command, const std::string& modifiers, std::string& map)
{
    const std::string rest = take_file_modifier(command, modifiers, "map", map);
    if (!map.empty() && !OIIO::Strutil::iends_with(map, ".exr"))
        throw CliError(command + " : map=" + map
            + " : the source map is a 2-channel float OpenEXR; name it *.exr");
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
