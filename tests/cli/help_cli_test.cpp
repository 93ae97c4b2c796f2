// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of the help: --help METHOD and --METHOD:help (generated from the method
// registry, their examples run), --list-methods, the general help's choice of method and
// -d rule, and the suggestions for misspelt commands and options.
#include <texsyn/methods.h>

#include "cli_fixture.h"

namespace {

std::vector<std::string> lines_of(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

// Each row's help names its summary, every option with its range and default, an example
// and its guide; --help NAME, --help --NAME and --NAME:help print the same.
TEST_F(Cli, MethodHelpComesFromTheRegistry)
{
    for (const Method* m : methods()) {
        SCOPED_TRACE(m->name);
        CliRun r = texsyn("--help " + m->name);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(r.err.empty()) << r.err;
        EXPECT_TRUE(contains(r.out, "--" + m->name)) << r.out;
        EXPECT_TRUE(contains(r.out, m->summary)) << r.out;
        EXPECT_TRUE(contains(r.out, "Example:\n    " + m->example + "\n")) << r.out;
        EXPECT_TRUE(contains(r.out, "docs/" + m->doc)) << r.out;
        const MethodOptions defaults = m->defaults();
        for (const OptionField& f : defaults.table().fields()) {
            const std::string value = defaults.value(f.name);
            EXPECT_TRUE(contains(r.out,
                "    " + f.name + std::string(f.name.size() < 14 ? 14 - f.name.size() : 1, ' ')
                    + f.allowed + "; default " + (value.empty() ? "none" : value) + "\n"))
                << f.name << "\n"
                << r.out;
        }
        EXPECT_FALSE(contains(r.out, "Global options:")) << "the general help";
        EXPECT_EQ(texsyn("--help --" + m->name).out, r.out);
        CliRun colon = texsyn("--" + m->name + ":help");
        EXPECT_EQ(colon.status, 0) << colon.err;
        EXPECT_EQ(colon.out, r.out);
        EXPECT_EQ(texsyn("stucco.png --" + m->name + ":help").out, r.out);
    }
}

// Every row's example runs from the repository's root (its sample is bundled).
TEST_F(Cli, MethodHelpExamplesRun)
{
    fs::create_directories(dir / "data");
    fs::create_directory_symlink(TEXSYN_TEST_DATA, dir / "data/samples");
    fs::create_directory_symlink(
        fs::path(TEXSYN_TEST_DATA).parent_path() / "meshes", dir / "data/meshes");
    fs::create_directory_symlink(
        fs::path(TEXSYN_TEST_DATA).parent_path() / "masks", dir / "data/masks");
    for (const Method* m : methods()) {
        SCOPED_TRACE(m->name);
        ASSERT_EQ(m->example.find("texsyn "), 0u) << m->example;
        CliRun r = texsyn(m->example.substr(7));
        EXPECT_EQ(r.status, 0) << m->example << ": " << r.err;
    }
}

TEST_F(Cli, HelpForAnUnknownMethodListsTheMethods)
{
    std::string list;
    for (const Method* m : methods())
        list += (list.empty() ? "" : ", ") + m->name;
    expect_failure(
        "--help foo", "texsyn ERROR: --help foo : unknown method (methods: " + list + ")");
    expect_failure("--help pyramd",
        "texsyn ERROR: --help pyramd : unknown method (did you mean pyramid? methods: " + list
            + ")");
    expect_failure("--help apply-map",
        "texsyn ERROR: --help apply-map : unknown method (methods: " + list + ")");
}

// --list-methods: the names padded to the longest, then the summaries, in one column.
TEST_F(Cli, ListMethodsIsAligned)
{
    CliRun r = texsyn("--list-methods");
    ASSERT_EQ(r.status, 0);
    size_t longest = 0;
    for (const Method* m : methods())
        longest = std::max(longest, m->name.size());
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), methods().size());
    for (size_t i = 0; i < lines.size(); ++i) {
        const Method& m = *methods()[i];
        EXPECT_EQ(lines[i], m.name + std::string(longest + 2 - m.name.size(), ' ') + m.summary);
    }
}

