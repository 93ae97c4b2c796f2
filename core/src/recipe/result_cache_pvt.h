// SPDX-License-Identifier: Apache-2.0
// The on-disk result cache of recipes, opted into with $TEXSYN_CACHE=FOLDER (docs/cache.md).
// An entry is one multi-part float OpenEXR, FOLDER/KEY.exr, KEY being a fingerprint of
// everything that decides the recipe's pixels; it appears by rename only, so a reader sees
// a whole entry or none. FOLDER/KEY.lock, locked with flock() by whoever makes the entry,
// makes processes and threads that want the same result at once synthesize it once: the
// others wait, then read it. The cache never makes a synthesis fail: a problem with it is a
// one-line warning on stderr (once per process) and the result is synthesized.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/recipe.h>

namespace texsyn::detail {

/// The cache folder $TEXSYN_CACHE names, created if missing, and whether results can be
/// stored there. False if the variable is unset or empty (the cache is off), or if the
/// folder cannot be created or is not a folder (warned once; the cache is then off).
bool result_cache_folder(std::string& folder, bool& writable);

/// The key of `recipe`'s result: 32 hex digits, a farmhash Fingerprint128 of the recipe
/// in canonical form (recipe_to_json, every option written, file paths cut to file
/// names) and, for each file it reads (samples, analysis files, the options' input
/// files), the file's bytes — or, for a recipe read as an input, that recipe's own key —
/// with the effective colour config (the bundled one by name, any other by its absolute
/// path and bytes), texsyn's library file, and OIIO's and OCIO's versions. False (with
/// `why`) if a file cannot be read, the config does not load, a name is not UTF-8, or
/// recipes nest more than 8 deep.
bool recipe_cache_key(const Recipe& recipe, std::string& key, std::string& why);

/// 32 hex digits: farmhash's Fingerprint128 of `bytes` (fixed forever, unlike Hash128).
std::string fingerprint_hex(std::string_view bytes);

/// What an entry must hold to be used: `leading` parts (the synthesis, or a volume's z
/// slices) of width x height with these channels, followed by more parts (the subbands)
/// exactly if `more`.
struct EntryLayout {
    int leading = 1;
    int width = 0;
    int height = 0;
    std::vector<std::string> channelnames;
    bool more = false;
};

/// The images `make` gives (float, all parts with one display window, each named by
/// "oiio:subimagename", metadata "synth:*" only kept), through the cache folder: read
/// from entry `key` if it is there, intact and of `layout`; else `make` runs — once for
/// all processes and threads that want the entry at once, under its lock — and its result
/// is stored (if `writable`). A damaged entry (truncated, corrupt, of another key or
/// layout) is ignored and replaced. `label` names the recipe in the TEXSYN_CACHE_VERBOSE
/// lines. Fails (false, `error`) only if `make` does.
bool cached_images(const std::string& folder, bool writable, const std::string& key,
    const EntryLayout& layout, const std::string& label,
    const std::function<bool(std::vector<OIIO::ImageBuf>&, std::string&)>& make,
    std::vector<OIIO::ImageBuf>& images, std::string& error);

/// The spec of a part of a recipe's result, as cached_images() and recipe_images() give it:
/// `src`'s size, channels (alpha: the one named "A" or "Alpha"), display window, float,
/// its "oiio:subimagename" and its synth:* metadata, nothing else (so that a part read
/// from an entry and the same part just made have the same spec).
OIIO::ImageSpec part_spec(const OIIO::ImageSpec& src);

/// Writes `line` to stderr as "texsyn cache: LINE" if $TEXSYN_CACHE_VERBOSE is set (and
/// neither empty nor "0").
void cache_note(const std::string& line);

} // namespace texsyn::detail
