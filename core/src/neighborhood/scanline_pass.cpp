// SPDX-License-Identifier: Apache-2.0
// The scanline pass as a wavefront: row y runs `reach` + 1 pixels behind row y - 1.
#include "neighborhood_pvt.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <thread>

#include <OpenImageIO/imageio.h>

namespace texsyn::detail {

int resolve_threads(int nthreads)
{
    if (nthreads > 0)
        return nthreads;
    int threads = 0;
    if (!OIIO::getattribute("threads", threads) || threads < 1)
        threads = int(std::thread::hardware_concurrency());
    return std::max(1, threads);
}

void scanline_pass(int width, int height, int reach, int nthreads,
    const std::function<void(int, int, int)>& pixel, const std::function<void()>& row_done)
{
    const int workers = std::max(1, std::min(nthreads, height));
    if (workers == 1) {
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x)
                pixel(0, x, y);
            row_done();
        }
        return;
    }
    // progress[y]: pixels of row y done. Rows are handed out in order.
    std::unique_ptr<std::atomic<int>[]> progress(new std::atomic<int>[size_t(height)]);
    for (int y = 0; y < height; ++y)
        progress[size_t(y)].store(0, std::memory_order_relaxed);
    std::atomic<int> next_row { 0 }, rows_done { 0 };
    std::atomic<bool> failed { false };
    std::exception_ptr error;
    std::atomic_flag error_taken = ATOMIC_FLAG_INIT;
    // Only the calling thread (worker 0) reports rows, as they complete.
    int reported = 0;
    auto report = [&] {
        for (const int done = rows_done.load(); reported < done; ++reported)
            row_done();
    };
    auto run = [&](int worker) {
        try {
            for (int y; !failed.load() && (y = next_row.fetch_add(1)) < height;) {
                for (int x = 0; x < width; ++x) {
                    if (y > 0) {
                        const int need = std::min(x + reach, width - 1) + 1;
                        for (int spins = 0;
                             progress[size_t(y - 1)].load(std::memory_order_acquire) < need;
                             ++spins) {
                            if (failed.load())
                                return;
                            if (spins > 64)
                                std::this_thread::yield();
                        }
                    }
                    pixel(worker, x, y);
                    progress[size_t(y)].store(x + 1, std::memory_order_release);
                }
                rows_done.fetch_add(1);
                if (worker == 0)
                    report();
            }
        } catch (...) {
            if (!error_taken.test_and_set())
                error = std::current_exception();
            failed.store(true);
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < workers; ++t)
        threads.emplace_back(run, t);
    run(0);
    while (rows_done.load() < height && !failed.load()) {
        report();
        std::this_thread::yield();
    }
    for (std::thread& t : threads)
        t.join();
    if (error)
        std::rethrow_exception(error);
    report();
}

} // namespace texsyn::detail
