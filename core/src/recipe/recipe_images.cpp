// SPDX-License-Identifier: Apache-2.0
// A recipe's result as the subimages of an image file, through the result cache when
// $TEXSYN_CACHE asks for one.
#include <texsyn/recipe.h>

#include <algorithm>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/volume.h>

#include "result_cache_pvt.h"

namespace texsyn {

namespace {

// The synthesis: run_recipe(), a volume cut into its z slices, the subbands after it.
bool make_images(const Recipe& recipe, std::vector<OIIO::ImageBuf>& images, std::string& error)
{
    OIIO::ImageBuf result;
    std::vector<NamedImage> bands;
    if (!run_recipe(recipe, result, &bands, error))
        return false;
    images.clear();
    if (const int depth = result.spec().depth; depth > 1) {
        for (int z = 0; z < depth; ++z) {
            images.push_back(volume_slice(result, z));
            images.back().specmod().attribute("oiio:subimagename", volume_exr_part_name(z, depth));
        }
    } else {
        images.push_back(std::move(result));
        images.back().specmod().attribute("oiio:subimagename", "synth");
    }
    for (NamedImage& band : bands) {
        OIIO::ImageBuf buf;
        imagebuf_from_planes(band.image, buf);
        buf.specmod().attribute("oiio:subimagename", band.name);
        for (const OIIO::ParamValue& p : images[0].spec().extra_attribs)
            if (OIIO::Strutil::starts_with(p.name(), "synth:"))
                buf.specmod().attribute(p.name(), p.type(), p.data());
        images.push_back(std::move(buf));
    }
    // One display window for all parts, so that they can be written as one OpenEXR.
    int full_w = 0, full_h = 0;
    for (const OIIO::ImageBuf& img : images) {
        full_w = std::max(full_w, img.spec().width);
        full_h = std::max(full_h, img.spec().height);
    }
    for (OIIO::ImageBuf& img : images) {
        img.specmod().full_width = full_w;
        img.specmod().full_height = full_h;
        img.specmod() = detail::part_spec(img.spec());
    }
    return true;
}

} // namespace

bool recipe_images(const Recipe& recipe, std::vector<OIIO::ImageBuf>& images, std::string& error)
{
    std::string folder, key, why;
    bool writable = false;
    OIIO::ImageSpec spec;
    if (!detail::result_cache_folder(folder, writable) || !recipe_spec(recipe, spec, why))
        return make_images(recipe, images, error);
    std::string label = recipe.method;
    for (const std::string& sample : recipe.samples)
        label += " " + OIIO::Filesystem::filename(sample);
    if (!detail::recipe_cache_key(recipe, key, why)) {
        detail::cache_note("not used for " + label + ": " + why);
        return make_images(recipe, images, error);
    }
    detail::EntryLayout layout;
    layout.leading = std::max(spec.depth, 1);
    layout.width = spec.width;
    layout.height = spec.height;
    layout.channelnames = spec.channelnames;
    layout.more = recipe.subbands;
    return detail::cached_images(
        folder, writable, key, layout, label,
        [&](std::vector<OIIO::ImageBuf>& made, std::string& err) {
            return make_images(recipe, made, err);
        },
        images, error);
}

} // namespace texsyn
