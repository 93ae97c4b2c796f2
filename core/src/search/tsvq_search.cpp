// SPDX-License-Identifier: Apache-2.0
// Tree-structured vector quantizer (Wei & Levoy 2000; the implementation report's §3.3.1,
// §6.2 and §6.3): a binary tree of codewords built by recursive 2-means, searched by
// best-first descent with backtracking over the `candidates` best leaves.
#include "distance_pvt.h"
#include "search_pvt.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {
namespace {

// A node stops splitting at this many vectors. The leaf scan is the exact part of the
// search: a leaf of b vectors costs b early-abandoned distances, one tree level two full
// ones, and the codewords take ~2 count / (average leaf) * dim floats. On texture
// neighbourhoods (rust.png, n=9) leaves of at most 16 hold 11 vectors on average: codewords
// 0.2x the vector set (0.4x with 8), a leaf scan about the price of the ~13-level descent,
// and closer matches than twice as many leaves of at most 8 for the same work.
constexpr uint32_t kBucket = 16;
// Generalized Lloyd (2-means) iterations per split after the initial partition; many
// splits converge sooner (the iteration stops when no vector changes side).
constexpr int kLloydIterations = 4;
// Vectors are processed in fixed chunks, whatever the thread count: every sum is formed per
// chunk and the chunks are combined in order, so the tree is identical for any nthreads.
constexpr uint32_t kTsvqChunk = 256;
// A node is split in parallel (over its chunks) when it holds this many floats.
constexpr size_t kParallelFloats = size_t(1) << 16;

inline void prefetch(const float* data, size_t bytes)
{
#if defined(__GNUC__)
    const char* p = reinterpret_cast<const char*>(data);
    for (size_t offset = 0; offset < bytes; offset += 64)
        __builtin_prefetch(p + offset);
#endif
}

struct Node {
    uint32_t begin = 0; ///< the node's vectors are m_order[begin, end)
    uint32_t end = 0;
    uint32_t child = 0; ///< left child (right = child + 1); 0 = leaf (the root is no child)
};

// Codewords, dim floats per node, in blocks of up to 256 nodes: the tree grows without
// reallocating, so building never holds two copies and nothing is over-reserved.
class Codewords {
public:
    Codewords(size_t dim, size_t count)
        : m_dim(dim)
    {
        // A tree over `count` vectors has at most 2 count - 1 nodes.
        while (m_shift < 8 && (size_t(1) << m_shift) < 2 * count)
            ++m_shift;
    }
    float* operator[](uint32_t node) const
    {
        return m_blocks[node >> m_shift].get() + size_t(node & ((1u << m_shift) - 1)) * m_dim;
    }
    void resize(uint32_t nodes)
    {
        while (m_blocks.size() << m_shift < nodes)
            m_blocks.emplace_back(new float[m_dim << m_shift]);
    }
    size_t bytes() const
    {
        return (m_blocks.size() * m_dim * sizeof(float) << m_shift)
            + m_blocks.capacity() * sizeof(m_blocks[0]);
    }

private:
    size_t m_dim;
    uint32_t m_shift = 0;
    std::vector<std::unique_ptr<float[]>> m_blocks;
};

struct Tree {
    std::vector<uint32_t> order; // vector indices, each node's a contiguous range
    std::vector<Node> nodes;     // nodes[0] is the root
    Codewords codewords;
    size_t depth = 0; // levels below the root
};

// Builds a Tree by recursive 2-means. Deterministic: chunked sums, ties to the left child
// and to the lowest position.
class TreeBuilder {
public:
    TreeBuilder(const VectorSet& vectors, int nthreads)
        : m_vectors(vectors)
        , m_dim(size_t(vectors.dim))
        , m_nthreads(nthreads)
        , m_side(vectors.count)
        , m_next_side(vectors.count)
        , m_partial(size_t(chunks(0, uint32_t(vectors.count))) * 2 * size_t(vectors.dim))
        , m_counts(size_t(chunks(0, uint32_t(vectors.count))) * 2)
        , m_c0(m_dim)
        , m_c1(m_dim)
        , m_n0(m_dim)
        , m_n1(m_dim)
    { }

