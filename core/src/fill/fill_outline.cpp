// SPDX-License-Identifier: Apache-2.0
// A region's copies composed into the image: offset by a membrane so that they meet the
// kept pixels across the hole's outline (seamless cloning, Pérez et al. 2003, in the
// membrane form of Farbman et al. 2009), then blended by the mask.
#include "fill_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

namespace {

// Jacobi sweeps of the membrane at each level of its coarse-to-fine solve, and at the
// coarsest (a few cells across, where it converges from its start).
constexpr int kSweeps = 8, kCoarsestSweeps = 200;

// Jacobi sweeps of Laplace's equation for each plane of `d` over the pixels of `domain`
// that are not `fixed` (neighbours outside the domain do not count: its edge is free).
void relax(std::vector<Plane>& d, const std::vector<uint8_t>& domain,
    const std::vector<uint8_t>& fixed, int sweeps)
{
    const int w = d[0].width(), h = d[0].height();
    std::vector<size_t> free;
    for (size_t i = 0; i < domain.size(); ++i)
        if (domain[i] && !fixed[i])
            free.push_back(i);
    Plane next;
    for (Plane& p : d)
        for (int sweep = 0; sweep < sweeps; ++sweep) {
            next = p;
            for (size_t i : free) {
                const int x = int(i % size_t(w)), y = int(i / size_t(w));
                double sum = 0.0;
                int n = 0;
                for (const auto& [dx, dy] :
                    { std::pair { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } }) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h
                        || !domain[size_t(ny) * size_t(w) + size_t(nx)])
                        continue;
                    sum += p(nx, ny);
                    ++n;
                }
                if (n)
                    next.data()[i] = float(sum / n);
            }
            std::swap(p, next);
        }
}

// The membrane: `d` (one plane per channel) given on `fixed` is replaced on the rest of
// `domain` by the harmonic interpolation of it (Laplace's equation, d held on `fixed`),
// solved coarse to fine: each level starts from its coarser level's solution and relaxes.
void membrane(
    std::vector<Plane>& d, const std::vector<uint8_t>& domain, const std::vector<uint8_t>& fixed)
{
    const int w = d[0].width(), h = d[0].height();
    const size_t nfree = size_t(std::count(domain.begin(), domain.end(), uint8_t(1)))
        - size_t(std::count(fixed.begin(), fixed.end(), uint8_t(1)));
    if (std::min(w, h) <= 8 || nfree <= 64) {
        // Start from the fixed values' mean, then relax to convergence.
        for (Plane& p : d) {
            double sum = 0.0;
            size_t n = 0;
            for (size_t i = 0; i < fixed.size(); ++i)
                if (fixed[i]) {
                    sum += p.data()[i];
                    ++n;
                }
            for (size_t i = 0; i < fixed.size(); ++i)
                if (domain[i] && !fixed[i])
                    p.data()[i] = n ? float(sum / double(n)) : 0.0f;
        }
        relax(d, domain, fixed, kCoarsestSweeps);
        return;
    }
    // Restriction: a coarse cell is in the domain (fixed) if one of its 2x2 fine pixels is,
    // holding the mean of its fixed ones.
    const int cw = (w + 1) / 2, ch = (h + 1) / 2;
    std::vector<uint8_t> cdomain(size_t(cw) * size_t(ch), 0), cfixed(cdomain.size(), 0);
    std::vector<Plane> cd(d.size(), Plane(cw, ch));
    std::vector<int> count(cdomain.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const size_t c = size_t(y / 2) * size_t(cw) + size_t(x / 2);
            cdomain[c] |= domain[i];
            if (!fixed[i])
                continue;
            cfixed[c] = 1;
            ++count[c];
            for (size_t k = 0; k < d.size(); ++k)
                cd[k].data()[c] += d[k].data()[i];
        }
    for (size_t c = 0; c < count.size(); ++c)
        if (count[c])
            for (Plane& p : cd)
                p.data()[c] /= float(count[c]);
    membrane(cd, cdomain, cfixed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (domain[i] && !fixed[i])
                for (size_t k = 0; k < d.size(); ++k)
                    d[k].data()[i] = cd[k](x / 2, y / 2);
        }
    relax(d, domain, fixed, kSweeps);
}

// Per crop pixel, its chessboard distance (1, 2, …) to the nearest pixel outside the hole,
// up to `limit` (further pixels get limit); 0 outside the hole.
std::vector<int> distance_inside(const std::vector<uint8_t>& hole, int w, int h, int limit)
{
    std::vector<int> d(hole.size(), 0);
    std::vector<size_t> front;
    for (size_t q = 0; q < hole.size(); ++q)
        if (hole[q])
            d[q] = limit;
        else
            front.push_back(q);
    for (int step = 1; step < limit && !front.empty(); ++step) {
        std::vector<size_t> next;
        for (size_t q : front) {
            const int x = int(q % size_t(w)), y = int(q / size_t(w));
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                        continue;
                    const size_t p = size_t(ny) * size_t(w) + size_t(nx);
                    if (d[p] > step) {
                        d[p] = step;
                        next.push_back(p);
                    }
                }
        }
        front = std::move(next);
    }
    return d;
}

} // namespace

