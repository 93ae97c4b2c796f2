// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ, read line by line: v, vt and f lines, every token validated (a face with
// repeated or unreadable indices, a coordinate that is not a number, are refused with
// their line, never dropped or guessed). Material libraries and other files an OBJ names
// are never opened: a mesh from an untrusted source cannot make texsyn read a FIFO or a
// device.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

const char* skip_blanks(const char* s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r')
        ++s;
    return s;
}

bool at_end_of_token(const char* s)
{
    return *s == '\0' || *s == ' ' || *s == '\t' || *s == '\r';
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

// One face corner "v", "v/vt", "v//vn" or "v/vt/vn"; false if malformed. `texcoord` is 0
// when the corner has none.
bool parse_corner(const char*& s, long long& vertex, long long& texcoord)
{
    long long ignored;
    texcoord = 0;
    if (!parse_index(s, vertex))
        return false;
    if (*s != '/')
        return true;
    ++s;
    if (*s != '/' && (!parse_index(s, texcoord) || texcoord == 0))
        return false;
    if (*s != '/')
        return true;
    ++s;
    return parse_index(s, ignored);
}

// `count` finite numbers (beyond float's range counts as not finite) from `s`, of which
// the first `required` must be there; the rest of the line is ignored (OBJ writers put a
// w or a colour there).
bool parse_numbers(const char* s, int required, int count, float* values)
{
    for (int k = 0; k < count; ++k) {
        s = skip_blanks(s);
        if (k >= required && *s == '\0')
            return true;
        char* end = nullptr;
        const double value = std::strtod(s, &end);
        if (end == s || !at_end_of_token(end) || !std::isfinite(value) || std::abs(value) > 3.4e38)
            return false;
        values[k] = float(value);
        s = end;
    }
    return true;
}

// An OBJ index (from 1, or negative from the end of what was read so far) as an index from
// 0; `so_far` is the count of elements read before the line.
long long from_obj_index(long long index, size_t so_far)
{
    return index < 0 ? index + static_cast<long long>(so_far) : index - 1;
}

class ObjReader {
public:
    explicit ObjReader(MeshRecord& record)
        : m_record(record)
    { }

    bool read_line(uint64_t number, const std::string& line, std::string& what)
    {
        m_number = number;
        m_line = &line;
        const char* s = skip_blanks(line.c_str());
        const char* word_end = s;
        while (!at_end_of_token(word_end))
            ++word_end;
        const std::string keyword(s, word_end);
        if (keyword == "v")
            return read_vertex(word_end, what);
        if (keyword == "vt")
            return read_texcoord(word_end, what);
        if (keyword == "f")
            return read_face(word_end, what);
        return true;
    }

    // Per-corner UVs from the faces' vt indices, once every vt line is known.
    bool finish(std::string& what)
    {
        if (!m_faces_have_texcoords)
            return true;
        m_record.corner_uvs.resize(m_texcoord_of_corner.size());
        for (size_t f = 0; f < m_record.polygons(); ++f)
            for (size_t c = m_record.polygon_start[f]; c < m_record.polygon_start[f + 1]; ++c) {
                const long long t = m_texcoord_of_corner[c];
                if (t < 0 || size_t(t) >= m_texcoords.size()) {
                    what = "face " + std::to_string(f + 1)
                        + " refers to a texture coordinate the file does not have (it has "
                        + std::to_string(m_texcoords.size()) + " vt lines)";
                    return false;
                }
                m_record.corner_uvs[c] = m_texcoords[t];
            }
        return true;
    }

private:
    std::string here() const { return at_line(m_number, *m_line); }

    bool read_vertex(const char* s, std::string& what)
    {
        float xyz[3];
        if (!parse_numbers(s, 3, 3, xyz)) {
            what = here() + "a vertex needs three finite numbers (x y z)";
            return false;
        }
        m_record.points.emplace_back(xyz[0], xyz[1], xyz[2]);
        return !too_many_mesh_elements(m_record.points.size(), "vertices", what);
    }

    bool read_texcoord(const char* s, std::string& what)
    {
        float uv[2] = { 0, 0 };
        if (!parse_numbers(s, 1, 2, uv)) {
            what = here() + "a texture coordinate needs one or two finite numbers (u v)";
            return false;
        }
        m_texcoords.emplace_back(uv[0], uv[1]);
        return !too_many_mesh_elements(m_texcoords.size(), "texture coordinates", what);
    }

    bool read_face(const char* s, std::string& what)
    {
        const size_t begin = m_record.corners.size();
        bool any_texcoord = false, all_texcoords = true;
        for (s = skip_blanks(s); *s; s = skip_blanks(s)) {
            long long vertex = 0, texcoord = 0;
            if (!parse_corner(s, vertex, texcoord) || !at_end_of_token(s)) {
                what = here() + "a face corner is v, v/vt, v//vn or v/vt/vn, with whole numbers";
                return false;
            }
            vertex = from_obj_index(vertex, m_record.points.size());
            if (vertex < 0) {
                what = here() + "a vertex index must be at least 1 (OBJ counts from 1)";
                return false;
            }
            m_record.corners.push_back(vertex);
            m_texcoord_of_corner.push_back(
                texcoord ? from_obj_index(texcoord, m_texcoords.size()) : -1);
            any_texcoord |= texcoord != 0;
            all_texcoords &= texcoord != 0;
        }
        const size_t n = m_record.corners.size() - begin;
        if (n < 3) {
            what = here() + "a face needs at least 3 vertices, found " + std::to_string(n);
            return false;
        }
        std::vector<int64_t> sorted(m_record.corners.begin() + begin, m_record.corners.end());
        std::sort(sorted.begin(), sorted.end());
        const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
        if (repeated != sorted.end()) {
            what = here() + "the face lists vertex " + std::to_string(*repeated + 1) + " twice";
            return false;
        }
        if (any_texcoord != all_texcoords
            || (m_record.polygons() > 0 && any_texcoord != m_faces_have_texcoords)) {
            what = here()
                + "texture coordinates on some face corners only (give every corner v/vt, or "
                  "none)";
            return false;
        }
        m_faces_have_texcoords = any_texcoord;
        m_record.end_polygon();
        m_triangles += n - 2;
        return !too_many_mesh_elements(m_triangles, "triangles", what);
    }

    MeshRecord& m_record;
    std::vector<Imath::V2f> m_texcoords;         // the vt lines
    std::vector<long long> m_texcoord_of_corner; // into m_texcoords, -1 for none
    bool m_faces_have_texcoords = false;
    uint64_t m_triangles = 0;
    uint64_t m_number = 0;
    const std::string* m_line = nullptr;
};

} // namespace

bool read_obj_record(const std::string& path, MeshRecord& record, std::string& what)
{
    record = MeshRecord();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        what = cannot_open_mesh();
        return false;
    }
    ObjReader reader(record);
    std::string line;
    for (uint64_t number = 1;; ++number) {
        const LineRead read = read_mesh_line(in, line);
        if (read == LineRead::End)
            break;
        if (read == LineRead::TooLong) {
            what = line_too_long(number, line, "an OBJ file");
            return false;
        }
        if (!reader.read_line(number, line, what))
            return false;
    }
    if (in.bad()) {
        what = "cannot be read to the end (" + std::string(std::strerror(errno)) + ")";
        return false;
    }
    return reader.finish(what);
}

} // namespace texsyn::detail
