// SPDX-License-Identifier: Apache-2.0
// A decompression bomb for tests: a real PNG whose header claims far more pixels than its
// data holds.
#pragma once

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace texsyn::test {

inline uint32_t crc32(const unsigned char* p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

/// The bytes of the PNG file `small_png` with its header claiming `side` x `side` pixels
/// (the IHDR's checksum fixed, so that readers get as far as the size).
inline std::string png_bomb(const std::string& small_png, uint32_t side)
{
    std::ifstream in(small_png, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string bytes = ss.str();
    // Signature (8), IHDR length (4), "IHDR" (4), width (4), height (4), 5 more bytes,
    // then the CRC of "IHDR" and its 13 data bytes.
    auto put_be = [&](size_t at, uint32_t v) {
        for (int i = 0; i < 4; ++i)
            bytes[at + size_t(i)] = char((v >> (24 - 8 * i)) & 0xff);
    };
    put_be(16, side);
    put_be(20, side);
    put_be(29, crc32(reinterpret_cast<const unsigned char*>(bytes.data()) + 12, 17));
    return bytes;
}

} // namespace texsyn::test
