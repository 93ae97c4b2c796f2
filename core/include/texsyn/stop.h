// SPDX-License-Identifier: Apache-2.0
// Stopping a run early: a flag that any thread may set (a front end's Ctrl-C, a cancel
// button, a watchdog) and that the methods read between their steps and inside their long
// parallel loops, so that a run ends within about a second of it at any size.
#pragma once

#include <atomic>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// A request to stop a run. Set it (to true, from any thread) and the run stops at its
/// next check: the function fails with the message "stopped" and gives no result. The
/// run only reads it; it is never reset.
using StopFlag = std::atomic<bool>;

/// True if `stop` is given and set. Cheap enough for an inner loop's rows.
inline bool stop_requested(const StopFlag* stop) noexcept
{
    return stop && stop->load(std::memory_order_relaxed);
}

} // namespace texsyn
#pragma GCC visibility pop
