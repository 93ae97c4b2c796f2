// SPDX-License-Identifier: Apache-2.0
// Command option strings: the first byte picks a method of the registry, the rest is the
// text after "--method:" (run through the method's shorthands, applied and validated as the
// command line does); --max-memory's sizes too.
#include "fuzz_target.h"

#include <texsyn/memory.h>
#include <texsyn/methods.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    const auto& all = texsyn::methods();
    const texsyn::Method& m = *all[data[0] % all.size()];
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    texsyn::MethodOptions options = m.defaults();
    std::string error;
    if (!options.apply(m.shorthands ? m.shorthands(text) : text, error) || !options.validate(error))
        texsyn::fuzz::expect_one_line(error, "option string");
    size_t bytes = 0;
    if (!texsyn::parse_memory_size(text, bytes, error))
        texsyn::fuzz::expect_one_line(error, "memory size");
    return 0;
}
