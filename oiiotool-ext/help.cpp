// SPDX-License-Identifier: Apache-2.0
// --help, --list-methods, --version. Option lists come from the option tables.
#include "cli_state.h"

#include <cstdio>

namespace texsyn::cli {

namespace {

template <class T>
void print_field(const OptionField<T>& f, const T& defaults)
{
    std::printf("        %-13s %s\n        %-13s (%s; default %s)\n", f.name.c_str(),
        f.help.c_str(), "", f.allowed.c_str(), f.format(defaults).c_str());
}

template <class T>
void print_table(const OptionTable<T>& table, const T& defaults)
{
    for (const auto& f : table.fields())
        print_field(f, defaults);
}

} // namespace

void print_help()
{
    std::printf(
        "texsyn %s -- texture synthesis for VFX pipelines\n"
        "Usage: texsyn [global options] ARGS...\n"
        "ARGS are processed left to right on an image stack, as in oiiotool: a file name\n"
        "reads an image, a command pops its inputs and pushes its result, -o writes the top.\n"
        "\n"
        "Global options:\n"
        "    --help                Print this help and exit\n"
        "    --version             Print the version and exit\n"
        "    --list-methods        List the synthesis methods and exit\n"
        "    -v                    Verbose: progress and timings on stderr\n"
        "    --seed N              Random seed, 0..2147483647 (default 0)\n"
        "    --threads N           Worker threads, 0 = all cores (default 0); the result\n"
        "                          does not depend on it\n"
        "    --colorconfig FILE    OCIO config (default: $OCIO, else texsyn's bundled config)\n"
        "    --iscolorspace NAME   Colour space of the current (or next) input image\n"
        "    --tocolorspace NAME   Colour space to write the current (or every) image in\n"
        "                          (default: scene_linear for float outputs such as EXR,\n"
        "                          the input's space for integer outputs such as PNG)\n"
        "    -d TYPE               Output pixel type: uint8, uint16, half, float\n"
        "                          (default: half for EXR, uint8 otherwise)\n"
        "    --subbands            -o writes a multi-part EXR: part 'synth' plus every\n"
        "                          pyramid subband of the sample and the synthesis\n"
        "\n"
        "Commands:\n"
        "    FILE                  Read an image, or an analysis file (*.tsa)\n"
        "    -o FILE               Write the current image (or analysis, as *.tsa) to FILE\n"
        "                          (atomically)\n"
        "    --recipe FILE.texsyn  Write the recipe of the current synthesis: OIIO tools\n"
        "                          open it as an image with texsyn's format plugin\n"
        "    --analyze[:pyramid=,scales=,orientations=,fft=,flatten=]\n"
        "                          Replace the current image by its pyramid analysis, to\n"
        "                          write as *.tsa and synthesize from without the sample\n"
        "    --check               Print how homogeneous the current image is: lighting\n"
        "                          gradient, local mean and contrast variation, score and\n"
        "                          warnings (Heeger & Bergen §6). Needs no -o\n"
        "    --pyramid[:name=value...]\n"
        "                          Heeger & Bergen 1995 pyramid synthesis of the current\n"
        "                          image or analysis. Options:\n",
        version());
    print_table(PyramidOptions::table(), PyramidOptions());
    std::printf("    --solid[:name=value...]\n"
                "                          Heeger & Bergen 1995 section 4 solid texture of the\n"
                "                          current image: a 3-D block whose slices look like it.\n"
                "                          Write it with -o FILE.vdb (OpenVDB: grids Cd and\n"
                "                          density) or -o FILE.exr (one part per z slice).\n"
                "                          Options:\n");
    print_table(SolidOptions::table(), SolidOptions());
    std::printf(
        "    --mix[:name=value...]\n"
        "                          Heeger & Bergen 1995 section 5 texture mixture of the top\n"
        "                          images (sample 0 is the one pushed first): one mode of\n"
        "                          palette=I:pattern=J (colour of I, subband statistics of\n"
        "                          J), split=S (scales >= S and the low-pass of sample 0,\n"
        "                          finer bands of sample 1) or weights=W0,W1,...\n"
        "                          (averaged histograms; pops one image per weight, else 2).\n"
        "                          Options (the --pyramid ones and):\n");
    const std::size_t shared = PyramidOptions::table().fields().size();
    const auto& mix = MixOptions::table().fields();
    for (std::size_t i = shared; i < mix.size(); ++i)
        print_field(mix[i], MixOptions());
    std::printf(
        "    --transfer[:name=value...]\n"
        "                          Texture transfer: pops a sample (top) and an image (below\n"
        "                          it) and gives the image's layout the sample's statistics,\n"
        "                          at the image's size. Options: the --pyramid ones but size\n"
        "    --neighborhood[:name=value...]\n"
        "                          Wei & Levoy 2000 neighbourhood synthesis of the current\n"
        "                          image (scanline order, causal L-shaped neighbourhoods,\n"
        "                          Gaussian pyramid, toroidal). map=FILE.exr also writes the\n"
        "                          sample coordinate of every output pixel. Options:\n");
    print_table(NeighborhoodOptions::table(), NeighborhoodOptions());
    std::printf(
        "    --choosy[:name=value...]\n"
        "                          Castellanos & Williams choosy sampling of the current\n"
        "                          image: coarse to fine by Laplacian inversion, each\n"
        "                          sample pixel's score penalised by its use count (keeps\n"
        "                          the sample's histogram), isotropic by default, toroidal.\n"
        "                          Each side of size must be a multiple of 2^(levels-1).\n"
        "                          map=FILE.exr also writes the sample coordinate of every\n"
        "                          output pixel.\n"
        "                          Options:\n");
    print_table(ChoosyOptions::table(), ChoosyOptions());
    std::printf(
        "    --cascade[:name=value...]\n"
        "                          Iterated nonlinear maps and convolution in a multiscale\n"
        "                          cascade (A <- p(N(A)), circular, so it tiles). A\n"
        "                          generator: with no current image it makes one from\n"
        "                          seeded noise; else it replaces the current image by a\n"
        "                          texture transfer from it, at its size unless size= is\n"
        "                          given. dilation=FILE reads a one-channel control image\n"
        "                          (no colour conversion) that spreads the kernel's taps by\n"
        "                          dmin..dmax; rotation=FILE one that turns them by 0..1\n"
        "                          turns; palette=FILE an image whose colours, by luminance\n"
        "                          rank, colour the result (instead of ramp=). The result\n"
        "                          is scene-linear (one channel Y, or RGB with ramp= or\n"
        "                          palette=). Options:\n");
    print_table(CascadeOptions::table(), CascadeOptions());
    std::printf(
        "    --apply-map MAP IMAGE Read IMAGE (aligned with the sample of a --neighborhood\n"
        "                          or --choosy run) and rearrange its pixels by that run's\n"
        "                          source map MAP: height, normal or roughness maps follow\n"
        "                          the colour. Written in IMAGE's colour space by default\n"
        "\n"
        "Examples:\n"
        "    texsyn rust.png --pyramid:size=1024x1024:iterations=5:orientations=4 -o "
        "rust_big.exr\n"
        "    texsyn rust.png --check\n"
        "    texsyn marble.png --solid:size=128x128x128 -o marble.vdb\n"
        "    texsyn rust.png paper.png --mix:palette=0:pattern=1 -o mix.exr\n"
        "    texsyn photo.png rust.png --transfer -o rusty_photo.exr\n"
        "    texsyn grass.png --neighborhood:size=512x512:map=coords.exr -o grass_big.exr\n"
        "    texsyn stone.png --choosy:size=512x512:iterations=1,8 -o stone_big.exr\n"
        "    texsyn --apply-map coords.exr grass_height.png -o grass_height_big.exr\n"
        "    texsyn --cascade:size=512x512:levels=4:r=3.9 -o cascade.exr\n");
}

void print_methods()
{
    std::printf("pyramid    Heeger & Bergen 1995: pyramid-based histogram matching "
                "(steerable or Laplacian), seamless\n"
                "solid      Heeger & Bergen 1995 section 4: solid textures (3-D blocks) from a "
                "2-D sample, seamless\n"
                "mix        Heeger & Bergen 1995 section 5: texture mixtures (palette of one "
                "sample and pattern of another, low and high bands, averaged histograms)\n"
                "transfer   Heeger & Bergen 1995 section 5: match-texture applied to an image "
                "instead of noise (its layout, the sample's statistics)\n"
                "neighborhood  Wei & Levoy 2000: multi-resolution neighbourhood search "
                "(exhaustive, tsvq, kdtree, coherent), toroidal, with source maps\n"
                "choosy     Castellanos & Williams: choosy sampling (use-count penalty keeps "
                "the sample's histogram), isotropic by default, toroidal, with source maps\n"
                "cascade    iterated nonlinear maps and convolution in a multiscale cascade: a "
                "generator, or a texture transfer from an image; seamless\n");
}

void print_version()
{
    std::printf("texsyn %s\n", version());
}

} // namespace texsyn::cli
