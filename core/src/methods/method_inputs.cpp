// SPDX-License-Identifier: Apache-2.0
// Samples and option files read for a method, the same way for every front end.
#include <texsyn/inputs.h>

#include <filesystem>

#include <texsyn/io.h>

namespace texsyn {

bool read_sample(const std::string& filename, const ColorConfig& colors,
    const std::string& colorspace, Sample& sample, std::string& error, int nthreads)
{
    Sample s;
    s.filename = filename;
    if (is_analysis_filename(filename)) {
        if (!colorspace.empty()) {
            error = filename
                + ": is an analysis, its statistics are already scene-linear "
                  "(it takes no colour space)";
            return false;
        }
        auto stats = std::make_shared<TextureStatistics>();
        if (!read_statistics(filename, *stats, error))
            return false;
        if (colors.resolve(stats->colorspace).empty()) {
            error = filename + ": its sample's colour space '" + stats->colorspace
                + "' is not in the colour config " + colors.source();
            return false;
        }
        s.colorspace = stats->colorspace;
        s.colorspace_reason = "the colour space its sample was read in";
        s.file_format
            = stats->sample_format.empty() ? OIIO::TypeFloat : OIIO::TypeDesc(stats->sample_format);
        s.analysis = std::move(stats);
        sample = std::move(s);
        return true;
    }
    // Held at once: the file's pixels, their scene-linear copy, and the colour
    // conversion's two working copies.
    OIIO::ImageSpec native;
    OIIO::ImageBuf pixels;
    return read_image(filename, pixels, error, &native, sample_read_copies)
        && sample_from_file_pixels(
            std::move(pixels), native, filename, colors, colorspace, sample, error, nthreads);
}

bool sample_from_file_pixels(OIIO::ImageBuf pixels, const OIIO::ImageSpec& native,
    const std::string& filename, const ColorConfig& colors, const std::string& colorspace,
    Sample& sample, std::string& error, int nthreads)
{
    Sample s;
    // The pixels are float now: what the file says of them (its type, its colour tags)
    // is in its native spec.
    ColorConfig::Guess guess { colorspace, "as asked (--iscolorspace)", "" };
    if (colorspace.empty()) {
        guess = colors.guess_colorspace(native);
        if (guess.space.empty()) {
            error = filename + ": unknown colour space (" + guess.reason
                + "); name it with --iscolorspace";
            return false;
        }
    }
    if (!sample_from_image(std::move(pixels), filename, colors, guess.space, s, error, nthreads))
        return false;
    s.file_format = native.format;
    s.colorspace_reason = guess.reason;
    s.colorspace_warning = guess.warning;
    sample = std::move(s);
    return true;
}

bool sample_from_image(OIIO::ImageBuf pixels, const std::string& name, const ColorConfig& colors,
    const std::string& colorspace, Sample& sample, std::string& error, int nthreads)
{
    Sample s;
    s.filename = name;
    s.file_format = pixels.spec().format;
    ColorConfig::Guess guess { colorspace, "as asked (--iscolorspace)", "" };
    if (colorspace.empty()) {
        guess = colors.guess_colorspace(pixels.spec());
        if (guess.space.empty()) {
            error = name + ": unknown colour space (" + guess.reason
                + "); name it with --iscolorspace";
            return false;
        }
    }
    if (pixels.spec().format == OIIO::TypeFloat)
        s.file_pixels = std::move(pixels);
    else if (!s.file_pixels.copy(pixels, OIIO::TypeFloat)) {
        error = name + ": " + s.file_pixels.geterror();
        return false;
    }
    if (!relinearize_sample(s, colors, guess.space, error, nthreads))
        return false;
    s.colorspace_reason = guess.reason;
    s.colorspace_warning = guess.warning;
    sample = std::move(s);
    return true;
}

bool relinearize_sample(Sample& sample, const ColorConfig& colors, const std::string& colorspace,
    std::string& error, int nthreads)
{
    if (sample.analysis) {
        error = sample.filename + ": is an analysis, its statistics are already scene-linear";
        return false;
    }
    const std::string space = colors.resolve(colorspace);
    if (space.empty()) {
        error = colors.unknown_colorspace(colorspace);
        return false;
    }
    // Kept un-associated: colour under zero alpha must survive to the output.
    if (!colors.convert_image(sample.file_pixels, space, colors.scene_linear(), false,
            sample.pixels, error, nthreads)) {
        error = sample.filename + ": " + error;
        return false;
    }
    sample.colorspace = space;
    sample.colorspace_reason = "as asked (--iscolorspace)";
    sample.colorspace_warning.clear();
    return true;
}

bool check_option_file(const OptionField& field, const std::string& file, std::string& error)
{
    if (check_regular_file(file, field.file == FileUse::ReadMesh ? "a mesh" : "an image", error))
        return true;
    error = option_error(field.name, file, error.substr(file.size() + 2)); // after "FILE: "
    return false;
}

bool read_option_files(const MethodOptions& options, const ColorConfig& colors, OptionImages& files,
    std::string& error, int nthreads)
{
    for (const OptionField& f : options.table().fields()) {
        const std::string file = options.value(f.name);
        if (f.type != OptionType::InputFile || file.empty())
            continue;
        if (!check_option_file(f, file, error))
            return false;
        OIIO::ImageBuf image;
        std::string why;
        // read_image's messages start with the file's name, which the option already gives.
        auto reason = [&file](const std::string& message) {
            const std::string prefix = file + ": ";
            return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
        };
        if (f.file == FileUse::ReadMesh)
            continue; // the method reads it (its run checks it)
        if (f.file == FileUse::ReadImage) {
            Sample s;
            if (!read_sample(file, colors, "", s, why, nthreads) || s.analysis) {
                error = option_error(
                    f.name, file, s.analysis ? "is an analysis, not an image" : reason(why));
                return false;
            }
            image = std::move(s.pixels);
        } else if (!read_image(file, image, why)) {
            error = option_error(f.name, file, reason(why));
            return false;
        }
        files[f.name] = std::move(image);
    }
    return true;
}

} // namespace texsyn
