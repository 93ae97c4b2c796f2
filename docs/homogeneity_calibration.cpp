// SPDX-License-Identifier: Apache-2.0
// Prints the calibration table of docs/homogeneity.md: check_homogeneity on each sample
// given on the command line, as read (sRGB-encoded 8-bit files are linearised as the tool
// does) and multiplied by lighting gradients in scene-linear. Each cell: illumination
// amplitude / local mean variation / local contrast variation → score.
// usage: texsyn_homogeneity_calibration SAMPLE.png...
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>

#include <OpenImageIO/filesystem.h>

#include <texsyn/color.h>
#include <texsyn/homogeneity.h>
#include <texsyn/io.h>

namespace {

using texsyn::PlanarImage;

// Multiplies the colour channels by gain(u, v), u and v in [0, 1] across the sample.
PlanarImage lit(PlanarImage image, const std::function<double(double, double)>& gain)
{
    const int w = image.width(), h = image.height();
    for (int c = 0; c < image.ncolor(); ++c)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                image.channels[size_t(c)](x, y) *= float(gain((x + 0.5) / w, (y + 0.5) / h));
    return image;
}

std::string cell(const texsyn::HomogeneityReport& r)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.2f / %.2f / %.2f → %.2f%s", r.illumination_amplitude,
        r.local_mean_variation, r.local_contrast_variation, r.score, r.poor ? " **poor**" : "");
    return buf;
}

// The lightings of the table's columns, as gains over u, v in [0, 1].
struct Lighting {
    const char* name;
    std::function<double(double, double)> gain;
};

double cos4_vignette(double u, double v, double corner_degrees)
{
    // A lens's natural fall-off cos⁴(θ), θ the field angle: corner_degrees at the corners.
    const double r = std::hypot(u - 0.5, v - 0.5) / std::sqrt(0.5);
    const double t = std::atan(r * std::tan(corner_degrees * M_PI / 180.0));
    return std::pow(std::cos(t), 4.0);
}

const Lighting lightings[] = {
    { "as read", [](double, double) { return 1.0; } },
    { "ramp 0.5→1.5", [](double u, double) { return 0.5 + u; } },
    { "cos⁴ vignette, corners 0.34", [](double u, double v) { return cos4_vignette(u, v, 40.0); } },
    { "ramp 0.75→1.25", [](double u, double) { return 0.75 + 0.5 * u; } },
    { "cos⁴ vignette, corners 0.59", [](double u, double v) { return cos4_vignette(u, v, 30.0); } },
};

} // namespace

int main(int argc, char* argv[])
{
    std::string error;
    auto colors = texsyn::ColorConfig::load("", error);
    if (!colors) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }
    std::printf("| sample |");
    for (const Lighting& l : lightings)
        std::printf(" %s |", l.name);
    std::printf("\n| --- |");
    for (size_t i = 0; i < std::size(lightings); ++i)
        std::printf(" --- |");
    std::printf("\n");
    for (int i = 1; i < argc; ++i) {
        OIIO::ImageBuf file;
        PlanarImage p;
        if (!texsyn::read_image(argv[i], file, error) || !planes_from_imagebuf(file, p, error)
            || !colors->convert(
                p, colors->guess_colorspace(file.spec()).space, colors->scene_linear(), error)) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        std::printf("| %s |", OIIO::Filesystem::filename(argv[i]).c_str());
        for (const Lighting& l : lightings)
            std::printf(" %s |", cell(texsyn::check_homogeneity(lit(p, l.gain))).c_str());
        std::printf("\n");
    }
    return 0;
}
