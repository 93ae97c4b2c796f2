// SPDX-License-Identifier: Apache-2.0
// The method registry: every command that works on texsyn's image stack — the synthesis
// methods and the operations beside them (analysis, homogeneity check) — as one row each,
// with its name, summary, option table, what it takes and gives, and its run function.
//
// The front ends iterate it and name no method in code: the `texsyn` tool's commands, its
// stack checks, --help and --list-methods; recipes (JSON, REST arguments, their schema) and
// the OIIO plugin; the generated option docs. Adding a method is its folder under
// core/src, one row in core/src/methods/registry.cpp, its tests and its doc page
// (docs/adding-a-method.md).
//
// Rules for everything here:
//  - Errors come back as one-line messages (false, `error`); nothing throws.
//  - run_method() validates before it allocates, and is deterministic for a seed whatever
//    RunSettings::nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/options.h>
#include <texsyn/run_controls.h>
#include <texsyn/subbands.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

struct SurfaceTexture;    // texsyn/surface.h
struct TextureStatistics; // texsyn/stats.h: an analysis, opaque to the registry
struct Material;          // texsyn/material.h

/// A method's options, whatever the method: its options struct together with that struct's
/// option table. Value semantics (copies are deep).
class MethodOptions {
public:
    MethodOptions() = default;
    /// Holds `value`, described by `table` (by default T::table()); T has
    /// `bool validate(std::string&) const`.
    template <class T>
    explicit MethodOptions(T value, const OptionTable<T>& table = T::table())
        : m_holder(std::make_unique<Holder<T>>(std::move(value), table))
    { }
    MethodOptions(const MethodOptions& other);
    MethodOptions& operator=(const MethodOptions& other);
    MethodOptions(MethodOptions&&) noexcept = default;
    MethodOptions& operator=(MethodOptions&&) noexcept = default;
    ~MethodOptions();

    /// Whether it holds options (a default-constructed one does not).
    explicit operator bool() const { return bool(m_holder); }

    /// The option table (empty if it holds nothing).
    const OptionList& table() const;
    /// Sets one option from text (OptionList::set).
    bool set(std::string_view name, std::string_view value, std::string& error);
    /// Applies "name=value:…" (OptionList::apply).
    bool apply(std::string_view text, std::string& error);
    /// The text of option `name` ("" if there is no such option).
    std::string value(std::string_view name) const;
    /// "name=value:…" with every option but the file options (synth:options, recipes).
    std::string format() const;
    /// The struct's validate(): every range and the rules between options.
    bool validate(std::string& error) const;

    /// The options struct if it is a T, or if it wraps a T (a row whose options add file
    /// options, e.g. map=, holds a struct whose member `options` is the method's struct:
    /// get<NeighborhoodOptions>() finds it), else null.
    template <class T>
    const T* get() const
    {
        return m_holder ? static_cast<const T*>(m_holder->find(typeid(T))) : nullptr;
    }
    template <class T>
    T* get()
    {
        return m_holder ? static_cast<T*>(const_cast<void*>(m_holder->find(typeid(T)))) : nullptr;
    }

private:
    struct Base {
        virtual ~Base() = default;
        virtual std::unique_ptr<Base> clone() const = 0;
        virtual void* data() = 0;
        virtual const void* data() const = 0;
        virtual const OptionList& table() const = 0;
        virtual bool validate(std::string& error) const = 0;
        virtual const void* find(const std::type_info& type) const = 0;
    };
    // The address of the `type` in `value`: value itself, or its member `options` (and so on
    // down) if it has one; null if none is a `type`.
    template <class T, class = void>
    struct Unwrap {
        static const void* find(const T& value, const std::type_info& type)
        {
            return typeid(T) == type ? &value : nullptr;
        }
    };
    template <class T>
    struct Unwrap<T, std::void_t<decltype(std::declval<const T&>().options)>> {
        static const void* find(const T& value, const std::type_info& type)
        {
            using Inner = std::decay_t<decltype(value.options)>;
            return typeid(T) == type ? &value : Unwrap<Inner>::find(value.options, type);
        }
    };
    template <class T>
    struct Holder final : Base {
        Holder(T v, const OptionTable<T>& t)
            : value(std::move(v))
            , options(&t)
        { }
        std::unique_ptr<Base> clone() const override
        {
            return std::make_unique<Holder>(value, *options);
        }
        void* data() override { return &value; }
        const void* data() const override { return &value; }
        const OptionList& table() const override { return *options; }
        bool validate(std::string& error) const override { return value.validate(error); }
        const void* find(const std::type_info& type) const override
        {
            return Unwrap<T>::find(value, type);
        }
        T value;
        const OptionTable<T>* options;
    };
    std::unique_ptr<Base> m_holder;
};

