// SPDX-License-Identifier: Apache-2.0
// Counter-based random numbers: every draw is a pure function of (seed, stream, index),
// so results do not depend on the order in which threads draw them (DESIGN.md
// "Determinism"). Streams separate independent uses (e.g. one per channel).
#pragma once

#include <cstdint>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// 64 well-mixed bits for (seed, stream, index). Pure function; thread safe.
uint64_t random_bits(uint64_t seed, uint64_t stream, uint64_t index);

/// A float uniformly distributed in [0, 1) for (seed, stream, index), with 24 random
/// mantissa bits. Pure function; thread safe.
float random_uniform(uint64_t seed, uint64_t stream, uint64_t index);

} // namespace texsyn
#pragma GCC visibility pop
