// SPDX-License-Identifier: Apache-2.0
// Analysis files (.tsa): any bytes are refused with one line or read into consistent
// statistics. The first input byte is a switch: odd, the file's trailing checksum is
// recomputed first (FNV-1a 64, docs/analysis-files.md), so that mutations reach the header
// and table checks behind it instead of all failing the checksum.
#include "fuzz_target.h"

#include <cstring>

#include <texsyn/stats.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    if ((data[0] & 1) && bytes.size() >= 8) {
        uint64_t h = 14695981039346656037ull;
        for (size_t i = 0; i < bytes.size() - 8; ++i)
            h = (h ^ uint8_t(bytes[i])) * 1099511628211ull;
        std::memcpy(&bytes[bytes.size() - 8], &h, 8);
    }
    texsyn::TextureStatistics stats;
    std::string error;
    if (!texsyn::parse_statistics(bytes, "fuzz.tsa", stats, error)) {
        texsyn::fuzz::expect_one_line(error, "analysis file");
        return 0;
    }
    if (stats.components.size() != size_t(stats.nchannels())
        || stats.channels.size() != stats.components.size())
        std::abort();
    return 0;
}
