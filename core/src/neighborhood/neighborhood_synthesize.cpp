// SPDX-License-Identifier: Apache-2.0
// Wei & Levoy 2000: multi-resolution scanline synthesis with causal neighbourhoods.
#include <texsyn/neighborhood.h>

#include <algorithm>

#include <texsyn/pyramid.h>
#include <texsyn/random.h>

#include "methods/method_helpers_pvt.h"
#include "methods/source_map_pvt.h"
#include "neighborhood_pvt.h"

namespace texsyn {

namespace {

using detail::CandidateGrid;
using detail::NeighborhoodLayout;

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

int halved(int n, int times)
{
    for (int i = 0; i < times; ++i)
        n = (n + 1) / 2;
    return n;
}

// The most levels (<= opt.levels) whose sample level l is at least n_l wide and high.
int levels_the_sample_allows(int w, int h, const NeighborhoodOptions& opt)
{
    int l = 0;
    while (l < opt.levels && halved(w, l) >= opt.n_at(l) && halved(h, l) >= opt.n_at(l))
        ++l;
    return l;
}

using detail::NeighborAccess;
using detail::NeighborView;
using detail::OutputLevel;

// Noise drawn from the sample: each pixel a seeded random pixel of the sample level.
OutputLevel initial_level(const std::vector<Plane>& sample, int w, int h, uint64_t seed, int level)
{
    OutputLevel out;
    OutputLevel::Pixels& noise = out.initial;
    const uint64_t npixels = uint64_t(sample[0].width()) * uint64_t(sample[0].height());
    noise.source.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < noise.source.size(); ++i) {
        const uint64_t r = random_bits(seed, 0x4e42 + uint64_t(level), i) >> 32;
        noise.source[i] = uint32_t((r * npixels) >> 32);
    }
    for (const Plane& s : sample) {
        Plane p(w, h);
        for (size_t i = 0; i < noise.source.size(); ++i)
            p.data()[i] = s.data()[noise.source[i]];
        noise.channels.push_back(std::move(p));
    }
    out.live = noise;
    return out;
}

// The coherence hints for output pixel (x, y): for each neighbour at offset o, the sample
// candidate its source would continue to (source - o), each once. One per worker.
class HintCollector {
public:
    explicit HintCollector(size_t ncandidates)
        : m_stamp(ncandidates, 0)
    { }

    const std::vector<uint32_t>& collect(const NeighborhoodLayout& layout,
        const CandidateGrid& grid, const NeighborAccess& access, int sample_width, int x, int y)
    {
        ++m_pixel;
        m_hints.clear();
        for (size_t i = 0; i < layout.fine.size(); ++i) {
            const detail::Offset& o = layout.fine[i];
            const uint32_t s = access.neighbor_source(x, y, i);
            const int64_t c = grid.index(
                int(s % uint32_t(sample_width)) - o.dx, int(s / uint32_t(sample_width)) - o.dy);
            if (c >= 0 && m_stamp[size_t(c)] != m_pixel) {
                m_stamp[size_t(c)] = m_pixel;
                m_hints.push_back(uint32_t(c));
            }
        }
        return m_hints;
    }

private:
    std::vector<uint32_t> m_stamp; // the pixel a candidate was last added for
    uint32_t m_pixel = 0;
    std::vector<uint32_t> m_hints;
};

// Whether the seam band is re-synthesized (opt.tile; the debug square shape has no seams
// to repair: it already sees both sides).
bool repairs_seams(const NeighborhoodOptions& opt)
{
    return opt.tile != 0 && opt.shape == NeighborhoodShape::Causal;
}

SearchSettings search_settings(const NeighborhoodOptions& opt)
{
    SearchSettings s;
    s.method = opt.search;
    s.candidates = opt.candidates;
    s.dims = opt.dims;
    s.eps = opt.eps;
    s.coherence = opt.coherence;
    s.merge = opt.merge != 0;
    s.nthreads = opt.nthreads;
    return s;
}

// The search of one level for one neighbourhood shape: the sample's vectors, a searcher
// over them, and the step that picks and copies one output pixel, which several workers may
// take at once (each with its own Worker).
class LevelSearch {
public:
    // What one worker needs for itself: its query vector and coherence hints.
    struct Worker {
        std::vector<float> query;
        std::unique_ptr<HintCollector> hints;
    };

