// SPDX-License-Identifier: Apache-2.0
#include <texsyn/random.h>

namespace texsyn {

namespace {

// SplitMix64's finaliser (Steele, Lea & Flood 2014): a bijective mix with full avalanche.
uint64_t mix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

} // namespace

uint64_t random_bits(uint64_t seed, uint64_t stream, uint64_t index)
{
    // Chaining the mix keeps (seed, stream, index) triples that differ in any word apart.
    return mix64(mix64(mix64(seed) ^ stream) ^ index);
}

float random_uniform(uint64_t seed, uint64_t stream, uint64_t index)
{
    return float(random_bits(seed, stream, index) >> 40) * (1.0f / 16777216.0f);
}

} // namespace texsyn
