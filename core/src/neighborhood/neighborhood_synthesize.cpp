// SPDX-License-Identifier: Apache-2.0
// Wei & Levoy 2000: multi-resolution scanline synthesis with causal neighbourhoods.
#include <texsyn/neighborhood.h>

#include <algorithm>

#include <texsyn/pyramid.h>
#include <texsyn/random.h>
#include <texsyn/synthesis.h>

#include "neighborhood_pvt.h"
#include "synthesis/synthesis_pvt.h"

namespace texsyn {

namespace {

using detail::CandidateGrid;
using detail::NeighborhoodLayout;

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

// Gaussian pyramid of every channel: levels[l][c], level 0 the image itself.
std::vector<std::vector<Plane>> gaussian_levels(
    const std::vector<Plane>& image, int nlevels, Boundary boundary, int nthreads)
{
    std::vector<std::vector<Plane>> levels(static_cast<size_t>(nlevels));
    levels[0] = image;
    for (int l = 1; l < nlevels; ++l)
        for (const Plane& p : levels[size_t(l - 1)])
            levels[size_t(l)].push_back(reduce_plane(p, boundary, nthreads));
    return levels;
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

bool check_sizes(int sw, int sh, int w, int h, const NeighborhoodOptions& opt, std::string& error)
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

// One output level being synthesized: its channels and, per pixel, the index of the sample
// pixel (at the same level) it holds.
struct OutputLevel {
    std::vector<Plane> channels;
    std::vector<uint32_t> source;
};

// Noise drawn from the sample: each pixel a seeded random pixel of the sample level.
OutputLevel initial_level(const std::vector<Plane>& sample, int w, int h, uint64_t seed, int level)
{
    OutputLevel out;
    const uint64_t npixels = uint64_t(sample[0].width()) * uint64_t(sample[0].height());
    out.source.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < out.source.size(); ++i) {
        const uint64_t r = random_bits(seed, 0x4e42 + uint64_t(level), i) >> 32;
        out.source[i] = uint32_t((r * npixels) >> 32);
    }
    for (const Plane& s : sample) {
        Plane p(w, h);
        for (size_t i = 0; i < out.source.size(); ++i)
            p.data()[i] = s.data()[out.source[i]];
        out.channels.push_back(std::move(p));
    }
    return out;
}

// The coherence hints for output pixel (x, y): for each neighbour at offset o, the sample
// candidate its source would continue to (source - o), each once.
class HintCollector {
public:
    explicit HintCollector(size_t ncandidates)
        : m_stamp(ncandidates, 0)
    { }

