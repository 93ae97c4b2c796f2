// SPDX-License-Identifier: Apache-2.0
// A material's search image and its maps re-applied by a source map.
#include <texsyn/material.h>

#include <algorithm>
#include <cmath>

#include <texsyn/image.h>

namespace texsyn {

namespace {

// The mean over channels of each channel's standard deviation.
double mean_spread(const PlanarImage& p)
{
    double sum = 0.0;
    for (const Plane& c : p.channels) {
        double s = 0.0, s2 = 0.0;
        for (size_t i = 0; i < c.size(); ++i) {
            s += c.data()[i];
            s2 += double(c.data()[i]) * c.data()[i];
        }
        const double n = double(c.size()), mean = s / n;
        sum += std::sqrt(std::max(0.0, s2 / n - mean * mean));
    }
    return sum / double(p.channels.size());
}

} // namespace

bool material_search_image(const Material& material, OIIO::ImageBuf& dst, std::string& error)
{
    if (material.maps.empty()) {
        error = "the material has no maps";
        return false;
    }
    PlanarImage first;
    if (!planes_from_imagebuf(material.maps[0].image, first, error)) {
        error = material.maps[0].name + ": " + error;
        return false;
    }
    const double reference = mean_spread(first);
    PlanarImage search;
    for (const MaterialMap& map : material.maps) {
        if (!(map.weight > 0.0f))
            continue;
        PlanarImage p;
        if (!planes_from_imagebuf(map.image, p, error)) {
            error = map.name + ": " + error;
            return false;
        }
        if (p.width() != first.width() || p.height() != first.height()) {
            error = "the " + map.name + " map is " + std::to_string(p.width()) + "x"
                + std::to_string(p.height()) + " and the " + material.maps[0].name + " "
                + std::to_string(first.width()) + "x" + std::to_string(first.height())
                + ": a map the search weighs must have the " + material.maps[0].name + "'s size";
            return false;
        }
        const double spread = mean_spread(p);
        const float scale
            = spread > 0.0 ? float(double(map.weight) * reference / spread) : map.weight;
        for (size_t c = 0; c < p.channels.size(); ++c) {
            Plane& plane = p.channels[c];
            for (size_t i = 0; i < plane.size(); ++i)
                plane.data()[i] *= scale;
            search.channels.push_back(std::move(plane));
            search.channel_names.push_back(map.name + "." + p.channel_names[c]);
        }
    }
    if (search.channels.empty()) {
        error = "no map of the material has a weight above 0 in the search";
        return false;
    }
    imagebuf_from_planes(search, dst, false);
    dst.specmod().erase_attribute("oiio:UnassociatedAlpha");
    return true;
}

bool apply_material(
    const OIIO::ImageBuf& source_map, const Material& material, Material& out, std::string& error)
{
    out.normals = material.normals;
    out.maps.clear();
    for (const MaterialMap& map : material.maps) {
        ApplyMapOptions opt;
        opt.normal = map.kind == MapKind::Normal ? material.normals : NormalMap::None;
        MaterialMap applied { map.name, map.kind, map.weight, {} };
        if (!apply_source_map(applied.image, source_map, map.image, opt)) {
            error = "the " + map.name + " map: " + applied.image.geterror();
            return false;
        }
        out.maps.push_back(std::move(applied));
    }
    return true;
}

} // namespace texsyn
