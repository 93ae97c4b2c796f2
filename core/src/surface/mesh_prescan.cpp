// SPDX-License-Identifier: Apache-2.0
// A first pass over a mesh file, before OpenMesh reads it: OpenMesh's OBJ reader drops
// faces with repeated or unreadable indices, stops at a coordinate it cannot parse and
// allocates what a PLY header announces, all without failing. This pass refuses those
// files, and absurd sizes, while allocating nothing per element.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

std::string cannot_open()
{
    return std::string("cannot be opened (") + std::strerror(errno) + ")";
}

// "line N: 'TEXT': " with TEXT cut to a readable length (and without a CR line end).
std::string at_line(uint64_t number, std::string line)
{
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
        line.pop_back();
    std::string text = line.substr(0, 48);
    if (text.size() < line.size())
        text += "...";
    return "line " + std::to_string(number) + ": '" + text + "': ";
}

const char* skip_blanks(const char* s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r')
        ++s;
    return s;
}

// One OBJ index ("12" or "-3"), or false if `s` does not start with one.
bool parse_index(const char*& s, long long& value)
{
    char* end = nullptr;
    errno = 0;
    value = std::strtoll(s, &end, 10);
    if (end == s || errno == ERANGE || (*s != '-' && !std::isdigit(static_cast<unsigned char>(*s))))
        return false;
    s = end;
    return true;
}

// One face corner "v", "v/vt", "v//vn" or "v/vt/vn"; false if malformed.
bool parse_corner(const char*& s, long long& vertex, bool& has_texcoord)
{
    long long ignored;
    has_texcoord = false;
    if (!parse_index(s, vertex))
        return false;
    if (*s != '/')
        return true;
    ++s;
    if (*s != '/') {
        if (!parse_index(s, ignored))
            return false;
        has_texcoord = true;
    }
    if (*s != '/')
        return true;
    ++s;
    return parse_index(s, ignored);
}

bool at_end_of_token(const char* s)
{
    return *s == '\0' || *s == ' ' || *s == '\t' || *s == '\r';
}

bool too_many(uint64_t count, const char* what_counted, std::string& what)
{
    if (count <= kMaxMeshElements)
        return false;
    what = "has more than " + std::to_string(kMaxMeshElements) + " " + what_counted
        + " (texsyn's limit for one surface)";
    return true;
}

bool scan_vertex_line(const char* s, uint64_t number, const std::string& line, std::string& what)
{
    for (int k = 0; k < 3; ++k) {
        s = skip_blanks(s);
        char* end = nullptr;
        const double value = std::strtod(s, &end);
        if (end == s || !at_end_of_token(end) || !std::isfinite(value)
            || std::abs(value) > 3.4e38) {
            what = at_line(number, line) + "a vertex needs three finite numbers (x y z)";
            return false;
        }
        s = end;
    }
    return true;
}

struct FaceScan {
    uint64_t number = 0; // of the face line
    std::vector<long long> corners;
    bool first_face = true, texcoords = false;
};

bool scan_face_line(const char* s, const std::string& line, uint64_t vertices_so_far,
    FaceScan& face, std::string& what)
{
    face.corners.clear();
    bool any_texcoord = false, all_texcoords = true;
    for (s = skip_blanks(s); *s; s = skip_blanks(s)) {
        long long vertex = 0;
        bool has_texcoord = false;
        if (!parse_corner(s, vertex, has_texcoord) || !at_end_of_token(s)) {
            what = at_line(face.number, line) + "a face corner is v, v/vt, v//vn or v/vt/vn, "
                + "with whole numbers";
            return false;
        }
        // As OpenMesh resolves them: negative indices count back from the last vertex read.
        if (vertex < 0)
            vertex += static_cast<long long>(vertices_so_far) + 1;
        if (vertex < 1) {
            what = at_line(face.number, line)
                + "a vertex index must be at least 1 (OBJ counts from 1)";
            return false;
        }
        face.corners.push_back(vertex);
        any_texcoord |= has_texcoord;
        all_texcoords &= has_texcoord;
    }
    if (face.corners.size() < 3) {
        what = at_line(face.number, line) + "a face needs at least 3 vertices, found "
            + std::to_string(face.corners.size());
        return false;
    }
    std::vector<long long> sorted = face.corners;
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end()) {
        what = at_line(face.number, line) + "the face lists vertex " + std::to_string(*repeated)
            + " twice";
        return false;
    }
    if (any_texcoord != all_texcoords || (!face.first_face && any_texcoord != face.texcoords)) {
        what = at_line(face.number, line)
            + "texture coordinates on some face corners only (give every corner v/vt, or none)";
        return false;
    }
    face.first_face = false;
    face.texcoords = any_texcoord;
    return true;
}

} // namespace

