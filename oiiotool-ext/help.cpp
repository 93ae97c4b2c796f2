// SPDX-License-Identifier: Apache-2.0
// --help, --list-methods, --version: the commands and their options come from the method
// registry.
#include "commands.h"

#include <cstdio>

#include <texsyn/version.h>

namespace texsyn::cli {

namespace {

// `text` wrapped to lines of at most `width` characters, the first starting with `first`,
// the others with `indent`.
void print_wrapped(
    const std::string& text, const std::string& first, const char* indent, size_t width = 56)
{
    std::string line;
    const char* lead = first.c_str();
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find(' ', start);
        if (end == std::string::npos)
            end = text.size();
        const std::string word = text.substr(start, end - start);
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            std::printf("%s%s\n", lead, line.c_str());
            lead = indent;
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        start = end + 1;
    }
    if (!line.empty())
        std::printf("%s%s\n", lead, line.c_str());
}

void print_method(const Method& m)
{
    const MethodOptions defaults = m.defaults();
    const auto& fields = defaults.table().fields();
    std::printf("    --%s%s\n", m.name.c_str(), fields.empty() ? "" : "[:name=value...]");
    const char* indent = "                          ";
    print_wrapped(m.help, indent, indent);
    if (fields.empty())
        return;
    std::printf("                          Options (docs/options-%s.md):\n", m.name.c_str());
    for (const OptionField& f : fields) {
        char name[32];
        std::snprintf(name, sizeof(name), "        %-13s ", f.name.c_str());
        const std::string value = defaults.value(f.name);
        print_wrapped(
            f.help + " (" + f.allowed + "; default " + (value.empty() ? "none" : value) + ")", name,
            "                      ", 70);
    }
}

} // namespace

void print_help()
{
    std::printf(
        "texsyn %s -- texture synthesis for VFX pipelines\n"
        "Usage: texsyn [global options] ARGS...\n"
        "ARGS are processed left to right on an image stack, as in oiiotool: a file name\n"
        "reads an image, a command pops its inputs and pushes its result, -o writes the top.\n"
        "\n"
        "Global options:\n"
        "    --help                Print this help and exit\n"
        "    --version             Print the version and exit\n"
        "    --list-methods        List the commands and exit\n"
        "    -v                    Verbose: progress and timings on stderr\n"
        "    --seed N              Random seed, 0..2147483647 (default 0)\n"
        "    --threads N           Worker threads, 0 = all cores (default 0); the result\n"
        "                          does not depend on it\n"
        "    --max-memory SIZE     Refuse work needing more memory than SIZE (8G, 512M,\n"
        "                          50%%; default: 90%% of RAM or of the cgroup limit, or\n"
        "                          $TEXSYN_MAX_MEMORY), before allocating it\n"
        "    --colorconfig FILE    OCIO config (default: $OCIO, else texsyn's bundled config,\n"
        "                          also named texsyn://bundled)\n"
        "    --iscolorspace NAME   Colour space of the current (or next) input image\n"
        "    --tocolorspace NAME   Colour space to write the current (or every) image in\n"
        "                          (default: scene_linear for float outputs such as EXR,\n"
        "                          the input's space for integer outputs such as PNG)\n"
        "    -d TYPE               Output pixel type: uint8, uint16, half, float\n"
        "                          (default: half for EXR, uint8 otherwise)\n"
        "    --subbands            -o writes a multi-part EXR: part 'synth' plus every\n"
        "                          pyramid subband of the sample and the synthesis\n"
        "\n"
        "Inputs and outputs:\n"
        "    FILE                  Read an image, or an analysis file (*.tsa)\n"
        "    -o FILE               Write the current image (or analysis, as *.tsa; solid\n"
        "                          texture, as *.vdb or *.exr) to FILE (atomically)\n"
        "    --recipe FILE.texsyn  Write the recipe of the current result: OIIO tools open\n"
        "                          it as an image with texsyn's format plugin\n"
        "    --apply-map MAP IMAGE Read IMAGE (aligned with the sample of a run that wrote\n"
        "                          the source map MAP with map=) and rearrange its pixels by\n"
        "                          MAP: height, normal or roughness maps follow the colour.\n"
        "                          Written in IMAGE's colour space by default\n"
        "\n"
        "Commands (--NAME:name=value:name=value...). Which method for which texture\n"
        "(docs/which-method.md): stochastic (rust, stucco) --pyramid; small structure,\n"
        "foliage --neighborhood; structured, regular, oriented (bricks, tiles, weave,\n"
        "wood) --patch; the sample's colour histogram kept exactly --choosy; no sample\n"
        "--cascade.\n",
        version());
    for (const Method* m : methods())
        print_method(*m);
    std::printf("\n"
                "Examples:\n"
                "    texsyn rust.png --pyramid:size=1024x1024:iterations=5:orientations=4 -o "
                "rust_big.exr\n"
                "    texsyn rust.png --check\n"
                "    texsyn marble.png --solid:size=128x128x128 -o marble.vdb\n"
                "    texsyn rust.png paper.png --mix:palette=0:pattern=1 -o mix.exr\n"
                "    texsyn photo.png rust.png --transfer -o rusty_photo.exr\n"
                "    texsyn grass.png --neighborhood:size=512x512:map=coords.exr -o grass_big.exr\n"
                "    texsyn stone.png --choosy:size=512x512:iterations=1,8 -o stone_big.exr\n"
                "    texsyn bricks.png --patch:size=1024x1024:map=coords.exr -o bricks_big.exr\n"
                "    texsyn --apply-map coords.exr grass_height.png -o grass_height_big.exr\n"
                "    texsyn --cascade:size=512x512:levels=4:r=3.9 -o cascade.exr\n");
}

void print_methods()
{
    for (const Method* m : methods())
        std::printf("%-13s %s\n", m->name.c_str(), m->summary.c_str());
}

void print_version()
{
    std::printf("texsyn %s\n", version());
}

} // namespace texsyn::cli
