// SPDX-License-Identifier: Apache-2.0
// texsyn.imageio.so: an OIIO ImageInput that opens synthesis recipes (*.texsyn) as images,
// so that stock oiiotool, iinfo, maketx and any OIIO application can use them. Parsing and
// dispatch only: the recipe is run by libtexsyn's run_recipe(), once per open().
//
// The plugin does not claim "procedural": stock oiiotool 2.4.7 crashes when a procedural
// plugin accepts a name in valid_file() and then fails open() (../shared/ECOSYSTEM.md §2).
// Without it, a bad recipe fails cleanly with the plugin's message.
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/recipe.h>

OIIO_PLUGIN_NAMESPACE_BEGIN

class TexsynInput final : public ImageInput {
public:
    const char* format_name() const override { return "texsyn"; }
    int supports(string_view feature) const override { return feature == "arbitrary_metadata"; }

    // A name is ours if it ends in .texsyn (before any "?arguments") and names a recipe
    // file, or a sample file with ".texsyn" appended.
    bool valid_file(const std::string& name) const override
    {
        const std::string base = name.substr(0, name.find('?'));
        if (!Strutil::iends_with(base, ".texsyn"))
            return false;
        std::error_code ec;
        return std::filesystem::exists(base, ec)
            || std::filesystem::exists(base.substr(0, base.size() - 7), ec);
    }

    bool open(const std::string& name, ImageSpec& newspec) override
    {
        close();
        texsyn::Recipe recipe;
        std::string error;
        if (!texsyn::recipe_from_filename(name, recipe, error)) {
            errorfmt("{}", error);
            return false;
        }
        if (recipe.subbands) {
            // TODO: serve subbands as further subimages once stock oiiotool 2.4 can read
            // them: its image cache aborts (refcnt.h "Assertion 'm_ptr' failed") on this
            // plugin's multi-subimage files, while iinfo and Python read them fine.
            errorfmt("{}: subbands=1 is not available through the OIIO plugin (stock "
                     "oiiotool 2.4 cannot read them); use texsyn --subbands",
                name.substr(0, name.find('?')));
            return false;
        }
        m_image = cached_synthesis(name, recipe, error);
        if (!m_image) {
            errorfmt("{}", error);
            return false;
        }
        m_spec = m_image->spec();
        newspec = m_spec;
        return true;
    }

    bool close() override
    {
        m_image.reset();
        return true;
    }

    // The image is complete in memory and never changes: rows can be served from any thread.
    bool read_native_scanline(int subimage, int miplevel, int y, int z, void* data) override
    {
        if (subimage != 0 || miplevel != 0 || !m_image)
            return false;
        const ImageSpec& spec = m_image->spec();
        return m_image->get_pixels(
            ROI(spec.x, spec.x + spec.width, y, y + 1, z, z + 1), TypeFloat, data);
    }

private:
    // OIIO tools open a file more than once (oiiotool: for its spec, then for its pixels),
    // and a synthesis is expensive, so the last few results are kept, keyed by the name as
    // given, the working directory (for relative paths) and the modification times of the
    // recipe file and the sample (so edits are seen).
    static std::shared_ptr<const ImageBuf> cached_synthesis(
        const std::string& name, const texsyn::Recipe& recipe, std::string& error)
    {
        namespace fs = std::filesystem;
        std::error_code ec;
        auto stamp = [&](const std::string& path) {
            return std::to_string(fs::last_write_time(path, ec).time_since_epoch().count());
        };
        const std::string key = name + "|" + fs::current_path(ec).string() + "|"
            + stamp(name.substr(0, name.find('?'))) + "|" + stamp(recipe.sample);
        static std::mutex mutex;
        static std::deque<std::pair<std::string, std::shared_ptr<const ImageBuf>>> cache;
        {
            std::lock_guard<std::mutex> lock(mutex);
            for (auto& entry : cache)
                if (entry.first == key)
                    return entry.second;
        }
        auto result = std::make_shared<ImageBuf>();
        if (!texsyn::run_recipe(recipe, *result, nullptr, error))
            return nullptr;
        std::lock_guard<std::mutex> lock(mutex);
        cache.emplace_back(key, result);
        if (cache.size() > 2)
            cache.pop_front();
        return result;
    }

    std::shared_ptr<const ImageBuf> m_image; // the synthesis, made or found by open()
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