/// What a method takes from the stack (the tool's image stack, a recipe's samples, a
/// Python call's arguments), in the order they were pushed.
enum class MethodInputs {
    None,           ///< nothing: a generator
    OptionalImage,  ///< an image if there is one (a transfer from it), else nothing
    Image,          ///< one image
    Sample,         ///< one image, or an analysis of one
    ImageAndSample, ///< an image (whose layout is kept), then a sample or analysis
    Samples,        ///< Method::count(options) samples, each an image or an analysis
};

/// What a method gives.
enum class MethodOutput {
    Image,    ///< a 2-D image
    Volume,   ///< a 3-D image (solid texture)
    Analysis, ///< the statistics of its input (an analysis file's contents)
    Report,   ///< a text report on its input, which it leaves where it was
    /// a triangle mesh with a colour per face (SurfaceTexture), and, if the mesh has UVs,
    /// their bake as the image (the first UDIM tile's; every tile in the SurfaceTexture)
    Mesh,
    /// a material set (material.h): an albedo and its other maps, for a copying method
    Material,
};

/// One input of a run: an image (scene-linear float), an analysis, or a material set (the
/// only input of a row that copies_pixels).
struct MethodInput {
    const OIIO::ImageBuf* image = nullptr;
    const TextureStatistics* analysis = nullptr;
    std::string name; ///< what to call it in messages and reports, e.g. its file name
    const Material* material = nullptr;
};

/// The largest seed every front end takes (--seed, a recipe's "seed", Python's seed=): the
/// seed is written as synth:seed, an int attribute.
constexpr int64_t max_seed = 2147483647;
/// The most worker threads every front end takes (--threads, Python's threads=; 0 = all
/// cores).
constexpr int max_threads = 1024;

/// What the front end sets besides the options: the run's controls (run_controls.h: seed,
/// threads, progress, stop; run_method gives them to the method's options), what it wants
/// back, and the run's memory budget. Only the seed changes the result.
struct RunSettings : RunControls {
    bool subbands = false; ///< fill MethodResult::subbands (methods that have them)
    /// Methods that copy sample pixels give their source map in MethodResult::files
    /// ("map") even when map= names no file (a material set needs it).
    bool source_map = false;
    /// This run's memory budget in bytes: work needing more is refused before it is
    /// allocated, whatever the rest of the process (a host) holds. 0: the process-wide limit
    /// less what the process holds (memory.h: check_memory).
    size_t max_memory = 0;
};

/// Something a user should know about a run that succeeded (a front end shows it even when
/// quiet): one line, and the option that would change it, so that a front end can leave it
/// out when the user set that option.
struct RunWarning {
    std::string option; ///< e.g. "flatten"
    std::string text;   ///< e.g. "bricks.png is unevenly lit (…): flatten=1 divides it out"
};

/// What a run gives (MethodOutput says which member).
struct MethodResult {
    /// Image, Volume (spec.depth slices), or Mesh's bake; float, scene-linear
    OIIO::ImageBuf image;
    std::shared_ptr<TextureStatistics> analysis;   ///< Analysis
    std::string report;                            ///< Report
    std::shared_ptr<const SurfaceTexture> surface; ///< Mesh
    std::shared_ptr<const Material> material;      ///< Material
    std::vector<NamedImage> subbands;              ///< with RunSettings::subbands
    /// The images of the output-file options that name a file, by option name (e.g.
    /// "map", the source map), for the front end to write.
    std::vector<std::pair<std::string, OIIO::ImageBuf>> files;
    /// What the run measured of its result, one line (the tool prints it with -v).
    std::string notes;
    /// What the user should know: for a method with flatten=0, a sample whose lighting the
    /// method would copy (check_homogeneity's uneven_for_copying, or its pyramid limit).
    std::vector<RunWarning> warnings;
};

/// An input's layout, known from its file's header without decoding pixels (an analysis:
/// its sample's).
struct InputLayout {
    int width = 0, height = 0;
    std::vector<std::string> channelnames;
};

/// What a run's image or volume will be, known before the run: what the OIIO plugin answers
/// open() with, and what run_method() checks every result against.
struct ResultLayout {
    int width = 0, height = 0;
    int depth = 1; ///< a volume's slices
    std::vector<std::string> channelnames;
    /// It wraps around seamlessly along x, along y: written with wrapmodes "periodic" for
    /// those axes ("black" for the others).
    bool tiles_x = true, tiles_y = true;

    /// Its OIIO "wrapmodes" attribute ("periodic,periodic" if it tiles), or "" if it
    /// tiles along neither axis.
    std::string wrapmodes() const
    {
        if (!tiles_x && !tiles_y)
            return "";
        return std::string(tiles_x ? "periodic" : "black") + "," + (tiles_y ? "periodic" : "black");
    }
    void set_tiles(bool both) { tiles_x = tiles_y = both; }
};

/// A row's layout rule: from the validated options and the inputs' layouts (checked for
/// count), the result's; false with a message if the options cannot apply to the inputs.
using MethodLayout = std::function<bool(const MethodOptions& options,
    const std::vector<InputLayout>& inputs, ResultLayout& result, std::string& error)>;

