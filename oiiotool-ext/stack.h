// SPDX-License-Identifier: Apache-2.0
// The image stack (oiiotool's model): what inputs push and commands pop and push.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/material.h>
#include <texsyn/recipe.h>
#include <texsyn/stats.h>
#include <texsyn/subbands.h>
#include <texsyn/surface.h>

namespace texsyn::cli {

/// What a stack item holds (item_kinds.h: what the tool does with each).
enum class ItemKind {
    Image,    ///< a 2-D image, scene-linear float
    Analysis, ///< a sample's statistics (an analysis file, or made by --analyze)
    Volume,   ///< a 3-D image (a solid texture), scene-linear, colour un-associated
    Mesh,     ///< a textured mesh (SurfaceTexture); `buf` its UV bake's first tile, if any
    Material, ///< a material set (texsyn/material.h); `buf` its albedo
};

/// One item on the stack.
struct StackItem {
    ItemKind kind = ItemKind::Image;
    OIIO::ImageBuf buf; ///< an image or a volume
    std::shared_ptr<const TextureStatistics> analysis;
    std::shared_ptr<const SurfaceTexture> surface;
    std::shared_ptr<const Material> material;
    std::vector<NamedImage> subbands; ///< filled when --subbands is on

    /// What to call it: the file name as given, or e.g. "pyramid synthesis of rust.png".
    std::string name;
    /// The file it was read from; "" for an item a command made.
    std::string file;
    OIIO::ImageBuf file_pixels; ///< an input image's values as read (for --iscolorspace)

    // How -o writes it (docs/colour.md): the pixel type and colour space of the sample its
    // colours come from, and --tocolorspace's choice ("" = the default policy).
    OIIO::TypeDesc input_format = OIIO::TypeUInt8;
    std::string input_colorspace;
    std::string output_colorspace;

    /// The recipe of a command's result whose inputs are all files (--recipe writes it);
    /// otherwise null, and `no_recipe` says why.
    std::shared_ptr<const Recipe> recipe;
    std::string no_recipe;
};

/// "CMD : no current image (…)" or "CMD : needs N images on the stack, there are H":
/// the message for a command that finds too few items.
std::string too_few_items(const std::string& command, int needed, int have);

/// The stack itself, with pops that throw CliError naming the command.
class Stack {
public:
    bool empty() const { return m_items.empty(); }
    int size() const { return int(m_items.size()); }
    /// The top item; throws if there is none.
    StackItem& top(const std::string& command);
    /// Pops the top n items, returned in the order they were pushed; throws if there are
    /// fewer.
    std::vector<StackItem> pop(const std::string& command, int n);
    void push(StackItem item) { m_items.push_back(std::move(item)); }

private:
    std::vector<StackItem> m_items;
};

} // namespace texsyn::cli
