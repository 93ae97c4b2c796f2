// SPDX-License-Identifier: Apache-2.0
// texsyn.imageio.so: an OIIO ImageInput that opens synthesis recipes (*.texsyn) as images,
// so that stock oiiotool, iinfo, maketx and any OIIO application can use them. Parsing and
// dispatch only: open() answers with libtexsyn's recipe_spec(), and the recipe is run by
// recipe_images() — or read from the $TEXSYN_CACHE result cache — on the first read of pixels.
//
// The plugin does not claim "procedural": stock oiiotool 2.4.7 crashes when a procedural
// plugin accepts a name in valid_file() and then fails open().
// Without it, a bad recipe fails cleanly with the plugin's message. Samples are read with
// their own ImageInput (texsyn::read_image): re-entering OIIO's shared ImageCache while it
// opens this file made oiiotool abort.
#include <algorithm>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <new>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/error_text.h>
#include <texsyn/memory.h>
#include <texsyn/recipe.h>
#include <texsyn/version.h>
#include <texsyn/volume.h>

OIIO_PLUGIN_NAMESPACE_BEGIN

class TexsynInput final : public ImageInput {
public:
    const char* format_name() const override { return "texsyn"; }
    int supports(string_view feature) const override { return feature == "arbitrary_metadata"; }

    // A name is ours if it ends in .texsyn (before any "?arguments") and names a recipe
    // file, or a sample file with ".texsyn" appended, or arguments that name a method that
    // needs no sample ("noise.texsyn?method=cascade").
    bool valid_file(const std::string& name) const override
    {
        const size_t q = name.find('?');
        const std::string base = name.substr(0, q);
        if (!Strutil::iends_with(base, ".texsyn"))
            return false;
        // Any existing file is ours, FIFOs and devices included: open() then refuses them,
        // where other formats' probes would block reading them.
        std::error_code ec;
        if (std::filesystem::exists(base, ec)
            || std::filesystem::exists(base.substr(0, base.size() - 7), ec))
            return true;
        if (q == std::string::npos)
            return false;
        for (const std::string& arg : Strutil::splits(name.substr(q + 1), "&"))
            if (Strutil::starts_with(arg, "method=")) {
                const texsyn::Method* m = texsyn::find_method(arg.substr(7));
                return m
                    && (m->inputs == texsyn::MethodInputs::None
                        || m->inputs == texsyn::MethodInputs::OptionalImage);
            }
        return false;
    }

    // Answers with the result's spec from the recipe and its samples' headers (recipe_spec):
    // the synthesis runs on the first read of pixels. A recipe with subbands is made here,
    // as its further subimages are known only then.
    bool open(const std::string& name, ImageSpec& newspec) override
    {
        // No allocation failure may end the host: it becomes this file's error.
        try {
            return open_recipe(name, newspec);
        } catch (const std::bad_alloc&) {
            close();
            errorfmt("{}: out of memory opening the recipe", name);
            return false;
        }
    }

    bool close() override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_images.reset();
        m_announced.clear();
        m_subimage = 0;
        return true;
    }

    int current_subimage() const override { return m_subimage; }

    bool seek_subimage(int subimage, int miplevel) override
    {
        try {
            return seek(subimage, miplevel);
        } catch (const std::bad_alloc&) {
            errorfmt("{}: out of memory", m_name);
            return false;
        }
    }

    // The images are complete in memory once made and never change: rows of any subimage
    // can be served without seeking, from any thread.
    bool read_native_scanline(int subimage, int miplevel, int y, int z, void* data) override
    {
        try {
            const Images* images = synthesized();
            if (!images || subimage < 0 || subimage >= int(images->size()) || miplevel != 0)
                return false;
            const ImageBuf& img = (*images)[size_t(subimage)];
            const ImageSpec& spec = img.spec();
            return img.get_pixels(
                ROI(spec.x, spec.x + spec.width, y, y + 1, z, z + 1), TypeFloat, data);
        } catch (const std::bad_alloc&) {
            errorfmt("{}: out of memory making the synthesis", m_name);
            return false;
        }
    }

