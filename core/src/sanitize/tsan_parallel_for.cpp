// SPDX-License-Identifier: Apache-2.0
// ThreadSanitizer builds only (TEXSYN_SANITIZE=thread; docs/robustness.md).
//
// OIIO's parallel loops run tasks on its thread pool, which waits for them through
// futures polled with atomics inside libOpenImageIO_Util. That library is not
// instrumented, so ThreadSanitizer never sees that a loop's tasks finish before the loop
// returns, and reports every write made in a task and read after the loop as a race. These
// definitions interpose OIIO's loop entry points (libtexsyn comes before OIIO in the
// lookup order) with the same contracts, run on std::thread and joined, which
// ThreadSanitizer follows. Races between the tasks themselves are still reported: that
// is what the build is for. Like OIIO's pool, a loop started inside a task runs serially
// in that task.

#include <OpenImageIO/parallel.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

OIIO_NAMESPACE_BEGIN

namespace {

thread_local bool t_in_task = false;

/// Runs chunk(b, e) over [begin, end) in chunks of `chunksize` (0: twice as many chunks as
/// threads) on up to opt.maxthreads() threads (0: every core), and returns when all are done.
template <class Index, class Chunk>
void run_chunks(Index begin, Index end, int64_t chunksize, const paropt& opt, Chunk&& chunk)
{
    if (end <= begin)
        return;
    const int64_t count = int64_t(end - begin);
    int threads = opt.maxthreads() > 0 ? opt.maxthreads()
                                       : int(std::max(1u, std::thread::hardware_concurrency()));
    if (chunksize < 1)
        chunksize = std::max<int64_t>(1, count / (2 * int64_t(threads)));
    const int64_t chunks = (count + chunksize - 1) / chunksize;
    threads = t_in_task ? 1 : int(std::min<int64_t>(threads, chunks));
    std::atomic<int64_t> next { 0 };
    auto worker = [&] {
        const bool nested = t_in_task;
        t_in_task = true;
        for (int64_t c = next++; c < chunks; c = next++) {
            const int64_t b = c * chunksize;
            chunk(Index(begin + b), Index(begin + std::min(count, b + chunksize)));
        }
        t_in_task = nested;
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
        t.join();
}

template <class Index, class Task>
void each_index(Index begin, Index end, Task& task, const paropt& opt)
{
    run_chunks(begin, end, 0, opt, [&](Index b, Index e) {
        for (Index i = b; i < e; ++i)
            task(i);
    });
}

template <class Index, class Task>
void each_range(Index begin, Index end, Task& task, const paropt& opt)
{
    run_chunks(begin, end, 0, opt, [&](Index b, Index e) { task(b, e); });
}

} // namespace

void parallel_for_chunked(int64_t begin, int64_t end, int64_t chunksize,
    std::function<void(int64_t, int64_t)>&& task, paropt opt)
{
    run_chunks(begin, end, chunksize, opt, [&](int64_t b, int64_t e) { task(b, e); });
}

void parallel_for(int32_t begin, int32_t end, function_view<void(int32_t)> task, paropt opt)
{
    each_index(begin, end, task, opt);
}

void parallel_for(int64_t begin, int64_t end, function_view<void(int64_t)> task, paropt opt)
{
    each_index(begin, end, task, opt);
}

void parallel_for(uint32_t begin, uint32_t end, function_view<void(uint32_t)> task, paropt opt)
{
    each_index(begin, end, task, opt);
}

void parallel_for(uint64_t begin, uint64_t end, function_view<void(uint64_t)> task, paropt opt)
{
    each_index(begin, end, task, opt);
}

void parallel_for_range(
    int32_t begin, int32_t end, std::function<void(int32_t, int32_t)>&& task, paropt opt)
{
    each_range(begin, end, task, opt);
}

void parallel_for_range(
    int64_t begin, int64_t end, std::function<void(int64_t, int64_t)>&& task, paropt opt)
{
    each_range(begin, end, task, opt);
}

void parallel_for_range(
    uint32_t begin, uint32_t end, std::function<void(uint32_t, uint32_t)>&& task, paropt opt)
{
    each_range(begin, end, task, opt);
}

void parallel_for_range(
    uint64_t begin, uint64_t end, std::function<void(uint64_t, uint64_t)>&& task, paropt opt)
{
    each_range(begin, end, task, opt);
}

OIIO_NAMESPACE_END
