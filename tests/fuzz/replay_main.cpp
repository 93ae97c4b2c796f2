// SPDX-License-Identifier: Apache-2.0
// Runs a fuzz target over files and folders of inputs without libFuzzer: the normal build's
// regression run of the seed corpus and of every input that once crashed.
#include "fuzz_target.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

int main(int argc, char* argv[])
{
    namespace fs = std::filesystem;
    size_t runs = 0;
    auto run = [&](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        ++runs;
    };
    for (int i = 1; i < argc; ++i) {
        if (fs::is_directory(argv[i])) {
            std::vector<fs::path> files;
            for (const auto& e : fs::directory_iterator(argv[i]))
                if (e.is_regular_file())
                    files.push_back(e.path());
            std::sort(files.begin(), files.end());
            for (const fs::path& f : files)
                run(f);
        } else {
            run(argv[i]);
        }
    }
    std::printf("%zu inputs ran without a finding\n", runs);
    return runs > 0 ? 0 : 1;
}