    Tree build()
    {
        Tree tree { {}, {}, Codewords(m_dim, m_vectors.count) };
        tree.order.resize(m_vectors.count);
        std::iota(tree.order.begin(), tree.order.end(), 0u);
        m_tree = &tree;
        tree.nodes.push_back({ 0, uint32_t(m_vectors.count), 0 });
        tree.codewords.resize(1);
        std::fill(m_side.begin(), m_side.end(), 0);
        centroids(0, uint32_t(m_vectors.count), tree.codewords[0], m_c1.data());

        std::vector<std::pair<uint32_t, size_t>> stack { { 0u, size_t(0) } }; // node, depth
        while (!stack.empty()) {
            const auto [node, depth] = stack.back();
            stack.pop_back();
            tree.depth = std::max(tree.depth, depth);
            if (split(node)) {
                const uint32_t child = tree.nodes[node].child;
                stack.push_back({ child + 1, depth + 1 });
                stack.push_back({ child, depth + 1 });
            }
        }
        tree.nodes.shrink_to_fit();
        return tree;
    }

private:
    struct Extremes {
        float nearest = std::numeric_limits<float>::infinity(), farthest = -1.0f;
        uint32_t nearest_pos = 0, farthest_pos = 0;
        void add(float d, uint32_t pos)
        {
            if (d < nearest) {
                nearest = d;
                nearest_pos = pos;
            }
            if (d > farthest) {
                farthest = d;
                farthest_pos = pos;
            }
        }
    };

    static uint32_t chunks(uint32_t begin, uint32_t end)
    {
        return (end - begin + kTsvqChunk - 1) / kTsvqChunk;
    }

    const float* vec(uint32_t pos) const { return m_vectors.row(m_tree->order[pos]); }

    // f(c, chunk_begin, chunk_end) for each chunk c of positions [begin, end).
    template <class F>
    void for_chunks(uint32_t begin, uint32_t end, F&& f)
    {
        const uint32_t n = chunks(begin, end);
        auto run = [&](int64_t c) {
            const uint32_t b = begin + uint32_t(c) * kTsvqChunk;
            f(uint32_t(c), b, std::min(end, b + kTsvqChunk));
        };
        if (n > 1 && size_t(end - begin) * m_dim >= kParallelFloats)
            OIIO::parallel_for(int64_t(0), int64_t(n), run, detail::split_every_item(m_nthreads));
        else
            for (uint32_t c = 0; c < n; ++c)
                run(c);
    }

    // The positions in [begin, end) nearest to and farthest from `centre` (lowest first).
    Extremes extremes(uint32_t begin, uint32_t end, const float* centre)
    {
        m_extremes.assign(chunks(begin, end), Extremes {});
        for_chunks(begin, end, [&](uint32_t c, uint32_t b, uint32_t e) {
            for (uint32_t p = b; p < e; ++p)
                m_extremes[c].add(distance2(vec(p), centre, int(m_dim)), p);
        });
        // In chunk order, so that ties go to the lowest position.
        Extremes all;
        for (const Extremes& x : m_extremes) {
            all.add(x.nearest, x.nearest_pos);
            all.add(x.farthest, x.farthest_pos);
        }
        return all;
    }

    // m_next_side[p] = 1 where c1 is strictly nearer than c0 (the search's rule, bit for
    // bit, so every vector of the set descends to its own leaf). Returns the count of 1s
    // and, in `changed`, how many differ from m_side.
    uint32_t assign(
        uint32_t begin, uint32_t end, const float* c0, const float* c1, uint32_t& changed)
    {
        for_chunks(begin, end, [&](uint32_t c, uint32_t b, uint32_t e) {
            uint32_t ones = 0, diff = 0;
            for (uint32_t p = b; p < e; ++p) {
                const float* v = vec(p);
                const float d0 = distance2(v, c0, int(m_dim));
                const uint8_t side = distance2_below(v, c1, int(m_dim), d0) < d0 ? 1 : 0;
                m_next_side[p] = side;
                ones += side;
                diff += side != m_side[p];
            }
            m_counts[2 * c] = ones;
            m_counts[2 * c + 1] = diff;
        });
        uint32_t ones = 0;
        changed = 0;
        for (uint32_t c = 0; c < chunks(begin, end); ++c) {
            ones += m_counts[2 * c];
            changed += m_counts[2 * c + 1];
        }
        return ones;
    }

    // The centroids of the m_side == 0 and == 1 vectors of [begin, end) (a side without
    // vectors is left unchanged): float sums per chunk (at most 256 terms, so a relative
    // error ~1e-5 at worst: plenty for a split), added in chunk order in double.
    void centroids(uint32_t begin, uint32_t end, float* out0, float* out1)
    {
        const uint32_t n = chunks(begin, end);
        for_chunks(begin, end, [&](uint32_t c, uint32_t b, uint32_t e) {
            float* sum = m_partial.data() + size_t(c) * 2 * m_dim;
            std::fill(sum, sum + 2 * m_dim, 0.0f);
            uint32_t ones = 0;
            for (uint32_t p = b; p < e; ++p) {
                const float* v = vec(p);
                float* s = sum + m_side[p] * m_dim;
                ones += m_side[p];
                for (size_t k = 0; k < m_dim; ++k)
                    s[k] += v[k];
            }
            m_counts[2 * c] = (e - b) - ones;
            m_counts[2 * c + 1] = ones;
        });
        for (int side = 0; side < 2; ++side) {
            double count = 0;
            m_sum.assign(m_dim, 0.0);
            for (uint32_t c = 0; c < n; ++c) {
                count += m_counts[2 * c + side];
                const float* s = m_partial.data() + (size_t(c) * 2 + size_t(side)) * m_dim;
                for (size_t k = 0; k < m_dim; ++k)
                    m_sum[k] += s[k];
            }
            float* out = side ? out1 : out0;
            if (count > 0)
                for (size_t k = 0; k < m_dim; ++k)
                    out[k] = float(m_sum[k] / count);
        }
    }