    const std::vector<uint32_t>& collect(const NeighborhoodLayout& layout,
        const CandidateGrid& grid, const OutputLevel& out, int sample_width, int x, int y)
    {
        ++m_pixel;
        m_hints.clear();
        const int w = out.channels[0].width(), h = out.channels[0].height();
        for (const detail::Offset& o : layout.fine) {
            const int qx = detail::wrap(x + o.dx, w), qy = detail::wrap(y + o.dy, h);
            const uint32_t s = out.source[size_t(qy) * size_t(w) + size_t(qx)];
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

// Synthesizes output level `l` in scanline order; `coarser` is the synthesized level l+1
// (empty at the coarsest). `done`/`total` count pixels over all levels for progress.
bool synthesize_level(OutputLevel& out, const std::vector<Plane>& sample,
    const std::vector<Plane>& sample_coarser, const std::vector<Plane>& coarser,
    const NeighborhoodOptions& opt, int l, size_t& done, size_t total, std::string& error)
{
    const NeighborhoodLayout layout
        = detail::make_layout(opt.n_at(l), opt.coarse, !coarser.empty(), opt.shape);
    const int sw = sample[0].width();
    const CandidateGrid grid = detail::candidate_grid(layout, sw, sample[0].height());
    const detail::SampleVectors vectors
        = detail::sample_vectors(layout, grid, sample, sample_coarser, opt.nthreads);
    VectorSet set;
    set.data = vectors.data();
    set.count = grid.count();
    set.dim = layout.npixels() * int(sample.size());
    std::unique_ptr<NeighborSearch> search = make_search(set, search_settings(opt), error);
    if (!search)
        return false;

    const bool coherent = opt.search == SearchMethod::Coherent;
    HintCollector hints(coherent ? grid.count() : 0);
    std::vector<float> query(size_t(set.dim));
    const int w = out.channels[0].width(), h = out.channels[0].height();
    const size_t nc = sample.size();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            detail::output_vector(layout, out.channels, coarser, x, y, query.data());
            const std::vector<uint32_t>* hint_list
                = coherent ? &hints.collect(layout, grid, out, sw, x, y) : nullptr;
            const uint32_t best = search->nearest(query.data(),
                hint_list ? hint_list->data() : nullptr, hint_list ? hint_list->size() : 0);
            const size_t from = size_t(grid.y(best)) * size_t(sw) + size_t(grid.x(best));
            const size_t to = size_t(y) * size_t(w) + size_t(x);
            for (size_t c = 0; c < nc; ++c)
                out.channels[c].data()[to] = sample[c].data()[from];
            out.source[to] = uint32_t(from);
        }
        done += size_t(w);
        if (opt.progress)
            opt.progress(float(double(done) / double(total)));
    }
    return true;
}

// The source map of the finest level: x and y of each pixel's sample position.
void write_source_map(OIIO::ImageBuf& map, const OutputLevel& out, int sw, int sh)
{
    const int w = out.channels[0].width(), h = out.channels[0].height();
    PlanarImage m;
    m.channels = { Plane(w, h), Plane(w, h) };
    m.channel_names = { "x", "y" };
    for (size_t i = 0; i < out.source.size(); ++i) {
        m.channels[0].data()[i] = float(out.source[i] % uint32_t(sw));
        m.channels[1].data()[i] = float(out.source[i] / uint32_t(sw));
    }
    imagebuf_from_planes(m, map, false);
    map.specmod().erase_attribute("oiio:UnassociatedAlpha");
    map.specmod().attribute("synth:sample_size", size_text(sw, sh));
}

bool synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const NeighborhoodOptions& opt,
    OIIO::ImageBuf* source_map)
{
    std::string error;
    if (!opt.validate(error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    if (sample.has_error()) {
        dst.errorfmt("sample: {}", sample.geterror());
        return false;
    }
    PlanarImage in;
    if (!planes_from_imagebuf(sample, in, error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    const int sw = in.width(), sh = in.height();
    const int w = opt.width ? opt.width : sw, h = opt.height ? opt.height : sh;
    if (!check_sizes(sw, sh, w, h, opt, error)
        || !detail::check_memory(neighborhood_memory_estimate(sw, sh, in.nchannels(), w, h, opt),
            "size=" + size_text(w, h), error)) {
        dst.errorfmt("{}", error);
        return false;
    }

    const auto sample_levels
        = gaussian_levels(in.channels, opt.levels, Boundary::Reflect, opt.nthreads);
    size_t total = 0, done = 0;
    for (int l = 0; l < opt.levels; ++l)
        total += size_t(halved(w, l)) * size_t(halved(h, l));
    OutputLevel coarser, out;
    static const std::vector<Plane> none;
    for (int l = opt.levels - 1; l >= 0; --l) {
        out = initial_level(sample_levels[size_t(l)], halved(w, l), halved(h, l), opt.seed, l);
        const bool top = l == opt.levels - 1;
        if (!synthesize_level(out, sample_levels[size_t(l)],
                top ? none : sample_levels[size_t(l + 1)], top ? none : coarser.channels, opt, l,
                done, total, error)) {
            dst.errorfmt("{}", error);
            return false;
        }
        coarser = std::move(out);
    }

    const bool unassociated = sample.spec().get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    PlanarImage result;
    result.channels = coarser.channels;
    result.channel_names = in.channel_names;
    result.alpha_channel = in.alpha_channel;
    imagebuf_from_planes(result, dst, !unassociated);
    NeighborhoodOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    auto tag = [&](OIIO::ImageSpec& spec) {
        spec.attribute("synth:version", version());
        spec.attribute("synth:method", "neighborhood");
        spec.attribute("synth:seed", int(opt.seed));
        spec.attribute("synth:options", NeighborhoodOptions::table().format(resolved));
    };
    tag(dst.specmod());
    if (source_map) {
        write_source_map(*source_map, coarser, sw, sh);
        tag(source_map->specmod());
    }
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

} // namespace texsyn
