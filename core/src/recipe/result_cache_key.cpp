// SPDX-License-Identifier: Apache-2.0
// The result cache's key: a fingerprint of everything that decides a recipe's pixels
// (result_cache_pvt.h; docs/cache.md lists it). Files are known by their bytes, not their
// paths, so a recipe and its samples copied elsewhere still find their entry, and a file
// edited in place does not.
#include "result_cache_pvt.h"

#include <filesystem>
#include <fstream>

#include <dlfcn.h>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/hash.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/color.h>
#include <texsyn/io.h>
#include <texsyn/version.h>

#include "recipe_limits_pvt.h"

namespace texsyn::detail {

namespace {

namespace fs = std::filesystem;

// The fingerprint of the bytes of file `path`, read in blocks of 1 MiB (the fingerprints
// of the blocks, fingerprinted), so that a large file is never held whole.
bool file_fingerprint(const std::string& path, std::string& digest, std::string& why)
{
    if (!check_regular_file(path, "a file", why))
        return false;
    std::ifstream in(path, std::ios::binary);
    std::string block(size_t(1) << 20, '\0'), blocks;
    while (in.read(block.data(), std::streamsize(block.size())) || in.gcount() > 0)
        blocks += fingerprint_hex({ block.data(), size_t(in.gcount()) });
    if (in.bad() || !in.eof()) {
        why = path + ": cannot read";
        return false;
    }
    digest = fingerprint_hex(blocks);
    return true;
}

// texsyn's code: the fingerprint of the library file this function is in (once per
// process), so that any rebuild that changes it changes every key. Empty if unreadable.
const std::string& library_fingerprint()
{
    static const std::string digest = [] {
        Dl_info info {};
        std::string d, why;
        if (::dladdr(reinterpret_cast<void*>(&library_fingerprint), &info) == 0 || !info.dli_fname
            || !file_fingerprint(info.dli_fname, d, why))
            d.clear();
        return d;
    }();
    return digest;
}

bool key_text(const Recipe& recipe, int depth, std::string& text, std::string& why);

// "ROLE DIGEST" for input file `path`: its bytes, or for a recipe its own key text.
bool input_line(const std::string& role, const std::string& path, int depth, std::string& line,
    std::string& why)
{
    std::string digest;
    if (is_recipe_name(path)) {
        Recipe inner;
        std::string inner_text;
        if (!recipe_from_filename(path, inner, why) || !key_text(inner, depth + 1, inner_text, why))
            return false;
        digest = "recipe " + fingerprint_hex(inner_text);
    } else if (!file_fingerprint(path, digest, why)) {
        return false;
    }
    line = role + " " + digest + "\n";
    return true;
}

// The text the key fingerprints, but for the library and versions (key_text of a recipe
// read as an input is part of its reader's).
bool key_text(const Recipe& recipe, int depth, std::string& text, std::string& why)
{
    // As deep as recipes may nest (recipe_limits.cpp): a deeper chain fails anyway.
    int max_depth = 0;
    if (!max_recipe_depth(max_depth, why))
        return false;
    if (depth > max_depth) {
        why = "recipes nest more than " + std::to_string(max_depth) + " deep";
        return false;
    }
    // The recipe with its files named by their file names only: their bytes follow. The
    // names stay (synth:sample carries them; the extension picks the reader).
    Recipe named = recipe;
    std::string inputs, line;
    for (size_t i = 0; i < recipe.samples.size(); ++i) {
        if (!input_line("sample", recipe.samples[i], depth, line, why))
            return false;
        inputs += line;
        named.samples[i] = fs::path(recipe.samples[i]).filename().string();
    }
    if (named.options)
        for (const OptionField& f : recipe.options.table().fields()) {
            const std::string file = recipe.options.value(f.name);
            if (f.type != OptionType::InputFile || file.empty())
                continue;
            if (!input_line(f.name, file, depth, line, why)
                || !named.options.set(f.name, fs::path(file).filename().string(), why))
                return false;
            inputs += line;
        }
    // The config that will be used ($OCIO or the bundled one when the recipe names none):
    // the bundled one is part of the library, any other is a file (found by its path, as
    // the LUT files it names may be relative to it).
    const auto colors = ColorConfig::load(recipe.colorconfig, why);
    if (!colors)
        return false;
    std::string config = ColorConfig::bundled_name;
    if (!colors->is_bundled()) {
        std::string digest;
        if (!file_fingerprint(colors->source(), digest, why))
            return false;
        config = fs::absolute(colors->source()).lexically_normal().string() + " " + digest;
    }
    named.colorconfig.clear();
    std::string json;
    if (!recipe_to_json(named, "", json, why))
        return false;
    text = json + inputs + "colorconfig " + config + "\n";
    return true;
}

} // namespace

std::string fingerprint_hex(std::string_view bytes)
{
    const auto h = OIIO::farmhash::Fingerprint128(bytes.data(), bytes.size());
    return OIIO::Strutil::fmt::format(
        "{:016x}{:016x}", OIIO::farmhash::Uint128High64(h), OIIO::farmhash::Uint128Low64(h));
}

bool recipe_cache_key(const Recipe& recipe, std::string& key, std::string& why)
{
    std::string text;
    if (library_fingerprint().empty()) {
        why = "texsyn's library file cannot be read";
        return false;
    }
    if (!key_text(recipe, 0, text, why))
        return false;
    text += "texsyn " + std::string(version()) + " " + library_fingerprint() + "\nOpenImageIO "
        + std::to_string(OIIO::openimageio_version()) + "\nOpenColorIO "
        + OCIO_NAMESPACE::GetVersion() + "\ncache entries 1\n";
    key = fingerprint_hex(text);
    return true;
}

} // namespace texsyn::detail
