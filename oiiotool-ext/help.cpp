// SPDX-License-Identifier: Apache-2.0
// --help, --help METHOD (--METHOD:help), --list-methods, --version: the commands, their
// options, examples and the textures they suit come from the method registry.
#include "cli_error.h"
#include "commands.h"

#include <algorithm>
#include <cstdio>

#include <texsyn/error_text.h>
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
        "    --help [METHOD]       Print this help, or METHOD's with an example (also\n"
        "                          --METHOD:help), and exit\n"
        "    --version             Print the version and exit\n"
        "    --list-methods        List the commands and exit\n"
        "    --colorspaces         List the colour config's spaces and roles, and exit\n"
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
        "                          (default: its texsyn tag, else oiio:ColorSpace, else\n"
        "                          sRGB for 8/16-bit and scene_linear for float files;\n"
        "                          -v says which and why)\n"
        "    --tocolorspace NAME   Colour space to write the current (or every) image in\n"
        "                          (default: scene_linear for float outputs such as EXR,\n"
        "                          the input's space for integer outputs such as PNG)\n"
        "    -d TYPE               Output pixel type: uint8, uint16, half, float. Default:\n"
        "                          the input's type if the format holds it (16-bit PNG\n"
        "                          in, 16-bit PNG out), else half for EXR, float for HDR,\n"
        "                          uint8 for PNG, JPEG, TIFF and others; TIFF stores half\n"
        "                          as float (a half EXR input gives a float TIFF)\n"
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
        "                          the source map MAP with map=; or a whole multiple or\n"
        "                          fraction of its size) and rearrange its pixels by MAP:\n"
        "                          height, normal or roughness maps follow the colour.\n"
        "                          Written in IMAGE's colour space by default.\n"
        "                          --apply-map:normal=opengl|directx turns a normal map's\n"
        "                          vectors with the pixels copied turned (isotropic=1)\n"
        "\n"
        "Which method for which texture (docs/which-method.md):\n",
        version());
    size_t width = 0;
    for (const Method* m : methods())
        width = std::max(width, m->suits.size());
    for (const Method* m : methods())
        if (!m->suits.empty())
            std::printf("    %-*s  --%s\n", int(width), m->suits.c_str(), m->name.c_str());
    std::printf("\n"
                "Commands (--NAME:name=value:name=value...; texsyn --help NAME or --NAME:help\n"
                "prints one with an example):\n");
    for (const Method* m : methods())
        print_method(*m);
    // One example per command, from its row, and the one command that is not a method.
    std::printf("\nExamples:\n");
    for (const Method* m : methods())
        std::printf("    %s\n", m->example.c_str());
    std::printf("    texsyn --apply-map coords.exr grass_height.png -o grass_height_big.exr\n");
}

const Method& method_for_help(const std::string& topic)
{
    const std::string name = topic.rfind("--", 0) == 0 ? topic.substr(2) : topic;
    if (const Method* m = find_method(name))
        return *m;
    std::vector<std::string> names;
    for (const Method* m : methods())
        names.push_back(m->name);
    const std::string guess = closest_name(name, names);
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    throw CliError("--help " + topic + " : unknown method ("
        + (guess.empty() ? "" : "did you mean " + guess + "? ") + "methods: " + list + ")");
}

void print_method_help(const Method& m)
{
    const MethodOptions defaults = m.defaults();
    const auto& fields = defaults.table().fields();
    std::printf("texsyn --%s: %s\n\n", m.name.c_str(), m.summary.c_str());
    std::printf("Usage: --%s%s\n", m.name.c_str(), fields.empty() ? "" : "[:name=value...]");
    print_wrapped(m.help, "    ", "    ", 74);
    if (!fields.empty()) {
        std::printf("\nOptions (name, allowed values, default, meaning):\n");
        for (const OptionField& f : fields) {
            const std::string value = defaults.value(f.name);
            const std::string pad(f.name.size() < 14 ? 14 - f.name.size() : 1, ' ');
            std::printf("    %s%s%s; default %s\n", f.name.c_str(), pad.c_str(), f.allowed.c_str(),
                value.empty() ? "none" : value.c_str());
            print_wrapped(f.help, "        ", "        ", 70);
        }
    }
    std::printf("\nExample:\n    %s\n", m.example.c_str());
    std::printf("\nGuide: docs/%s%s\n", m.doc.c_str(),
        fields.empty() ? "" : ("; options: docs/options-" + m.name + ".md").c_str());
}

void print_methods()
{
    size_t width = 0;
    for (const Method* m : methods())
        width = std::max(width, m->name.size());
    for (const Method* m : methods())
        std::printf("%-*s  %s\n", int(width), m->name.c_str(), m->summary.c_str());
}

void print_version()
{
    std::printf("texsyn %s\n", version());
    const std::string gpl = gpl_components();
    if (!gpl.empty())
        std::printf("GPL build: %s (this binary is under the GPL, not Apache-2.0)\n", gpl.c_str());
}

} // namespace texsyn::cli
