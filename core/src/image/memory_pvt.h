// SPDX-License-Identifier: Apache-2.0
// A run's own memory budget (RunSettings::max_memory), in force on the thread that runs it.
#pragma once

#include <cstddef>

namespace texsyn::detail {

/// While it lives, check_memory() on this thread compares what work needs with `bytes`
/// (and what an address-space limit leaves) instead of the process-wide limit less what the
/// process holds: a host gives each run its budget, whatever the host itself uses. 0 keeps
/// the budget in force before it (none: the process-wide limit). Checks made on other
/// threads (inside a parallel loop) still use the process-wide limit.
class RunMemoryBudget {
public:
    explicit RunMemoryBudget(size_t bytes);
    ~RunMemoryBudget();
    RunMemoryBudget(const RunMemoryBudget&) = delete;
    RunMemoryBudget& operator=(const RunMemoryBudget&) = delete;

private:
    size_t previous_;
};

} // namespace texsyn::detail
