// SPDX-License-Identifier: Apache-2.0
// How much memory a run may use, and refusing work that would need more before any of it
// is allocated (a decompression bomb, an absurd size): a refusal names the estimate and
// the limit, where an allocation failure would crash or be half-reported.
#pragma once

#include <cstddef>
#include <string>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// The most memory, in bytes, one process of texsyn may use: set_memory_limit()'s value
/// if one was set, else $TEXSYN_MAX_MEMORY (same syntax as parse_memory_size), else 90%
/// of the smallest of physical memory and the cgroup's memory limit. An address-space
/// limit (ulimit -v) lowers what is available further (memory_available()).
size_t memory_limit();

/// Sets memory_limit() (the command line's --max-memory); 0 restores the default.
void set_memory_limit(size_t bytes);

/// What memory_limit() leaves now: the limit less what the process already holds, and no
/// more than its address-space limit leaves.
size_t memory_available();

/// Parses a memory size: bytes ("1500000000"), with a binary unit ("512M", "8G", "1.5T",
/// "64K"; an optional trailing "B"), or a share of physical memory ("50%"). False (with
/// a reason) for anything else or zero.
bool parse_memory_size(const std::string& text, size_t& bytes, std::string& error);

/// False, with "WHAT would need about N of memory (M available, limit L: --max-memory)",
/// if `need` bytes exceed memory_available(). Inside run_method() with a budget
/// (RunSettings::max_memory), on the thread that called it, the budget takes the place of
/// memory_available(): what the process already holds does not count against it.
bool check_memory(size_t need, const std::string& what, std::string& error);

/// "1.5 GB": bytes in binary units with one decimal.
std::string format_bytes(double bytes);

} // namespace texsyn
#pragma GCC visibility pop