void compose_region(const RegionCopies& copies, const Plane& mask, FillOutline outline, int rim,
    int nthreads, const std::function<void(int, int, const float*)>& write)
{
    const PixelBox& box = copies.crop;
    const int cw = box.width(), ch = box.height(), nc = copies.channels;
    const size_t n = size_t(cw) * size_t(ch);
    auto mask_at = [&](int x, int y) { return std::min(1.0f, mask(box.x0 + x, box.y0 + y)); };
    std::vector<uint8_t> hole(n, 0), ring(n, 0);
    for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x)
            hole[size_t(y) * size_t(cw) + size_t(x)] = mask_at(x, y) > 0.0f;
    // The copied content as planes of the crop (where the hole is).
    std::vector<Plane> copied(size_t(nc), Plane(cw, ch));
    std::vector<float> v(static_cast<size_t>(nc)), kept(static_cast<size_t>(nc));
    for (size_t q = 0; q < n; ++q)
        if (hole[q]) {
            copies.copied(q, 0, 0, v.data());
            for (int c = 0; c < nc; ++c)
                copied[size_t(c)].data()[q] = v[size_t(c)];
        }
    if (outline == FillOutline::Match) {
        // On the hole's side of the outline: the kept pixels beside each filled one, minus
        // the copied content's continuation there (its source's neighbour).
        std::vector<Plane> diff(size_t(nc), Plane(cw, ch));
        std::vector<double> sum(static_cast<size_t>(nc));
        for (int y = 0; y < ch; ++y)
            for (int x = 0; x < cw; ++x) {
                const size_t q = size_t(y) * size_t(cw) + size_t(x);
                if (!hole[q])
                    continue;
                std::fill(sum.begin(), sum.end(), 0.0);
                int neighbours = 0;
                for (const auto& [dx, dy] :
                    { std::pair { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } }) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= cw || ny >= ch
                        || hole[size_t(ny) * size_t(cw) + size_t(nx)])
                        continue;
                    copies.kept(box.x0 + nx, box.y0 + ny, kept.data());
                    copies.copied(q, dx, dy, v.data());
                    for (int c = 0; c < nc; ++c)
                        sum[size_t(c)] += double(kept[size_t(c)]) - double(v[size_t(c)]);
                    ++neighbours;
                }
                if (!neighbours)
                    continue;
                ring[q] = 1;
                for (int c = 0; c < nc; ++c)
                    diff[size_t(c)].data()[q] = float(sum[size_t(c)] / neighbours);
            }
        if (std::find(ring.begin(), ring.end(), uint8_t(1)) != ring.end()) {
            membrane(diff, hole, ring);
            for (size_t q = 0; q < n; ++q)
                if (hole[q])
                    for (int c = 0; c < nc; ++c)
                        copied[size_t(c)].data()[q] += diff[size_t(c)].data()[q];
        }
        // A soft image (no detail finer than 2 rim px): the copies fade in over `rim`
        // pixels from the kept pixels' smooth continuation, whose steps at the outline are
        // the image's own.
        if (rim > 1) {
            CropLevel smooth;
            smooth.planes.assign(size_t(nc), Plane(cw, ch));
            smooth.known.resize(n);
            for (int y = 0; y < ch; ++y)
                for (int x = 0; x < cw; ++x) {
                    const size_t q = size_t(y) * size_t(cw) + size_t(x);
                    smooth.known[q] = !hole[q];
                    if (hole[q])
                        continue;
                    copies.kept(box.x0 + x, box.y0 + y, kept.data());
                    for (int c = 0; c < nc; ++c)
                        smooth.planes[size_t(c)].data()[q] = kept[size_t(c)];
                }
            pushpull_fill(smooth, nthreads);
            const std::vector<int> depth = distance_inside(hole, cw, ch, rim);
            for (size_t q = 0; q < n; ++q)
                if (hole[q] && depth[q] < rim) {
                    const float a = float(depth[q]) / float(rim);
                    for (int c = 0; c < nc; ++c) {
                        float& f = copied[size_t(c)].data()[q];
                        f = a * f + (1.0f - a) * smooth.planes[size_t(c)].data()[q];
                    }
                }
        }
    }
    for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x) {
            const size_t q = size_t(y) * size_t(cw) + size_t(x);
            if (!hole[q])
                continue;
            const float m = mask_at(x, y);
            copies.kept(box.x0 + x, box.y0 + y, kept.data());
            for (int c = 0; c < nc; ++c) {
                const float fill = copied[size_t(c)].data()[q];
                v[size_t(c)] = m == 1.0f ? fill : (1.0f - m) * kept[size_t(c)] + m * fill;
            }
            write(box.x0 + x, box.y0 + y, v.data());
        }
}

} // namespace texsyn::detail