    // A leaf whose vectors are all bit-identical keeps only the lowest index: the others
    // are at the same distance from any query and lose the tie.
    void make_leaf(uint32_t node)
    {
        Node& nd = m_tree->nodes[node];
        std::vector<uint32_t>& order = m_tree->order;
        const size_t bytes = m_dim * sizeof(float);
        for (uint32_t p = nd.begin + 1; p < nd.end; ++p)
            if (std::memcmp(vec(p), vec(nd.begin), bytes) != 0)
                return;
        std::iter_swap(order.begin() + nd.begin,
            std::min_element(order.begin() + nd.begin, order.begin() + nd.end));
        nd.end = nd.begin + 1;
    }

    // Splits `node` in two (false: it stays a leaf) by 2-means (generalized Lloyd). The
    // report's §6.2 starts from the vectors nearest to and farthest from the node's
    // codeword, but its outlier seed makes 2-means peel a few vectors off at every level
    // (rust.png n=9, leaves of at most 8: depth 96, leaves of 2.3 vectors, codewords 0.9x
    // the vector set). The same pair's direction is used instead as an LBG split: the seeds
    // are the codeword moved half the pair's difference either way, so the first partition
    // is the hyperplane through the centroid across that direction (same data: depth 15,
    // leaves of 5.5, codewords 0.4x, slightly closer matches). The children's codewords are
    // the centres the vectors were last assigned by: their centroids once the iteration
    // has converged.
    bool split(uint32_t node)
    {
        const uint32_t begin = m_tree->nodes[node].begin, end = m_tree->nodes[node].end;
        if (end - begin <= kBucket)
            return false;
        const int dim = int(m_dim);
        const float* centre = m_tree->codewords[node];
        const Extremes x = extremes(begin, end, centre);
        const float *a = vec(x.nearest_pos), *b = vec(x.farthest_pos);
        // All vectors equidistant from the centroid (two values alternating, say): the
        // farthest from the nearest instead.
        if (distance2(a, b, dim) == 0.0f)
            b = vec(extremes(begin, end, a).farthest_pos);
        for (size_t k = 0; k < m_dim; ++k) {
            const float half = 0.5f * (b[k] - a[k]);
            m_n0[k] = centre[k] - half;
            m_n1[k] = centre[k] + half;
        }
        std::fill(m_side.begin() + begin, m_side.begin() + end, 0);
        uint32_t changed = 0;
        for (int it = 0; it <= kLloydIterations; ++it) {
            const uint32_t ones = assign(begin, end, m_n0.data(), m_n1.data(), changed);
            // A side left empty: identical vectors (before the first iteration) or a
            // degenerate Lloyd step (keep the previous partition).
            if (ones == 0 || ones == end - begin) {
                if (it > 0)
                    break;
                make_leaf(node);
                return false;
            }
            std::swap(m_side, m_next_side);
            std::swap(m_c0, m_n0);
            std::swap(m_c1, m_n1);
            if (it == kLloydIterations || (it > 0 && changed == 0))
                break;
            centroids(begin, end, m_n0.data(), m_n1.data());
        }

        // Stable partition by side, into the two children's ranges.
        std::vector<uint32_t>& order = m_tree->order;
        m_scratch.clear();
        uint32_t out = begin;
        for (uint32_t p = begin; p < end; ++p)
            if (m_side[p])
                m_scratch.push_back(order[p]);
            else
                order[out++] = order[p];
        std::copy(m_scratch.begin(), m_scratch.end(), order.begin() + out);

        const uint32_t child = uint32_t(m_tree->nodes.size());
        m_tree->nodes[node].child = child;
        m_tree->nodes.push_back({ begin, out, 0 });
        m_tree->nodes.push_back({ out, end, 0 });
        m_tree->codewords.resize(child + 2);
        std::copy(m_c0.begin(), m_c0.end(), m_tree->codewords[child]);
        std::copy(m_c1.begin(), m_c1.end(), m_tree->codewords[child + 1]);
        return true;
    }

