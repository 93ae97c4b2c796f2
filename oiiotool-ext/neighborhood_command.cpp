// SPDX-License-Identifier: Apache-2.0
// --neighborhood: Wei & Levoy neighbourhood synthesis, with an optional source map.
#include "cli_state.h"

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

NeighborhoodCommand parse_neighborhood_options(
    const std::string& command, const std::string& modifiers)
{
    // map= names a file, so it is the tool's own, not an option of the method.
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (!split_option_string(modifiers, pairs, error))
        throw CliError(command + " : " + error);
    NeighborhoodCommand result;
    std::string rest;
    for (auto& [name, value] : pairs) {
        if (name != "map") {
            rest += (rest.empty() ? "" : ":") + name + "=" + value;
            continue;
        }
        if (!result.map.empty())
            throw CliError(command + " : map is given twice");
        if (!OIIO::Strutil::iends_with(value, ".exr"))
            throw CliError(command + " : map=" + value
                + " : the source map is a 2-channel float OpenEXR; name it *.exr");
        result.map = value;
    }
    result.options = parse_modifiers(command, rest, NeighborhoodOptions::table());
    if (!result.options.validate(error))
        throw CliError(command + " : " + error);
    return result;
}

void run_neighborhood(CliState& state, const std::string& command, const std::string& modifiers)
{
    NeighborhoodCommand parsed = parse_neighborhood_options(command, modifiers);
    NeighborhoodOptions& opt = parsed.options;
    apply_run_settings(state, command, opt);
    StackImage sample = state.pop(command);
    OIIO::ImageBuf map;
    run_synthesis(state, command, synthesis_result(sample, sample.sources), "", [&](StackImage& r) {
        if (!neighborhood_synthesize(r.buf, sample.buf, opt, parsed.map.empty() ? nullptr : &map))
            return false;
        describe_by_recipe(state, sample, r, "neighborhood", &Recipe::neighborhood, opt);
        return true;
    });
    if (parsed.map.empty())
        return;
    map.specmod().attribute("synth:sample", sample_names(sample));
    map.specmod().attribute("synth:commandline", state.command_line);
    const std::string tmp = temporary_path_for(parsed.map);
    state.pending_outputs.emplace_back(tmp, parsed.map);
    std::string error;
    if (!write_image_atomic(map, tmp, OIIO::TypeFloat, error))
        throw CliError(command + " : map=" + parsed.map + " : could not write the source map");
}

} // namespace texsyn::cli
