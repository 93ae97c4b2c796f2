// SPDX-License-Identifier: Apache-2.0
#include <texsyn/memory.h>

#include "memory_pvt.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <sys/resource.h>
#include <unistd.h>

namespace texsyn {

namespace {

std::atomic<size_t> user_limit { 0 };

size_t physical_memory()
{
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(0);
}

// The first number in a file, or 0 ("max", missing file).
size_t read_number(const char* path)
{
    std::ifstream in(path);
    unsigned long long v = 0;
    return (in >> v) ? size_t(v) : size_t(0);
}

// The cgroup's memory limit (v2, else v1), or 0 when none is set.
size_t cgroup_limit()
{
    size_t v2 = read_number("/sys/fs/cgroup/memory.max");
    if (v2)
        return v2;
    size_t v1 = read_number("/sys/fs/cgroup/memory/memory.limit_in_bytes");
    return v1 < (size_t(1) << 60) ? v1 : 0; // v1 says "no limit" with a huge number
}

// Field `index` (0 = total size, 1 = resident) of /proc/self/statm, in bytes.
size_t statm_bytes(int index)
{
    std::ifstream in("/proc/self/statm");
    unsigned long long v[2] = { 0, 0 };
    in >> v[0] >> v[1];
    return size_t(v[index]) * size_t(::sysconf(_SC_PAGE_SIZE));
}

size_t default_limit()
{
    if (const char* env = std::getenv("TEXSYN_MAX_MEMORY")) {
        size_t bytes = 0;
        std::string ignored;
        if (parse_memory_size(env, bytes, ignored))
            return bytes;
    }
    size_t limit = physical_memory();
    const size_t cgroup = cgroup_limit();
    if (cgroup && (!limit || cgroup < limit))
        limit = cgroup;
    return limit ? size_t(double(limit) * 0.9) : size_t(0);
}

} // namespace

size_t memory_limit()
{
    const size_t user = user_limit.load();
    return user ? user : default_limit();
}

void set_memory_limit(size_t bytes)
{
    user_limit.store(bytes);
}

namespace {

// The budget of the run on this thread (detail::RunMemoryBudget), 0 for none.
thread_local size_t run_budget = 0;

// What the address-space limit (ulimit -v) leaves mapping, SIZE_MAX without one.
size_t address_space_left()
{
    struct rlimit as { };
    if (::getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY)
        return SIZE_MAX;
    const size_t mapped = statm_bytes(0);
    return size_t(as.rlim_cur) > mapped ? size_t(as.rlim_cur) - mapped : 0;
}

} // namespace

size_t memory_available()
{
    const size_t limit = memory_limit();
    const size_t available = limit ? limit - std::min(limit, statm_bytes(1)) : SIZE_MAX;
    return std::min(available, address_space_left());
}

bool parse_memory_size(const std::string& text, size_t& bytes, std::string& error)
{
    const char* s = text.c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    std::string unit(end);
    if (!unit.empty() && unit.size() > 1 && (unit.back() == 'B' || unit.back() == 'b'))
        unit.pop_back();
    double scale = -1.0;
    if (unit.empty())
        scale = 1.0;
    else if (unit.size() == 1) {
        switch (unit[0]) {
        case 'K':
        case 'k':
            scale = 1024.0;
            break;
        case 'M':
        case 'm':
            scale = 1024.0 * 1024.0;
            break;
        case 'G':
        case 'g':
            scale = 1024.0 * 1024.0 * 1024.0;
            break;
        case 'T':
        case 't':
            scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
            break;
        case '%':
            scale = double(physical_memory()) / 100.0;
            break;
        default:
            break;
        }
    }
    const double b = v * scale;
    if (end == s || scale < 0.0 || !std::isfinite(b) || b < 1.0 || b > 1.0e18
        || (unit == "%" && v > 100.0)) {
        error = "expected a memory size such as 8G, 512M, 1500000000 or 50%";
        return false;
    }
    bytes = size_t(b);
    return true;
}

std::string format_bytes(double bytes)
{
    const char* units[] = { "B", "KB", "MB", "GB", "TB", "PB", "EB" };
    int u = 0;
    while (bytes >= 1024.0 && u < 6) {
        bytes /= 1024.0;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.1f %s", bytes, units[u]);
    return buf;
}

bool check_memory(size_t need, const std::string& what, std::string& error)
{
    if (run_budget) {
        const size_t available = std::min(run_budget, address_space_left());
        if (need <= available)
            return true;
        error = what + " would need about " + format_bytes(double(need))
            + " of memory (this run's budget is " + format_bytes(double(run_budget))
            + (available < run_budget
                    ? ", and the address-space limit leaves " + format_bytes(double(available))
                    : std::string())
            + ": RunSettings::max_memory)";
        return false;
    }
    const size_t available = memory_available();
    if (need <= available)
        return true;
    // What the process holds already (libraries, inputs) counts against the limit: say so,
    // or a limit below it reads as a refusal of everything.
    error = what + " would need about " + format_bytes(double(need)) + " of memory (only "
        + format_bytes(double(available)) + " available of a limit of "
        + format_bytes(double(memory_limit())) + ", of which the process holds "
        + format_bytes(double(statm_bytes(1))) + ": see --max-memory or $TEXSYN_MAX_MEMORY)";
    return false;
}

namespace detail {

RunMemoryBudget::RunMemoryBudget(size_t bytes)
    : previous_(run_budget)
{
    if (bytes)
        run_budget = bytes;
}

RunMemoryBudget::~RunMemoryBudget()
{
    run_budget = previous_;
}

} // namespace detail

} // namespace texsyn
