// SPDX-License-Identifier: Apache-2.0
// Recipes that nest recipes: the input, split at NUL bytes, is up to four recipe files
// r0.texsyn ... r3.texsyn in one folder, which may name each other (and themselves) as
// samples or input files. Opening r0 and counting the work it asks for must end, with one
// line or a count within the limits, whatever the files say.
#include "fuzz_target.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <texsyn/recipe.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    namespace fs = std::filesystem;
    static const fs::path dir
        = fs::temp_directory_path() / ("texsyn-fuzz-nested-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    size_t begin = 0;
    for (int k = 0; k < 4 && begin <= bytes.size(); ++k) {
        const size_t end = std::min(bytes.find('\0', begin), bytes.size());
        std::ofstream(dir / ("r" + std::to_string(k) + ".texsyn"), std::ios::binary)
            << bytes.substr(begin, end - begin);
        begin = end + 1;
    }
    texsyn::Recipe recipe;
    std::string error;
    if (!texsyn::recipe_from_filename((dir / "r0.texsyn").string(), recipe, error))
        texsyn::fuzz::expect_one_line(error, "recipe");
    else if (!texsyn::check_recipe_work(recipe, error))
        texsyn::fuzz::expect_one_line(error, "nested recipes");
    fs::remove_all(dir);
    return 0;
}
