// SPDX-License-Identifier: Apache-2.0
// The libFuzzer entry point every fuzz target defines. Built with -fsanitize=fuzzer
// (tests/fuzz/run) it is fuzzed; built without, replay_main.cpp runs it over the seed
// corpus and the recorded crash inputs (a ctest case of the normal build).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace texsyn::fuzz {

/// Ends the process (a finding) unless `error` is one non-empty line: every refusal of
/// untrusted input must say why, on one line.
inline void expect_one_line(const std::string& error, const char* where)
{
    if (error.empty() || error.find('\n') != std::string::npos) {
        std::fprintf(stderr, "%s: bad error message '%s'\n", where, error.c_str());
        std::abort();
    }
}

} // namespace texsyn::fuzz
