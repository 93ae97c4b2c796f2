// SPDX-License-Identifier: Apache-2.0
// Colour: OCIO colour management and the PCA colour decorrelation of Heeger & Bergen
// 1995 §3.5.
//
// Policy (DESIGN.md "Colour"): statistics are taken in the config's scene_linear role.
// Inputs are converted to scene_linear on the way in and to the requested space on the
// way out. Alpha is never colour converted and never dropped.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// An OCIO config. Immutable after loading; thread safe.
class ColorConfig {
public:
    ~ColorConfig();
    ColorConfig(ColorConfig&&) noexcept;
    ColorConfig& operator=(ColorConfig&&) noexcept;

    /// The name that selects texsyn's bundled config wherever a config is named
    /// (--colorconfig, a recipe's "colorconfig"), whatever $OCIO says. Recipes record the
    /// bundled config by this name, never by a path that another machine may not have.
    static constexpr const char* bundled_name = "texsyn://bundled";

    /// Loads, in order of precedence: `explicit_path` if not empty (bundled_name: the
    /// bundled config), else $OCIO if set, else texsyn's bundled config (compiled into the
    /// library; the same file is installed as share/texsyn/ocio/config.ocio). Returns
    /// nullptr and sets `error` (naming the file and OCIO's message) if the config cannot
    /// be read or does not validate.
    static std::unique_ptr<ColorConfig> load(const std::string& explicit_path, std::string& error);
    /// texsyn's bundled config text (YAML).
    static const char* bundled_config_text();

    /// Where the config came from: a file path, or bundled_name.
    const std::string& source() const;
    /// Whether this is the bundled config: loaded by its name or by default, or from a
    /// file whose text is the bundled config's (an installed copy).
    bool is_bundled() const;
    /// Why this config: "--colorconfig", "$OCIO" or "default" (as load() chose it).
    const std::string& origin() const;
    /// Canonical name of the colour space `name` (aliases and role names resolve), or ""
    /// if the config has no such space.
    std::string resolve(const std::string& name) const;
    /// Canonical name of the scene_linear role's colour space.
    std::string scene_linear() const;
    /// Whether `name` is a data space (no conversion applies to it).
    bool is_data(const std::string& name) const;
    /// All colour space names, in config order.
    std::vector<std::string> colorspace_names() const;
    /// "unknown colour space 'NAME', did you mean 'X'? (known: a, b, …; …)": the message
    /// for a name the config does not know, with the nearest known name or alias if one
    /// is near.
    std::string unknown_colorspace(const std::string& name) const;
    /// The config's colour spaces (name, aliases, family, encoding, data or not) and roles,
    /// one per line, as `texsyn --colorspaces` prints them.
    std::string describe() const;

    /// Converts the colour channels of `image` (1: grey, >= 3: the first three are RGB;
    /// alpha and other channels are untouched) from space `from` to space `to`, in place.
    /// Fails (false, `error` names the unknown space or OCIO's message) without modifying
    /// the image.
    bool convert(PlanarImage& image, const std::string& from, const std::string& to,
        std::string& error, int nthreads = 0) const;

    /// ImageBuf form of convert(): `src` (any pixel type; colour associated with alpha, or
    /// un-associated if flagged "oiio:UnassociatedAlpha") becomes `dst`, a float image
    /// with colour in `to`, associated with alpha if `associate` (else un-associated and
    /// flagged), and src's metadata. Fails (false, `error`) on NaN/Inf pixels or unknown
    /// spaces; `dst` is then unchanged.
    bool convert_image(const OIIO::ImageBuf& src, const std::string& from, const std::string& to,
        bool associate, OIIO::ImageBuf& dst, std::string& error, int nthreads = 0) const;

    /// The CIE xy chromaticities of space `name`'s red, green and blue primaries and white
    /// (OpenEXR's "chromaticities": rx ry gx gy bx by wx wy), through the config's
    /// cie_xyz_d65_interchange role (white points adapted to D65, as that role is). False
    /// if the config has no such role, or for a data space.
    bool chromaticities(const std::string& name, float xy[8]) const;

