// SPDX-License-Identifier: Apache-2.0
// The textured-mesh output (DESIGN.md "Output files"): binary PLY with per-face colours,
// written like every texsyn output (temporary file, synced, checked, renamed).
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>
#include <texsyn/version.h>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

struct PlyLayout {
    size_t vertices = 0, faces = 0, channels = 0;
    bool display = false;
    uint64_t face_bytes() const { return 1 + 3 * 4 + 4 * channels + (display ? 3 : 0); }
    uint64_t data_bytes() const { return vertices * 12 + faces * face_bytes(); }
};

bool valid_property_name(const std::string& name)
{
    if (name.empty())
        return false;
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
            return false;
    return true;
}

// The arguments' consistency; `what` names the parameter.
bool check_arguments(const std::vector<Imath::V3f>& vertices,
    const std::vector<std::array<uint32_t, 3>>& faces,
    const std::vector<std::vector<float>>& channels, const std::vector<std::string>& names,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& what)
{
    constexpr size_t int_max = 2147483647;
    if (faces.empty() || faces.size() > int_max || vertices.size() > int_max) {
        what = "faces: " + std::to_string(faces.size()) + " faces and "
            + std::to_string(vertices.size()) + " vertices (1 to 2^31-1 faces, at most 2^31-1 "
            + "vertices)";
        return false;
    }
    for (size_t f = 0; f < faces.size(); ++f)
        for (uint32_t v : faces[f])
            if (v >= vertices.size()) {
                what = "faces[" + std::to_string(f) + "] refers to vertex " + std::to_string(v)
                    + ", but there are " + std::to_string(vertices.size());
                return false;
            }
    for (size_t v = 0; v < vertices.size(); ++v)
        if (!std::isfinite(vertices[v].x) || !std::isfinite(vertices[v].y)
            || !std::isfinite(vertices[v].z)) {
            what = "vertices[" + std::to_string(v) + "] is not finite";
            return false;
        }
    if (channels.size() != names.size()) {
        what = "face_channels has " + std::to_string(channels.size())
            + " channels but channel_names " + std::to_string(names.size()) + " names";
        return false;
    }
    std::set<std::string> taken { "vertex_indices" };
    if (display_rgb)
        taken.insert({ "red", "green", "blue" });
    for (size_t c = 0; c < names.size(); ++c) {
        const std::string at = "channel_names[" + std::to_string(c) + "]='" + names[c] + "'";
        if (!valid_property_name(names[c])) {
            what = at + " is not a PLY property name (letters, digits and '_')";
            return false;
        }
        if (!taken.insert(names[c]).second) {
            what = at + " is already a face property of this file";
            return false;
        }
        if (channels[c].size() != faces.size()) {
            what = "face_channels[" + std::to_string(c) + "] has "
                + std::to_string(channels[c].size()) + " values for " + std::to_string(faces.size())
                + " faces";
            return false;
        }
    }
    if (display_rgb && display_rgb->size() != faces.size()) {
        what = "display_rgb has " + std::to_string(display_rgb->size()) + " colours for "
            + std::to_string(faces.size()) + " faces";
        return false;
    }
    return true;
}

std::string ply_header_text(const PlyLayout& layout, const std::vector<std::string>& names)
{
    std::string text = "ply\nformat binary_little_endian 1.0\n";
    text += std::string("comment texsyn ") + texsyn::version() + " surface texture\n";
    if (!names.empty())
        text += "comment face properties " + OIIO::Strutil::join(names, " ")
            + ": float, scene-linear (the OCIO config's scene_linear role)\n";
    if (layout.display)
        text += "comment face properties red green blue: 8-bit sRGB-encoded, for viewers\n";
    text += "element vertex " + std::to_string(layout.vertices) + "\n";
    text += "property float x\nproperty float y\nproperty float z\n";
    text += "element face " + std::to_string(layout.faces) + "\n";
    text += "property list uchar int vertex_indices\n";
    for (const std::string& name : names)
        text += "property float " + name + "\n";
    if (layout.display)
        text += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    return text + "end_header\n";
}