/// The images an input-file option names (read by read_option_files, inputs.h), by
/// option name.
using OptionImages = std::map<std::string, OIIO::ImageBuf>;

/// A method's work: `inputs` are checked (count and kinds) and `options` validated.
using MethodRun = std::function<bool(const MethodOptions& options,
    const std::vector<MethodInput>& inputs, const OptionImages& files, const RunSettings& settings,
    MethodResult& result, std::string& error)>;

/// One row of the registry. Rows are written as aggregates, in member order: name, what
/// it takes and gives, its options and run, its doc page and texts (summary, help, example,
/// suits), then the optional members.
struct Method {
    std::string name; ///< "pyramid": the command --pyramid, a recipe's "method": "pyramid"
    MethodInputs inputs = MethodInputs::Image;
    MethodOutput output = MethodOutput::Image;
    /// The options with their defaults.
    std::function<MethodOptions()> defaults;
    MethodRun run;
    std::string doc;     ///< its page in docs/, e.g. "choosy.md"
    std::string summary; ///< one line (--list-methods)
    std::string help;    ///< what it does with the stack and its result (--help)
    /// One command line that runs it, on samples bundled in data/samples, from the
    /// repository's root (--help NAME prints it; a test runs it).
    std::string example;
    /// The textures it is the method for, a few words for --help's "which method" table
    /// (e.g. "stochastic, noise-like: rust, stucco"); "" for a row that makes no texture.
    std::string suits;
    bool subbands = false; ///< it can give its pyramid's subbands (--subbands)
    /// Samples: how many the options ask for.
    std::function<int(const MethodOptions&)> count = {};
    /// Which input the result's colours come from (whose file encoding an 8-bit output
    /// keeps); empty = the last.
    std::function<int(const MethodOptions&)> colours_from = {};
    /// Rewrites the tool's shorthand forms of its modifiers into options (may be empty).
    std::function<std::string(const std::string&)> shorthands = {};
    /// Its result's layout (rows that make images or volumes); empty = the usual rule:
    /// size= if given, else the size of the input the colours come from (colours_from),
    /// with that input's channels, and tiling.
    MethodLayout layout = {};
    /// Every output pixel is a sample pixel: it gives their source map (the output-file
    /// option map=, or RunSettings::source_map) and so synthesizes material sets (a
    /// MethodInput::material moves every map of the set by that source map).
    bool copies_pixels = false;

    /// How many items it takes when `available` are on the stack.
    int input_count(const MethodOptions& options, int available) const;
    /// Whether input `index` of a run may be an analysis.
    bool accepts_analysis(int index) const;
    /// Whether its result can be written as a recipe (an image, a volume, or a mesh's UV
    /// bake).
    bool makes_recipes() const
    {
        return output == MethodOutput::Image || output == MethodOutput::Volume
            || output == MethodOutput::Mesh;
    }
};

/// Every row, in the order --help lists them.
const std::vector<const Method*>& methods();

/// The row called `name`, or null.
const Method* find_method(std::string_view name);

/// "a|b|c": the names of the rows that make recipes (all rows with `all`).
std::string method_names(bool all = false);

/// "--a, --b and --c" (each name after `prefix` and before `suffix`): the rows `which`
/// selects, in --help's order, as messages list them; "" if none.
std::string command_list(const std::function<bool(const Method&)>& which,
    const std::string& suffix = "", const std::string& prefix = "--");

/// The layout of `method`'s result (a row that makes images or volumes) for `options` and
/// inputs with these layouts: the row's rule, or the usual one. Fails (false, `error`) if
/// the options do not validate, the input count is wrong, or the rule refuses.
bool result_layout(const Method& method, const MethodOptions& options,
    const std::vector<InputLayout>& inputs, ResultLayout& layout, std::string& error);

/// The layout of an input image or analysis (InputLayout).
InputLayout input_layout(const MethodInput& input);

/// Runs `method` with `options` on `inputs`: checks the options (validate()), the inputs'
/// count and kinds (naming each by MethodInput::name), that every input-file option that
/// names a file has its image in `files`, then calls the row's run function with any
/// exception turned into a message. A material set (the one input of a row that
/// copies_pixels) is synthesized as material.h says: `result` then holds the set
/// (result.material), its albedo as the image, and the run's source map in its files. The result
/// names its inputs (their file names without folders): synth:sample (a transfer's image:
/// synth:image), or an analysis's `source`; an image or volume is checked against result_layout()
/// (a mismatch is an internal error) and carries wrapmodes "periodic,periodic" if it tiles. False
/// with a message otherwise.
bool run_method(const Method& method, const MethodOptions& options,
    const std::vector<MethodInput>& inputs, const OptionImages& files, const RunSettings& settings,
    MethodResult& result, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