private:
    // 0: the synthesis, then its subbands if asked for; a volume: one subimage per z slice.
    using Images = std::vector<ImageBuf>;

    // Refuses a recipe whose result the host cannot hold, as the command line does, before
    // announcing its spec: a host that trusts the spec allocates it (float pixels) and
    // aborts, or its ImageCache asserts, when that fails; the synthesis holds the result
    // too. memory_available() keeps --max-memory, $TEXSYN_MAX_MEMORY and ulimit -v.
    static bool fits_in_memory(const ImageSpec& spec, std::string& error)
    {
        const double result_bytes = double(spec.width) * double(spec.height)
            * double(std::max(spec.depth, 1)) * double(spec.nchannels) * sizeof(float);
        return texsyn::check_memory(size_t(std::min(2.0 * result_bytes, 1e18)),
            "a " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                + (spec.depth > 1 ? "x" + std::to_string(spec.depth) : std::string())
                + " result and the host's copy of it",
            error);
    }

    bool open_recipe(const std::string& name, ImageSpec& newspec)
    {
        close();
        std::string error;
        if (!texsyn::recipe_from_filename(name, m_recipe, error)
            || !texsyn::recipe_spec(m_recipe, m_spec, error)) {
            errorfmt("{}", texsyn::readable_message(error));
            return false;
        }
        if (!fits_in_memory(m_spec, error)) {
            errorfmt("{}: {}", name.substr(0, name.find('?')), error);
            return false;
        }
        m_name = name;
        m_announced.clear();
        if (const int depth = m_spec.depth; depth > 1) {
            // A volume: its z slices, named as in the slice EXR (volume.h).
            ImageSpec slice = m_spec;
            slice.depth = slice.full_depth = 1;
            slice.erase_attribute("oiio:UnassociatedAlpha"); // slices are associated
            for (int z = 0; z < depth; ++z) {
                slice.attribute("oiio:subimagename", texsyn::volume_exr_part_name(z, depth));
                m_announced.push_back(slice);
            }
        } else {
            m_spec.attribute("oiio:subimagename", "synth");
            m_announced.push_back(m_spec);
        }
        if (m_recipe.subbands) {
            const Images* images = synthesized();
            if (!images) {
                close();
                return false;
            }
            m_announced[0].full_width = (*images)[0].spec().full_width;
            m_announced[0].full_height = (*images)[0].spec().full_height;
        }
        m_subimage = 0;
        m_spec = m_announced[0];
        newspec = m_spec;
        return true;
    }

    bool seek(int subimage, int miplevel)
    {
        if (subimage < 0 || miplevel != 0 || m_announced.empty())
            return false;
        if (size_t(subimage) < m_announced.size()) {
            m_spec = m_announced[size_t(subimage)];
        } else {
            const Images* images = m_recipe.subbands ? synthesized() : nullptr;
            if (!images || size_t(subimage) >= images->size())
                return false;
            m_spec = (*images)[size_t(subimage)].spec();
        }
        m_subimage = subimage;
        return true;
    }

    // The synthesis, made on first use (by one thread; the others wait for it), checked
    // against the spec open() announced. Null (with errorfmt) if it fails.
    const std::vector<ImageBuf>* synthesized()
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_images)
            return m_images.get();
        std::string error;
        std::shared_ptr<const Images> images = cached_synthesis(m_name, m_recipe, error);
        if (images) {
            for (size_t i = 0; i < m_announced.size() && error.empty(); ++i) {
                const ImageSpec& want = m_announced[i];
                if (i >= images->size() || (*images)[i].spec().width != want.width
                    || (*images)[i].spec().height != want.height
                    || (*images)[i].spec().channelnames != want.channelnames)
                    error = "internal error: the synthesis differs from the spec announced";
            }
        }
        if (!error.empty()) {
            errorfmt("{}", texsyn::readable_message(error));
            return nullptr;
        }
        m_images = images;
        return m_images.get();
    }

    // OIIO tools open a file more than once (oiiotool: for its spec, then for its pixels),
    // and a synthesis is expensive (even a read from $TEXSYN_CACHE is not free: docs/cache.md),
    // so the last two results are kept in memory, keyed by the name as
    // given, the working directory (for relative paths) and the modification times and
    // sizes of the recipe file, the samples, the files its options read and the colour
    // config (so edits are seen).
    static std::shared_ptr<const Images> cached_synthesis(
        const std::string& name, const texsyn::Recipe& recipe, std::string& error)
    {
        namespace fs = std::filesystem;
        std::error_code ec;
        auto stamp = [&](const std::string& path) {
            if (path.empty())
                return std::string("-");
            return std::to_string(fs::last_write_time(path, ec).time_since_epoch().count()) + ":"
                + std::to_string(fs::file_size(path, ec));
        };
        std::vector<std::string> inputs = recipe.samples;
        for (const texsyn::OptionField& f : recipe.options.table().fields())
            if (f.type == texsyn::OptionType::InputFile)
                inputs.push_back(recipe.options.value(f.name));
        std::string key = name + "|" + fs::current_path(ec).string() + "|"
            + stamp(name.substr(0, name.find('?'))) + "|" + stamp(recipe.colorconfig);
        // A recipe whose input is a recipe depends on files this key does not see.
        bool cacheable = true;
        for (const std::string& input : inputs) {
            key += "|" + stamp(input);
            cacheable = cacheable && !Strutil::iends_with(input, ".texsyn");
        }
        static std::mutex mutex;
        static std::deque<std::pair<std::string, std::shared_ptr<const Images>>> cache;
        if (cacheable) {
            std::lock_guard<std::mutex> lock(mutex);
            for (auto& entry : cache)
                if (entry.first == key)
                    return entry.second;
        }
        auto images = std::make_shared<Images>();
        if (!texsyn::recipe_images(recipe, *images, error))
            return nullptr;
        if (!cacheable)
            return images;
        std::lock_guard<std::mutex> lock(mutex);
        cache.emplace_back(key, images);
        if (cache.size() > 2)
            cache.pop_front();
        return images;
    }

    std::string m_name;                     // as given to open()
    texsyn::Recipe m_recipe;                // what open() read
    std::vector<ImageSpec> m_announced;     // the subimages' specs open() knows
    std::mutex m_mutex;                     // guards m_images
    std::shared_ptr<const Images> m_images; // made on first use
    int m_subimage = 0;
};

OIIO_PLUGIN_NAMESPACE_END

OIIO_PLUGIN_EXPORTS_BEGIN

OIIO_EXPORT int texsyn_imageio_version = OIIO_PLUGIN_VERSION;

OIIO_EXPORT const char* texsyn_imageio_library_version()
{
    static const std::string v = std::string("texsyn ") + texsyn::version();
    return v.c_str();
}

OIIO_EXPORT OIIO::ImageInput* texsyn_input_imageio_create()
{
    return new OIIO::TexsynInput;
}

OIIO_EXPORT const char* texsyn_input_extensions[] = { "texsyn", nullptr };

OIIO_PLUGIN_EXPORTS_END