// Little-endian whatever the host is.
void put_u32(std::vector<char>& out, uint32_t value)
{
    for (int k = 0; k < 4; ++k)
        out.push_back(char((value >> (8 * k)) & 0xff));
}

void put_float(std::vector<char>& out, float value)
{
    uint32_t bits;
    std::memcpy(&bits, &value, 4);
    put_u32(out, bits);
}

bool write_ply_data(const std::string& path, const std::string& header,
    const std::vector<Imath::V3f>& vertices, const std::vector<std::array<uint32_t, 3>>& faces,
    const std::vector<std::vector<float>>& channels,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& reason)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) {
        reason = std::strerror(errno);
        return false;
    }
    out.write(header.data(), std::streamsize(header.size()));
    constexpr size_t chunk = 1 << 20;
    std::vector<char> bytes;
    bytes.reserve(chunk + 256);
    auto flush = [&](bool always) {
        if (always || bytes.size() >= chunk) {
            out.write(bytes.data(), std::streamsize(bytes.size()));
            bytes.clear();
        }
    };
    for (const Imath::V3f& v : vertices) {
        put_float(bytes, v.x);
        put_float(bytes, v.y);
        put_float(bytes, v.z);
        flush(false);
    }
    for (size_t f = 0; f < faces.size(); ++f) {
        bytes.push_back(3);
        for (uint32_t v : faces[f])
            put_u32(bytes, v);
        for (const std::vector<float>& channel : channels)
            put_float(bytes, channel[f]);
        if (display_rgb)
            bytes.insert(bytes.end(), (*display_rgb)[f].begin(), (*display_rgb)[f].end());
        flush(false);
    }
    flush(true);
    out.close();
    if (!out) {
        reason = std::string("writing failed (") + std::strerror(errno) + ")";
        return false;
    }
    return true;
}

// The file reads back with the header written and exactly the data it announces.
bool verify_ply(const std::string& path, const PlyLayout& layout, std::string& reason)
{
    std::ifstream in(path, std::ios::binary);
    PlyHeader header;
    if (!in || !read_ply_header(in, header, reason)) {
        reason = "the written file does not read back: " + reason;
        return false;
    }
    const PlyElement* vertex = header.element("vertex");
    const PlyElement* face = header.element("face");
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (header.format != PlyHeader::Format::BinaryLittleEndian || !vertex || !face
        || vertex->count != layout.vertices || face->count != layout.faces || ec
        || size != header.bytes + layout.data_bytes()) {
        reason = "the written file reads back with another header or size (disk full?)";
        return false;
    }
    return true;
}

} // namespace

bool write_face_colour_ply(const std::string& path, const std::vector<Imath::V3f>& vertices,
    const std::vector<std::array<uint32_t, 3>>& faces,
    const std::vector<std::vector<float>>& face_channels,
    const std::vector<std::string>& channel_names,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& error)
{
    std::string what;
    if (!OIIO::Strutil::iends_with(path, ".ply")) {
        error = path + ": cannot write (a face-colour mesh is written as .ply)";
        return false;
    }
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
        error = path + ": cannot write (directory " + parent.string() + " does not exist)";
        return false;
    }
    if (!check_arguments(vertices, faces, face_channels, channel_names, display_rgb, what)) {
        error = path + ": cannot write (" + what + ")";
        return false;
    }
    PlyLayout layout;
    layout.vertices = vertices.size();
    layout.faces = faces.size();
    layout.channels = face_channels.size();
    layout.display = display_rgb != nullptr;

    if (!check_output_destination(path, error))
        return false;
    const std::string tmp = temporary_path_for(path);
    bool written = false;
    try {
        written = write_ply_data(tmp, ply_header_text(layout, channel_names), vertices, faces,
                      face_channels, display_rgb, what)
            && sync_written_file(tmp, what) && verify_ply(tmp, layout, what);
    } catch (const std::bad_alloc&) {
        what = "out of memory";
    }
    if (written)
        return commit_file(tmp, path, error);
    discard_temporary(tmp);
    error = path + ": cannot write (" + what + ")";
    return false;
}

} // namespace texsyn::detail