    LevelSearch(const NeighborhoodLayout& layout, const std::vector<Plane>& sample,
        const std::vector<Plane>& sample_coarser, const NeighborhoodOptions& opt,
        std::string& error)
        : m_layout(layout)
        , m_sample(sample)
        , m_grid(detail::candidate_grid(layout, sample[0].width(), sample[0].height()))
        , m_vectors(detail::sample_vectors(layout, m_grid, sample, sample_coarser, opt.nthreads))
        , m_coherent(opt.search == SearchMethod::Coherent)
    {
        VectorSet set;
        set.data = m_vectors.data();
        set.count = m_grid.count();
        set.dim = layout.npixels() * int(sample.size());
        m_search = make_search(set, search_settings(opt), error);
    }

    bool ok() const { return bool(m_search); }
    const NeighborhoodLayout& layout() const { return m_layout; }

    Worker make_worker() const
    {
        Worker w;
        w.query.resize(size_t(m_layout.npixels()) * m_sample.size());
        if (m_coherent)
            w.hints = std::make_unique<HintCollector>(m_grid.count());
        return w;
    }

    // Output pixel (x, y) of `out` becomes the sample pixel whose neighbourhood best matches
    // its own, read through `access`.
    void synthesize_pixel(
        OutputLevel& out, const NeighborAccess& access, Worker& worker, int x, int y) const
    {
        const int sw = m_sample[0].width(), w = out.width();
        access.gather(x, y, worker.query.data());
        const std::vector<uint32_t>* hints
            = worker.hints ? &worker.hints->collect(m_layout, m_grid, access, sw, x, y) : nullptr;
        const uint32_t best = m_search->nearest(
            worker.query.data(), hints ? hints->data() : nullptr, hints ? hints->size() : 0);
        const size_t from = size_t(m_grid.y(best)) * size_t(sw) + size_t(m_grid.x(best));
        const size_t to = size_t(y) * size_t(w) + size_t(x);
        for (size_t c = 0; c < m_sample.size(); ++c)
            out.live.channels[c].data()[to] = m_sample[c].data()[from];
        out.live.source[to] = uint32_t(from);
    }

private:
    NeighborhoodLayout m_layout;
    const std::vector<Plane>& m_sample;
    CandidateGrid m_grid;
    detail::SampleVectors m_vectors;
    bool m_coherent;
    std::unique_ptr<NeighborSearch> m_search;
};

// Synthesizes output level `l` in scanline order; `coarser` is the synthesized level l+1
// (empty at the coarsest). With opt.tile, then re-synthesizes the seam band
// (detail::repair_seams). `done`/`total` count
// pixels over all levels for progress.
bool synthesize_level(OutputLevel& out, const std::vector<Plane>& sample,
    const std::vector<Plane>& sample_coarser, const std::vector<Plane>& coarser,
    const NeighborhoodOptions& opt, int l, size_t& done, size_t total, std::string& error)
{
    const int w = out.width(), h = out.height();
    auto report = [&](size_t pixels) {
        done += pixels;
        detail::report_progress(opt.progress, opt.stop, float(double(done) / double(total)));
    };
    {
        const LevelSearch search(
            detail::make_layout(opt.n_at(l), opt.coarse, !coarser.empty(), opt.shape), sample,
            sample_coarser, opt, error);
        if (!search.ok())
            return false;
        const NeighborAccess access(search.layout(), out, coarser, NeighborView::Scanline);
        // The exhaustive search parallelises over the candidates of one pixel instead.
        const int workers
            = opt.search == SearchMethod::Exhaustive ? 1 : detail::resolve_threads(opt.nthreads);
        std::vector<LevelSearch::Worker> scratch;
        for (int t = 0; t < workers; ++t)
            scratch.push_back(search.make_worker());
        detail::scanline_pass(
            w, h, access.reach(), int(scratch.size()),
            [&](int worker, int x, int y) {
                search.synthesize_pixel(out, access, scratch[size_t(worker)], x, y);
            },
            [&] { report(size_t(w)); });
    }
    if (repairs_seams(opt)) {
        detail::repair_seams(out, sample, sample_coarser, coarser, opt.n_at(l), opt.coarse);
        report(detail::seam_band(w, h, (opt.n_at(l) - 1) / 2).size());
    }
    return true;
}

bool synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const NeighborhoodOptions& opt,
    OIIO::ImageBuf* source_map)
{
    PlanarImage in;
    if (!detail::validated_sample(dst, sample, opt, in))
        return false;
    std::string error;
    const int sw = in.width(), sh = in.height();
    const int w = opt.width ? opt.width : sw, h = opt.height ? opt.height : sh;
    if (!detail::check_neighborhood_sizes(sw, sh, w, h, opt, error)
        || !detail::check_memory(neighborhood_memory_estimate(sw, sh, in.nchannels(), w, h, opt),
            "size=" + size_text(w, h), error)) {
        dst.errorfmt("{}", error);
        return false;
    }

    const auto sample_levels
        = gaussian_pyramid(in.channels, opt.levels, Boundary::Reflect, opt.nthreads);
    size_t total = 0, done = 0;
    for (int l = 0; l < opt.levels; ++l) {
        const int lw = halved(w, l), lh = halved(h, l);
        total += size_t(lw) * size_t(lh);
        if (repairs_seams(opt))
            total += detail::seam_band(lw, lh, (opt.n_at(l) - 1) / 2).size();
    }
    OutputLevel coarser, out;
    static const std::vector<Plane> none;
    for (int l = opt.levels - 1; l >= 0; --l) {
        out = initial_level(sample_levels[size_t(l)], halved(w, l), halved(h, l), opt.seed, l);
        const bool top = l == opt.levels - 1;
        if (!synthesize_level(out, sample_levels[size_t(l)],
                top ? none : sample_levels[size_t(l + 1)], top ? none : coarser.live.channels, opt,
                l, done, total, error)) {
            dst.errorfmt("{}", error);
            return false;
        }
        coarser = std::move(out);
    }

    NeighborhoodOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    if (source_map)
        detail::write_source_map(*source_map, coarser.live.source, w, h, sw, sw, sh);
    detail::write_synthesis(
        dst, coarser.live.channels, in, sample, "neighborhood", resolved, source_map);
    return true;
}

} // namespace

