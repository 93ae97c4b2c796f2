// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §4 solid textures: match-texture on a 3-D block of noise with a 3-D
// Laplacian pyramid, plus (combined) 2-D steerable pyramids of every xy, xz and yz slice.
#include <texsyn/solid.h>
#include <texsyn/volume.h>

#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

#include <algorithm>
#include <climits>
#include <new>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn {

namespace {

constexpr SliceAxis kAxes[3] = { SliceAxis::Z, SliceAxis::Y, SliceAxis::X };

// The transforms for one block size, shared by every component and iteration.
struct SolidPlan {
    std::unique_ptr<VolumePyramid> laplacian;
    std::shared_ptr<Pyramid> steerable[3]; // per kAxes entry; empty for pyramid=laplacian
};

// What one component is matched to.
struct ComponentTables {
    const QuantileTable& pixels;
    const std::vector<QuantileTable>& laplacian;
    const std::vector<QuantileTable>* steerable; // null for pyramid=laplacian
};

// The size of the slices perpendicular to `axis` of a w x h x d block.
std::pair<int, int> slice_size(SliceAxis axis, int w, int h, int d)
{
    if (axis == SliceAxis::Z)
        return { w, h };
    if (axis == SliceAxis::Y)
        return { w, d };
    return { h, d };
}

bool make_plan(
    const SolidOptions& opt, int w, int h, int d, int scales, SolidPlan& plan, std::string& error)
{
    plan.laplacian = make_laplacian_pyramid_3d(w, h, d, scales, error);
    if (!plan.laplacian)
        return false;
    if (opt.pyramid == SolidPyramid::Laplacian)
        return true;
    for (int a = 0; a < 3; ++a) {
        const auto size = slice_size(kAxes[a], w, h, d);
        for (int b = 0; b < a && !plan.steerable[a]; ++b) // a cube needs one plan
            if (slice_size(kAxes[b], w, h, d) == size)
                plan.steerable[a] = plan.steerable[b];
        if (!plan.steerable[a])
            plan.steerable[a] = make_steerable_pyramid(
                size.first, size.second, scales, opt.orientations, opt.fft, error);
        if (!plan.steerable[a])
            return false;
    }
    return true;
}

// The 3-D Laplacian solid of one iteration: `image`'s bands matched to the sample's 2-D
// Laplacian bands (same names, same units), collapsed into `out`.
void laplacian_solid(const Volume& image, const VolumePyramid& pyramid,
    const std::vector<QuantileTable>& tables, HistogramMode mode, int nthreads,
    const StopFlag* stop, Volume& out)
{
    std::vector<Volume> bands;
    pyramid.build(image, bands, nthreads);
    for (size_t b = 0; b < bands.size(); ++b) {
        detail::throw_if_stopped(stop);
        match_histogram(bands[b].voxels(), tables[b], mode, nthreads);
    }
    pyramid.collapse(bands, out, nthreads);
}

// Adds the steerable solid of one axis to `sum`: every slice of `image` perpendicular to
// `axis` through the 2-D steerable pyramid with its oriented bands matched to the sample's.
// The two unoriented residuals are left as they are: the 3-D Laplacian pyramid already
// matches the finest and coarsest scales isotropically, and matching them again slice by
// slice (a 128^2 slice's low-pass is 8x8) changes each slice on its own, which shows as
// one-voxel-thin streaks along the axes in the other slices. One slice per task; slices of
// one axis are disjoint, so the sum does not depend on threads.
void add_steerable_solid(const Volume& image, SliceAxis axis, const Pyramid& pyramid,
    const std::vector<QuantileTable>& tables, HistogramMode mode, int nthreads,
    const StopFlag* stop, Volume& sum)
{
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(slice_count(image, axis)), int64_t(1),
        [&](int64_t i, int64_t) {
            if (stop_requested(stop))
                return;
            Plane slice;
            std::vector<Plane> bands;
            extract_slice(image, axis, int(i), slice);
            pyramid.transform_bands(
                slice, bands,
                [&](int b, Plane& band) {
                    if (b > 0 && b + 1 < pyramid.nbands())
                        match_histogram(band, tables[size_t(b)], mode, 1);
                },
                1);
            add_slice(slice, axis, int(i), sum);
        },
        detail::split_every_item(nthreads));
}

// §3.3 match-texture with §4's pyramids, from noise already in `image`.
void match_solid(Volume& image, const ComponentTables& t, const SolidPlan& plan,
    const SolidOptions& opt, const std::function<void(int)>& iteration_done)
{
    match_histogram(image.voxels(), t.pixels, opt.histogram, opt.nthreads);
    Volume next;
    for (int it = 0; it < opt.iterations; ++it) {
        laplacian_solid(
            image, *plan.laplacian, t.laplacian, opt.histogram, opt.nthreads, opt.stop, next);
        if (t.steerable) {
            for (int a = 0; a < 3; ++a) {
                add_steerable_solid(image, kAxes[a], *plan.steerable[a], *t.steerable,
                    opt.histogram, opt.nthreads, opt.stop, next);
                detail::throw_if_stopped(opt.stop);
            }
            // The average of the four solids (the histogram match below sets the contrast).
            float* v = next.data();
            for (size_t i = 0; i < next.size(); ++i)
                v[i] *= 0.25f;
        }
        std::swap(image, next);
        match_histogram(image.voxels(), t.pixels, opt.histogram, opt.nthreads);
        iteration_done(it + 1);
    }
}

