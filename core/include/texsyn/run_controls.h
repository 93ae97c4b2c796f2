// SPDX-License-Identifier: Apache-2.0
// What every synthesis takes besides its options: the seed, the threads, a progress
// callback and a stop flag. Declared once here; every method's options struct and
// RunSettings (methods.h) derive from it, so a front end sets them the same way for all.
#pragma once

#include <cstdint>
#include <functional>

#include <texsyn/stop.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// The controls of one run. None of them is an option (`:name=`), none is in a recipe, and
/// only `seed` changes the result: the same seed gives bit-identical output whatever
/// `nthreads` is.
struct RunControls {
    /// The random seed (the tool's --seed).
    uint64_t seed = 0;
    /// Threads for the run's parallel loops; 0 = OIIO's default.
    int nthreads = 0;
    /// Called with the fraction done (0..1) from the calling thread, outside parallel loops;
    /// may be empty. It may throw to stop the run (a front end's cancellation): the run then
    /// fails with the exception's message.
    std::function<void(float)> progress;
    /// Set from any thread to stop the run (stop.h); may be null.
    const StopFlag* stop = nullptr;
};

} // namespace texsyn
#pragma GCC visibility pop
