// SPDX-License-Identifier: Apache-2.0
// The registry row of the cascade: a generator, or a transfer from an image; control and
// palette images named by file options.
#include <texsyn/cascade.h>
#include <texsyn/methods.h>

#include "cascade_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

// The cascade's options and the files they name: dilation= and rotation= (one-channel
// control images, read as their numbers) and palette= (an image read like a sample, whose
// colours the result takes).
struct CascadeWithFiles {
    CascadeOptions options;
    std::string dilation, rotation, palette;

    static const OptionTable<CascadeWithFiles>& table()
    {
        using O = CascadeWithFiles;
        return declared_table<O>([](OptionTable<O>& t) {
            t.include(&O::options, CascadeOptions::table());
            t.file("dilation", &O::dilation, FileUse::ReadData, "",
                "a one-channel control image (read without colour conversion) that spreads the "
                "kernel's taps by dmin..dmax");
            t.file("rotation", &O::rotation, FileUse::ReadData, "",
                "a one-channel control image that turns the kernel's taps by 0..1 turns");
            t.file("palette", &O::palette, FileUse::ReadImage, "",
                "an image whose colours, by luminance rank, colour the result (instead of "
                "ramp=)");
        });
    }
    bool validate(std::string& error) const
    {
        return table().check(*this, error) && options.validate(error);
    }
};

// The control image of option `name`, or null; false (with a message naming the option
// and its file) if it has more than one channel.
bool control(const OptionImages& files, const char* name, const std::string& file,
    const OIIO::ImageBuf*& image, std::string& error)
{
    const auto it = files.find(name);
    image = it == files.end() ? nullptr : &it->second;
    if (!image || image->nchannels() == 1)
        return true;
    error = option_error(name, file,
        "the control image has " + std::to_string(image->nchannels()) + " channels; expected 1");
    return false;
}

bool run_cascade(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages& files, const RunSettings& settings, MethodResult& result,
    std::string& error)
{
    const CascadeWithFiles& given = options_of<CascadeWithFiles>(options);
    CascadeOptions opt = given.options;
    apply_run_settings(settings, opt);
    const OIIO::ImageBuf *dilation = nullptr, *rotation = nullptr, *palette = nullptr;
    if (!control(files, "dilation", given.dilation, dilation, error)
        || !control(files, "rotation", given.rotation, rotation, error))
        return false;
    if (const auto it = files.find("palette"); it != files.end())
        palette = &it->second;
    if (cascade_synthesize(result.image, opt, inputs.empty() ? nullptr : inputs[0].image, dilation,
            rotation, palette))
        return true;
    error = result.image.geterror();
    return false;
}

// size=, else the input image's size, else 512x512; RGB when coloured by a ramp or palette,
// else one lattice Y, or the image's channels with transfer=channels. A generator tiles; a
// transfer from an image only if the image does, which is not known.
bool cascade_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    const CascadeWithFiles& given = options_of<CascadeWithFiles>(options);
    layout.width = layout.height = 512;
    if (!inputs.empty())
        layout = layout_from_input(inputs[0], options);
    apply_size_option(options, layout);
    if (!given.options.ramp.empty() || !given.palette.empty())
        layout.channelnames = { "R", "G", "B" };
    else if (inputs.empty() || given.options.transfer != CascadeTransfer::Channels)
        layout.channelnames = { "Y" };
    layout.set_tiles(inputs.empty());
    return true;
}

} // namespace

const Method& cascade_method()
{
    static const Method m { "cascade", MethodInputs::OptionalImage, MethodOutput::Image,
        [] { return MethodOptions(CascadeWithFiles()); }, run_cascade, "cascade.md",
        "iterated nonlinear maps and convolution in a multiscale cascade: a generator, or a "
        "texture transfer from an image; seamless",
        "Iterated nonlinear maps and convolution in a multiscale cascade (A <- p(N(A)), "
        "circular, so it tiles). A generator: with no current image it makes one from seeded "
        "noise; else it replaces the current image by a texture transfer from it, at its size "
        "unless size= is given. The result is scene-linear (one channel Y, or RGB with ramp= "
        "or palette=).",
        "texsyn --seed 1 --cascade:preset=stone:size=512x512 -o stone.exr",
        "no sample: a procedural look", false, {}, {}, cascade_shorthands, cascade_layout };
    return m;
}

} // namespace texsyn::detail