bool synthesize(
    PlanarVolume& dst, const OIIO::ImageBuf& sample, const SolidOptions& opt, std::string& error)
{
    if (!opt.validate(error))
        return false;
    if (sample.has_error()) {
        error = "sample: " + sample.geterror();
        return false;
    }
    const int sw = sample.spec().width, sh = sample.spec().height;
    const int w = opt.width ? opt.width : sw, h = opt.height ? opt.height : sh;
    const int d = opt.depth ? opt.depth : std::min(sw, sh);
    const std::string size
        = "size=" + std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(d);
    const int min_side = std::min({ w, h, d });
    // One `scales` for both analyses and every pyramid: the most that the sample and the
    // block's smallest slice side allow, as the 2-D method does for the sample and output.
    const int scales = opt.scales
        ? opt.scales
        : std::max(1, std::min(max_pyramid_scales(sw, sh), max_pyramid_scales(min_side, min_side)));

    PyramidOptions analysis;
    analysis.pyramid = PyramidKind::Laplacian;
    analysis.scales = scales;
    analysis.orientations = opt.orientations;
    analysis.histogram = opt.histogram;
    analysis.fft = opt.fft;
    analysis.flatten = opt.flatten;
    analysis.nthreads = opt.nthreads;
    TextureStatistics lap, steer;
    if (!analyze_texture(sample, analysis, lap, error))
        return false;
    const bool combined = opt.pyramid == SolidPyramid::Combined;
    analysis.pyramid = PyramidKind::Steerable;
    if (combined && !analyze_texture(sample, analysis, steer, error, &lap.color))
        return false;

    const int nc = lap.nchannels();
    if (!detail::check_memory(solid_memory_estimate(w, h, d, nc), size, error))
        return false;
    if (int64_t(h) * int64_t(d) > INT_MAX) {
        error = size + " is too large (height x depth must be under 2^31)";
        return false;
    }
    if (min_side < (1 << scales)) {
        error = size + " is too small for " + std::to_string(scales)
            + " scales (each side at least " + std::to_string(1 << scales) + ")";
        return false;
    }
    SolidPlan plan;
    if (!make_plan(opt, w, h, d, scales, plan, error))
        return false;

    PlanarVolume out;
    out.channel_names = lap.channel_names;
    out.alpha_channel = lap.alpha_channel;
    for (int c = 0; c < nc; ++c) {
        const ComponentStatistics& comp = lap.components[size_t(c)];
        if (comp.constant) {
            out.channels.emplace_back(w, h, d, comp.mean);
            continue;
        }
        auto iteration_done = [&](int it) {
            detail::report_progress(opt.progress, opt.stop,
                float(c * opt.iterations + it) / float(std::max(1, nc * opt.iterations)));
        };
        Volume image(detail::seeded_noise(w, h * d, opt.seed, uint64_t(c), opt.nthreads), h, d);
        const ComponentTables tables { comp.pixels, comp.bands,
            combined ? &steer.components[size_t(c)].bands : nullptr };
        match_solid(image, tables, plan, opt, iteration_done);
        out.channels.push_back(std::move(image));
    }

    // Back to the sample's channels, then one last match of each channel's histogram to the
    // sample's, which recorrelation alone does not guarantee.
    PlanarImage planes;
    swap_voxel_planes(out, planes);
    recorrelate(planes, lap.color, opt.nthreads);
    swap_voxel_planes(out, planes);
    for (int c = 0; c < nc; ++c)
        match_histogram(
            out.channels[size_t(c)].voxels(), lap.channels[size_t(c)], opt.histogram, opt.nthreads);

    SolidOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    resolved.depth = d;
    resolved.scales = scales;
    out.attributes.attribute("synth:version", version());
    out.attributes.attribute("synth:method", "solid");
    out.attributes.attribute("synth:seed", int(opt.seed));
    out.attributes.attribute("synth:options", SolidOptions::table().format(resolved));
    dst = std::move(out);
    return true;
}

} // namespace

bool solid_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const SolidOptions& opt)
{
    return detail::guarded(dst, "solid_synthesize", [&] {
        PlanarVolume volume;
        std::string error;
        if (!synthesize(volume, sample, opt, error)) {
            dst.errorfmt("{}", error);
            return false;
        }
        imagebuf_from_volume(volume, dst);
        return true;
    });
}

OIIO::ImageBuf solid_synthesize(const OIIO::ImageBuf& sample, const SolidOptions& opt)
{
    return detail::value_form("solid_synthesize",
        [&](OIIO::ImageBuf& dst) { return solid_synthesize(dst, sample, opt); });
}

} // namespace texsyn
