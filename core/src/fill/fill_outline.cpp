// SPDX-License-Identifier: Apache-2.0
// A region's copies composed into the image: offset so that they meet the kept pixels across
// the hole's outline and one another across their seams without steps (gradient-domain
// compositing), then blended by the mask.
#include "fill_pvt.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

namespace {

// A faint pull of every offset toward 0, relative to a neighbour's weight: it keeps the
// system definite where a hole touches no kept pixel (a whole image filled from sample=)
// and does not move the offsets elsewhere.
constexpr double kPull = 1e-6;

// The offsets (one plane per channel, over the crop; 0 outside the hole) that make the
// copies meet the kept pixels and one another without steps: the least-squares solution of
//   d_q - d_p = s_qp           for 4-neighbours q, p in the hole,
//   d_q = kept_p - c_q(p - q)  for q in the hole beside a kept p,
// where c_q(v) is the copied content at q's source moved by v, and s_qp the mean of the two
// copies' disagreement across the pair (zero between coherent copies, whose continuations
// are each other). Gradient-domain compositing (Pérez et al. 2003; Agarwala et al. 2004):
// the copies keep their own gradients, the seams between them and the outline lose their
// steps. Solved by preconditioned conjugate gradients, the same at any thread count.
std::vector<Plane> seam_offsets(const RegionCopies& copies, const std::vector<uint8_t>& hole)
{
    const int cw = copies.crop.width(), ch = copies.crop.height(), nc = copies.channels;
    std::vector<int> index(hole.size(), -1);
    int unknowns = 0;
    for (size_t q = 0; q < hole.size(); ++q)
        if (hole[q])
            index[q] = unknowns++;
    std::vector<Plane> offsets(size_t(nc), Plane(cw, ch));
    if (!unknowns)
        return offsets;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, nc);
    std::vector<float> here(static_cast<size_t>(nc)), there(static_cast<size_t>(nc)),
        moved(static_cast<size_t>(nc)), back(static_cast<size_t>(nc));
    for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x) {
            const size_t q = size_t(y) * size_t(cw) + size_t(x);
            if (!hole[q])
                continue;
            const int row = index[q];
            double diagonal = kPull;
            copies.copied(q, 0, 0, here.data());
            for (const auto& [dx, dy] : { std::pair { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } }) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= cw || ny >= ch)
                    continue;
                const size_t p = size_t(ny) * size_t(cw) + size_t(nx);
                diagonal += 1.0;
                copies.copied(q, dx, dy, moved.data());
                if (!hole[p]) {
                    copies.kept(copies.crop.x0 + nx, copies.crop.y0 + ny, there.data());
                    for (int c = 0; c < nc; ++c)
                        rhs(row, c) += double(there[size_t(c)]) - double(moved[size_t(c)]);
                    continue;
                }
                entries.emplace_back(row, index[p], -1.0);
                copies.copied(p, 0, 0, there.data());
                copies.copied(p, -dx, -dy, back.data());
                for (int c = 0; c < nc; ++c) {
                    const size_t k = size_t(c);
                    rhs(row, c) += 0.5
                        * ((double(there[k]) - double(moved[k]))
                            + (double(back[k]) - double(here[k])));
                }
            }
            entries.emplace_back(row, row, diagonal);
        }
    Eigen::SparseMatrix<double> system(unknowns, unknowns);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
        Eigen::IncompleteCholesky<double>>
        solver;
    solver.setTolerance(1e-6);
    solver.compute(system);
    for (int c = 0; c < nc; ++c) {
        const Eigen::VectorXd d = solver.solve(rhs.col(c));
        for (size_t q = 0; q < hole.size(); ++q)
            if (hole[q])
                offsets[size_t(c)].data()[q] = float(d(index[q]));
    }
    return offsets;
}

} // namespace

void compose_region(const RegionCopies& copies, const Plane& mask, FillOutline outline, int rim,
    int nthreads, const std::function<void(int, int, const float*)>& write)
{
    const PixelBox& box = copies.crop;
    const int cw = box.width(), ch = box.height(), nc = copies.channels;
    const size_t n = size_t(cw) * size_t(ch);
    auto mask_at = [&](int x, int y) { return std::min(1.0f, mask(box.x0 + x, box.y0 + y)); };
    std::vector<uint8_t> hole(n, 0);
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
        const std::vector<Plane> offsets = seam_offsets(copies, hole);
        for (size_t q = 0; q < n; ++q)
            if (hole[q])
                for (int c = 0; c < nc; ++c)
                    copied[size_t(c)].data()[q] += offsets[size_t(c)].data()[q];
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
            // The image's edge is not the outline: a copy there keeps its full weight.
            const std::vector<int> depth = chessboard_distance(hole, cw, { 0, 0, cw, ch }, false);
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
