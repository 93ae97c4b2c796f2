// SPDX-License-Identifier: Apache-2.0
// LSD radix ranking of floats: the per-iteration cost of exact histogram matching.
#include "histogram_pvt.h"

#include <array>
#include <cstring>
#include <type_traits>
#include <vector>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn {
namespace histogram_pvt {
namespace {

// 4 passes of 8 bits: measured faster than 3 x 11 bits, whose 2048 scatter streams
// thrash L1 and the TLB (about 4 ms vs 1 ms per pass on 1M values).
constexpr int kBits = 8;
constexpr int kPasses = 4;
constexpr uint32_t kBuckets = 1u << kBits;
// Fixed chunking of the counting pass, so the work split never depends on nthreads
// (the counts are integers, so the sum is exact in any case).
constexpr size_t kChunk = size_t(1) << 16;

using Histograms = std::array<uint32_t, kPasses * kBuckets>;

// Float bits -> uint32 whose unsigned order is the float order: negatives are inverted,
// positives get the sign bit. -0 is first mapped to +0 so that they tie (and are ranked by
// index), as a value comparison would. Branch-free: signs of a band are random, and a
// mispredicted branch per value tripled the cost of the first pass.
inline uint32_t monotone_key(float v)
{
    uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    u &= ~(uint32_t(u == 0x80000000u) << 31);
    const uint32_t mask = uint32_t(-int32_t(u >> 31)) | 0x80000000u;
    return u ^ mask;
}

inline uint32_t digit(uint32_t key, int pass)
{
    return (key >> (pass * kBits)) & (kBuckets - 1);
}

// The entry buffers of the passes, reused by the thread's next call. Only the serial
// passes touch them: while a thread waits in the parallel count below, OIIO's pool may
// run another ranking on it (work stealing), which may use them freely.
struct Scratch {
    std::vector<uint64_t> a, b;
};
thread_local Scratch tl_scratch;

// Per-chunk digit counts: local to the call, never thread-local, since the calling thread
// may run other rankings while it waits for the chunks.
void count_digits(const float* values, size_t n, Histograms& total, int nthreads)
{
    const size_t nchunks = (n + kChunk - 1) / kChunk;
    std::vector<Histograms> chunk_hist(nchunks);
    OIIO::parallel_for_chunked(
        0, int64_t(n), int64_t(kChunk),
        [&](int64_t begin, int64_t end) {
            Histograms& h = chunk_hist[size_t(begin) / kChunk];
            h.fill(0);
            for (int64_t i = begin; i < end; ++i) {
                const uint32_t key = monotone_key(values[i]);
                for (int p = 0; p < kPasses; ++p)
                    ++h[p * kBuckets + digit(key, p)];
            }
        },
        detail::split_every_item(nthreads));
    total.fill(0);
    for (const Histograms& h : chunk_hist)
        for (size_t j = 0; j < total.size(); ++j)
            total[j] += h[j];
}

} // namespace

namespace {

// LSD radix passes over (key, index) entries; passes whose digit is the same for every key
// are skipped (a stable pass would not move anything). The last moving pass calls
// last(position, entry) for every entry instead of scattering it, when `Last` is not
// std::nullptr_t. Returns the sorted entries, nullptr if no pass moved anything (all keys
// equal: the order is the identity), or the end marker `fused` if `last` consumed them.
const uint64_t fused_marker = 0;

template <class Last>
const uint64_t* radix_passes(const float* values, size_t n, int nthreads, Last last)
{
    Histograms hist;
    count_digits(values, n, hist, nthreads);
    Scratch& s = tl_scratch;
    s.a.resize(n);
    s.b.resize(n);

    const uint32_t first_key = monotone_key(values[0]);
    int moving[kPasses], nmoving = 0;
    for (int p = 0; p < kPasses; ++p)
        if (hist[size_t(p) * kBuckets + digit(first_key, p)] != n)
            moving[nmoving++] = p;
    // A fused last pass must not be the first: that one reads its keys from `values`,
    // which `last` may be rewriting.
    constexpr bool has_last = !std::is_same_v<Last, std::nullptr_t>;
    const bool fuse = has_last && nmoving > 1;

    const uint64_t* src = nullptr; // nullptr: read keys from `values` in index order
    uint64_t* dst = s.a.data();
    std::array<size_t, kBuckets> offset;
    for (int m = 0; m < nmoving; ++m) {
        const int p = moving[m];
        const uint32_t* h = hist.data() + p * kBuckets;
        size_t sum = 0;
        for (uint32_t d = 0; d < kBuckets; ++d) {
            offset[d] = sum;
            sum += h[d];
        }
        // Stable scatter, so equal keys keep index order: ties are ranked by index.
        if (!src) {
            for (size_t i = 0; i < n; ++i) {
                const uint32_t key = monotone_key(values[i]);
                dst[offset[digit(key, p)]++] = (uint64_t(key) << 32) | uint64_t(i);
            }
        } else if (fuse && m == nmoving - 1) {
            if constexpr (has_last)
                for (size_t i = 0; i < n; ++i) {
                    const uint64_t e = src[i];
                    last(offset[digit(uint32_t(e >> 32), p)]++, e);
                }
            return &fused_marker;
        } else {
            for (size_t i = 0; i < n; ++i) {
                const uint64_t e = src[i];
                dst[offset[digit(uint32_t(e >> 32), p)]++] = e;
            }
        }
        src = dst;
        dst = (dst == s.a.data()) ? s.b.data() : s.a.data();
    }
    return src;
}

} // namespace

const uint64_t* rank_by_value(const float* values, size_t n, int nthreads)
{
    return radix_passes(values, n, nthreads, nullptr);
}

void assign_quantiles_by_rank(float* values, size_t n, const float* sorted, size_t m, int nthreads)
{
    const double dn = double(n);
    auto assign = [&](size_t rank, uint64_t entry) {
        values[uint32_t(entry)] = quantile_of_sorted(sorted, m, (double(rank) + 0.5) / dn);
    };
    const uint64_t* order = radix_passes(values, n, nthreads, assign);
    if (order == &fused_marker)
        return;
    // Not fused (fewer than two moving passes): assign from the sorted order.
    for (size_t i = 0; i < n; ++i)
        assign(i, order ? order[i] : uint64_t(i));
}

} // namespace histogram_pvt
} // namespace texsyn
