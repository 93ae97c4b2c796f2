// SPDX-License-Identifier: Apache-2.0
// The registry row of the homogeneity check: a report on the current image, which stays.
#include <texsyn/homogeneity.h>
#include <texsyn/memory.h>
#include <texsyn/methods.h>

#include <algorithm>

namespace texsyn::detail {

namespace {

// --check takes no options.
struct NoOptions {
    static const OptionTable<NoOptions>& table()
    {
        return declared_table<NoOptions>([](OptionTable<NoOptions>&) {});
    }
    bool validate(std::string&) const { return true; }
};

bool run_check(const MethodOptions&, const std::vector<MethodInput>& inputs, const OptionImages&,
    const RunSettings& settings, MethodResult& result, std::string& error)
{
    // Its planes and the working images of the measures: measured, about 33 bytes per
    // pixel of an RGB sample beyond the float sample itself; a quarter more for the
    // allocator.
    const OIIO::ImageSpec& spec = inputs[0].image->spec();
    const double need
        = 1.25 * double(spec.width) * double(spec.height) * (8.0 * spec.nchannels + 12.0);
    if (!check_memory(size_t(std::min(need, 1e18)),
            "the check of the " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                + " sample",
            error))
        return false;
    PlanarImage planes;
    if (!planes_from_imagebuf(*inputs[0].image, planes, error))
        return false;
    result.report
        = format_homogeneity_report(check_homogeneity(planes, settings.nthreads), inputs[0].name);
    return true;
}

} // namespace

const Method& check_method()
{
    static const Method m { "check", MethodInputs::Image, MethodOutput::Report,
        [] { return MethodOptions(NoOptions()); }, run_check, "homogeneity.md",
        "how homogeneous a sample is (Heeger & Bergen 1995 section 6): lighting gradient, local "
        "mean and contrast, score and warnings",
        "Print how homogeneous the current image is: lighting gradient, local mean and "
        "contrast variation, score and warnings (Heeger & Bergen section 6). Leaves the image "
        "where it is; needs no -o.",
        "texsyn data/samples/rust.png --check", "" };
    return m;
}

} // namespace texsyn::detail