    /// Tags `spec`, an image about to be written in space `name` (canonical), so that
    /// texsyn and OIIO tools read the file back in that space: oiio:ColorSpace and
    /// synth:colorspace (OpenEXR and PNG keep them), Exif:ColorSpace (1 for sRGB-encoded
    /// spaces, 65535 "uncalibrated" for others: what TIFF keeps; OIIO reads 1 as sRGB),
    /// and "chromaticities" where the config gives them (OpenEXR keeps them).
    void tag_colorspace(OIIO::ImageSpec& spec, const std::string& name) const;

    /// The colour space an image file's pixels are in, and why.
    struct Guess {
        std::string space;   ///< canonical name; "" if nothing tells
        std::string reason;  ///< in words, e.g. "its synth:colorspace tag"
        std::string warning; ///< "" or why the answer may be wrong (a generic tag)
    };
    /// The colour space of an image file from its `spec`, first of: texsyn's own tag
    /// synth:colorspace; texsyn's ImageDescription ("…, colorspace NAME", for formats that
    /// keep no tag, as TIFF); `oiio:ColorSpace` if the config knows it (a generic name such
    /// as OIIO's "Linear" for every OpenEXR file: scene_linear, with a warning); else by
    /// pixel type: 8- and 16-bit integers sRGB-encoded ("sRGB - Texture"), floating point
    /// scene_linear — what OIIO assumes too.
    Guess guess_colorspace(const OIIO::ImageSpec& spec) const;
    /// Whether `name` is a generic colour-space name that says nothing of primaries:
    /// "linear" (OIIO's tag for every OpenEXR file) or a role name of the config.
    bool is_generic_name(const std::string& name) const;

private:
    struct Impl;
    explicit ColorConfig(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

/// PCA colour decorrelation (§3.5): y = M (x - mean) with M = S^-1 U^T from the SVD of the
/// colour covariance C = U S^2 U^T, so the components pc0.. are uncorrelated with unit
/// variance. Directions whose singular value is below 1e-6 of the largest carry no signal:
/// they get unit scale (no division by zero) and are marked `constant`, so a constant
/// sample or one whose colours lie on a line or plane gives a finite, correct result.
struct ColorTransform {
    int n = 0;                   ///< number of colour channels
    std::vector<double> mean;    ///< n
    std::vector<double> forward; ///< n x n, row-major: M
    std::vector<double> inverse; ///< n x n, row-major: M^-1 = U S
    std::vector<bool> constant;  ///< n: component carries no variance
};

/// First and second moments of a colour distribution.
struct ColorMoments {
    int n = 0;                      ///< number of colour channels
    std::vector<double> mean;       ///< n
    std::vector<double> covariance; ///< n x n, row-major, symmetric (divided by the count)
};

/// Mean and covariance of the first `ncolor` channels of `image` (two passes, double
/// accumulation in pixel order, so the result does not depend on threads). n = 0 for an
/// empty image or ncolor < 1.
ColorMoments color_moments(const PlanarImage& image, int ncolor);

/// Moments of the mixture of several colour distributions with weights `weights` (>= 0,
/// normalised here; same count as `parts`, all of the same n): mean m = sum w_i m_i and
/// covariance sum w_i (C_i + (m_i - m)(m_i - m)^T) — the moments of the pooled pixels when
/// the weights are the pixel shares. Used by texture mixtures (Heeger & Bergen §5) to fit
/// one basis to several samples. n = 0 if the counts or the parts' n differ, or the weights
/// sum to 0.
ColorMoments mixture_moments(const std::vector<ColorMoments>& parts, std::vector<double> weights);

/// The §3.5 transform of a distribution with these moments (see ColorTransform).
ColorTransform color_transform_from_moments(const ColorMoments& moments);

/// Fits the transform to the first `ncolor` channels of `image`:
/// color_transform_from_moments(color_moments(image, ncolor)).
ColorTransform fit_color_transform(const PlanarImage& image, int ncolor);

/// Applies x -> M (x - mean) to the first t.n channels, in place.
void decorrelate(PlanarImage& image, const ColorTransform& t, int nthreads = 0);

/// Applies y -> M^-1 y + mean to the first t.n channels, in place.
void recorrelate(PlanarImage& image, const ColorTransform& t, int nthreads = 0);

} // namespace texsyn
#pragma GCC visibility pop