bool prescan_obj(const std::string& path, MeshFileCounts& counts, std::string& what)
{
    counts = MeshFileCounts();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        what = cannot_open();
        return false;
    }
    std::string line;
    FaceScan face;
    for (uint64_t number = 1; std::getline(in, line); ++number) {
        const char* s = skip_blanks(line.c_str());
        const char* word_end = s;
        while (*word_end && !at_end_of_token(word_end))
            ++word_end;
        const std::string keyword(s, word_end);
        if (keyword == "v") {
            if (!scan_vertex_line(word_end, number, line, what))
                return false;
            if (too_many(++counts.vertices, "vertices", what))
                return false;
        } else if (keyword == "vt") {
            if (too_many(++counts.texcoords, "texture coordinates", what))
                return false;
        } else if (keyword == "f") {
            face.number = number;
            if (!scan_face_line(word_end, line, counts.vertices, face, what))
                return false;
            ++counts.faces;
            counts.triangles += face.corners.size() - 2;
            if (too_many(counts.triangles, "triangles", what))
                return false;
        }
    }
    if (in.bad()) {
        what = "cannot be read to the end (" + std::string(std::strerror(errno)) + ")";
        return false;
    }
    counts.face_texcoords = face.texcoords;
    return true;
}

namespace {

bool has_property(const PlyElement& element, const char* name, bool list)
{
    for (const PlyProperty& p : element.properties)
        if (p.name == name && (p.count_size > 0) == list)
            return true;
    return false;
}

// Whether the data after an ASCII header holds at least `elements` lines, the last one
// ended by a line break (a file cut in the middle of a line has lost its end).
bool ascii_data_complete(std::istream& in, uint64_t elements)
{
    uint64_t lines = 0;
    std::string line;
    bool ended = true;
    while (std::getline(in, line)) {
        ended = !in.eof();
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            ++lines;
    }
    return lines >= elements && ended;
}

} // namespace

bool prescan_ply(const std::string& path, MeshFileCounts& counts, std::string& what)
{
    counts = MeshFileCounts();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        what = cannot_open();
        return false;
    }
    PlyHeader header;
    if (!read_ply_header(in, header, what))
        return false;
    const PlyElement* vertex = header.element("vertex");
    const PlyElement* face = header.element("face");
    if (!vertex || !has_property(*vertex, "x", false) || !has_property(*vertex, "y", false)
        || !has_property(*vertex, "z", false)) {
        what = "the PLY header has no vertex element with x, y and z";
        return false;
    }
    if (!face
        || !(has_property(*face, "vertex_indices", true)
            || has_property(*face, "vertex_index", true))) {
        what = "the PLY header has no face element with a vertex_indices list";
        return false;
    }
    counts.vertices = vertex->count;
    counts.faces = face->count;
    if (too_many(counts.vertices, "vertices", what) || too_many(counts.faces, "faces", what))
        return false;

    uint64_t elements = 0, smallest_bytes = 0;
    for (const PlyElement& e : header.elements) {
        if (too_many(e.count, ("'" + e.name + "' elements").c_str(), what))
            return false;
        uint64_t record = 0;
        for (const PlyProperty& p : e.properties) {
            const bool indices
                = &e == face && (p.name == "vertex_indices" || p.name == "vertex_index");
            record += p.count_size > 0 ? p.count_size + (indices ? 3 * p.size : 0) : p.size;
        }
        elements += e.count;
        smallest_bytes += e.count * record;
    }
    const std::string announced = "its header announces " + std::to_string(counts.vertices)
        + " vertices and " + std::to_string(counts.faces) + " faces";
    if (header.format == PlyHeader::Format::Ascii) {
        if (!ascii_data_complete(in, elements)) {
            what = "is truncated: " + announced + ", but the data stops before their end";
            return false;
        }
        return true;
    }
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (ec || size < header.bytes + smallest_bytes) {
        what = "is truncated: " + announced + " (at least "
            + std::to_string(header.bytes + smallest_bytes) + " bytes), but the file has "
            + std::to_string(ec ? 0 : size);
        return false;
    }
    return true;
}

} // namespace texsyn::detail