// The general help says which method suits which texture, one table line each.
TEST_F(Cli, HelpSaysWhichMethodSuitsWhichTexture)
{
    CliRun r = texsyn("--help");
    ASSERT_EQ(r.status, 0);
    auto line_with = [&](const std::string& words) {
        for (const std::string& line : lines_of(r.out))
            if (contains(line, words))
                return line;
        return std::string();
    };
    EXPECT_TRUE(contains(line_with("stochastic"), "--pyramid")) << r.out;
    EXPECT_TRUE(contains(line_with("pebbles"), "--neighborhood")) << r.out;
    EXPECT_TRUE(contains(line_with("bricks"), "--patch")) << r.out;
    EXPECT_TRUE(contains(line_with("histogram"), "--choosy")) << r.out;
    EXPECT_TRUE(contains(line_with("no sample"), "--cascade")) << r.out;
    for (const Method* m : methods()) {
        if (!m->suits.empty()) {
            EXPECT_TRUE(contains(line_with(m->suits), "--" + m->name)) << m->name << "\n" << r.out;
        }
    }
}

TEST_F(Cli, MisspeltCommandsAndOptionsGetASuggestion)
{
    expect_failure("stucco.png --neighbourhood -o x.png",
        "texsyn ERROR: unknown command '--neighbourhood' (did you mean --neighborhood?)");
    expect_failure("stucco.png --neighbourhood:size=64x64 -o x.png",
        "texsyn ERROR: unknown command '--neighbourhood' (did you mean --neighborhood?)");
    expect_failure("--sed 3 stucco.png --pyramid -o x.png",
        "texsyn ERROR: unknown command '--sed' (did you mean --seed?)");
    expect_failure("stucco.png --pyramid:sise=512x512 -o x.png",
        "texsyn ERROR: --pyramid : sise=512x512 : unknown option 'sise' (did you mean size?)");
    expect_failure("stucco.png --choosy:iteartions=1,2 -o x.png",
        "texsyn ERROR: --choosy : iteartions=1,2 : unknown option 'iteartions' (did you mean "
        "iterations?)");
    // Far from every name: no guess.
    expect_failure("stucco.png --frobnicate -o out.exr",
        "texsyn ERROR: unknown command or option '--frobnicate' (see texsyn --help)");
}

// -d's default, as --help states it: the input's type where the format holds it, else the
// format's first type; OIIO's TIFF writer stores half as float.
TEST_F(Cli, HelpStatesTheOutputTypeRule)
{
    CliRun r = texsyn("--help");
    ASSERT_EQ(r.status, 0);
    std::string text = r.out.substr(r.out.find("-d TYPE"));
    text = text.substr(0, text.find("--subbands"));
    std::string words; // the lines joined, without their indentation
    std::istringstream in(text);
    for (std::string word; in >> word;)
        words += (words.empty() ? "" : " ") + word;
    EXPECT_TRUE(contains(words, "Default: the input's type if the format holds it")) << words;
    EXPECT_TRUE(contains(words, "else half for EXR, float for HDR, uint8 for PNG, JPEG, TIFF"))
        << words;
    EXPECT_TRUE(contains(words, "a half EXR input gives a float TIFF")) << words;

    write_sample("half.exr", 3, OIIO::TypeHalf);
    const std::string synth = " --pyramid:size=16x16:iterations=1 ";
    ASSERT_EQ(texsyn("half.exr" + synth + "-o half.tif -o half.png -o half_out.exr").status, 0);
    EXPECT_EQ(file_type("half.tif"), OIIO::TypeFloat);
    EXPECT_EQ(file_type("half.png"), OIIO::TypeUInt8);
    EXPECT_EQ(file_type("half_out.exr"), OIIO::TypeHalf);
    write_sample("deep.png", 3, OIIO::TypeUInt16);
    ASSERT_EQ(texsyn("deep.png" + synth + "-o deep.tif -o deep.exr").status, 0);
    EXPECT_EQ(file_type("deep.tif"), OIIO::TypeUInt16);
    EXPECT_EQ(file_type("deep.exr"), OIIO::TypeHalf);
    ASSERT_EQ(texsyn("stucco.png" + synth + "-o out.tif").status, 0);
    EXPECT_EQ(file_type("out.tif"), OIIO::TypeUInt8);
}