bool neighborhood_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const NeighborhoodOptions& opt, OIIO::ImageBuf* source_map)
{
    return detail::guarded(
        dst, "neighborhood_synthesize", [&] { return synthesize(dst, sample, opt, source_map); });
}

OIIO::ImageBuf neighborhood_synthesize(
    const OIIO::ImageBuf& sample, const NeighborhoodOptions& opt, OIIO::ImageBuf* source_map)
{
    return detail::value_form("neighborhood_synthesize",
        [&](OIIO::ImageBuf& dst) { return neighborhood_synthesize(dst, sample, opt, source_map); });
}

namespace detail {

bool check_neighborhood_sizes(
    int sw, int sh, int w, int h, const NeighborhoodOptions& opt, std::string& error)
{
    const int allowed = levels_the_sample_allows(sw, sh, opt);
    if (allowed == 0) {
        error = "the sample (" + size_text(sw, sh)
            + ") is smaller than the n=" + std::to_string(opt.n_at(0)) + " neighbourhood";
        return false;
    }
    if (allowed < opt.levels) {
        error = "levels=" + std::to_string(opt.levels) + " is too many for the sample ("
            + size_text(sw, sh) + "): level " + std::to_string(allowed) + " would be "
            + size_text(halved(sw, allowed), halved(sh, allowed))
            + ", smaller than its n=" + std::to_string(opt.n_at(allowed))
            + " neighbourhood (use levels=" + std::to_string(allowed) + " or less)";
        return false;
    }
    for (int l = 0; l < opt.levels; ++l) {
        const int lw = halved(w, l), lh = halved(h, l), n = opt.n_at(l);
        if (lw < n || lh < n) {
            error = "size=" + size_text(w, h)
                + " is too small for levels=" + std::to_string(opt.levels) + ": output level "
                + std::to_string(l) + " would be " + size_text(lw, lh)
                + ", smaller than its n=" + std::to_string(n) + " neighbourhood";
            return false;
        }
    }
    return true;
}

} // namespace detail

} // namespace texsyn