    VectorSet m_vectors;
    size_t m_dim;
    int m_nthreads;
    Tree* m_tree = nullptr;
    std::vector<uint8_t> m_side, m_next_side; // per position: 0 left, 1 right
    std::vector<float> m_partial;             // per chunk: both sides' sums
    std::vector<uint32_t> m_counts;           // per chunk: two counts
    std::vector<Extremes> m_extremes;         // per chunk
    std::vector<double> m_sum;
    std::vector<float> m_c0, m_c1, m_n0, m_n1; // current and next codewords
    std::vector<uint32_t> m_scratch;
};

class TsvqSearch final : public NeighborSearch {
public:
    TsvqSearch(const VectorSet& vectors, const SearchSettings& settings)
        : m_vectors(vectors)
        , m_candidates(uint32_t(settings.candidates))
        , m_tree(TreeBuilder(vectors, settings.nthreads).build())
    { }

    uint32_t nearest(const float* query, const uint32_t*, size_t) const override
    {
        Best best;
        if (m_candidates == 1) {
            scan(descend(0, query, nullptr), query, best);
            return best.index;
        }
        // The unexplored subtrees: one queue per thread (nearest() may run on several at
        // once), kept between queries so they do not allocate.
        thread_local std::vector<Entry> queue;
        queue.clear();
        queue.push_back({ 0.0f, 0 });
        for (uint32_t visited = 0; visited < m_candidates && !queue.empty(); ++visited) {
            std::pop_heap(queue.begin(), queue.end(), Entry::later);
            const uint32_t start = queue.back().node;
            queue.pop_back();
            scan(descend(start, query, &queue), query, best);
        }
        return best.index;
    }

    size_t memory_bytes() const override
    {
        return m_tree.order.capacity() * sizeof(uint32_t) + m_tree.nodes.capacity() * sizeof(Node)
            + m_tree.codewords.bytes();
    }

private:
    struct Best {
        float distance = std::numeric_limits<float>::infinity();
        uint32_t index = 0;
    };

    // An unexplored subtree, keyed by its codeword's distance to the query.
    struct Entry {
        float distance;
        uint32_t node;
        // The heap's order: the nearest (then the lowest node) comes out first.
        static bool later(const Entry& a, const Entry& b)
        {
            return a.distance > b.distance || (a.distance == b.distance && a.node > b.node);
        }
    };

    const float* codeword(uint32_t node) const { return m_tree.codewords[node]; }

    // Follows the nearer child codeword (ties left) from `node` to a leaf; pushes the other
    // child onto the heap `queue` if there is one (backtracking).
    uint32_t descend(uint32_t node, const float* query, std::vector<Entry>* queue) const
    {
        const int dim = m_vectors.dim;
        for (uint32_t child; (child = m_tree.nodes[node].child) != 0;) {
            const float d0 = distance2(query, codeword(child), dim);
            if (!queue) {
                node
                    = distance2_below(query, codeword(child + 1), dim, d0) < d0 ? child + 1 : child;
                continue;
            }
            const float d1 = distance2(query, codeword(child + 1), dim);
            const bool right = d1 < d0;
            queue->push_back({ right ? d0 : d1, right ? child : child + 1 });
            std::push_heap(queue->begin(), queue->end(), Entry::later);
            node = right ? child + 1 : child;
        }
        return node;
    }

    // Every vector of a leaf, exactly; ties to the lowest index (the bound is one ulp
    // above the best so that equal distances come back exact).
    void scan(uint32_t leaf, const float* query, Best& best) const
    {
        const Node& nd = m_tree.nodes[leaf];
        const int dim = m_vectors.dim;
        // The leaf's vectors are scattered over the set: ask for all of them at once (the
        // first 512 bytes each; the hardware streams the rest) rather than one miss at a
        // time. 10-15% of a synthesis at n=9.
        for (uint32_t p = nd.begin; p < nd.end; ++p)
            prefetch(
                m_vectors.row(m_tree.order[p]), std::min<size_t>(512, sizeof(float) * size_t(dim)));
        float bound = std::nextafter(best.distance, std::numeric_limits<float>::infinity());
        for (uint32_t p = nd.begin; p < nd.end; ++p) {
            const uint32_t i = m_tree.order[p];
            const float d = distance2_below(query, m_vectors.row(i), dim, bound);
            if (d < best.distance || (d == best.distance && i < best.index)) {
                best = { d, i };
                bound = std::nextafter(d, std::numeric_limits<float>::infinity());
            }
        }
    }

    VectorSet m_vectors;
    uint32_t m_candidates;
    Tree m_tree;
};

} // namespace

std::unique_ptr<NeighborSearch> make_tsvq_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error)
{
    if (settings.candidates < 1) {
        error = "tsvq search: candidates=" + std::to_string(settings.candidates)
            + " is out of range (at least 1 leaf is visited)";
        return nullptr;
    }
    return std::make_unique<TsvqSearch>(vectors, settings);
}

} // namespace texsyn::detail
