// SPDX-License-Identifier: Apache-2.0
// PLY data (ASCII, binary little- and big-endian) after a header read by ply_header.cpp.
// Every element of the file is read in order, the ones texsyn does not use as well (their
// bytes have to be passed), and every ASCII token is checked against its property's type
// before it is used: a 'nan', an 'x' or a number beyond float's range is refused with its
// line, never handed on as garbage.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

// Names a value in messages ("vertex 2's x", "face 1's vertex_indices count"); the text
// is made only when a message needs it, not for each of millions of values.
struct ValueName {
    const PlyElement& element;
    uint64_t index; // from 0
    const PlyProperty& property;
    bool count = false; // the list's item count

    std::string text() const
    {
        return element.name + " " + std::to_string(index + 1) + "'s " + property.name
            + (count ? " count" : "");
    }
};

// The values of a PLY file's data section, one at a time, as doubles (every PLY type
// converts exactly). Failures leave a reason without the file name.
class PlyValues {
public:
    PlyValues(std::istream& in, PlyHeader::Format format, uint64_t first_line)
        : m_in(in)
        , m_format(format)
        , m_number(first_line - 1)
    { }

    // The next value, of `type`, for the value `name`.
    bool next(PlyType type, const ValueName& name, double& value, std::string& what)
    {
        return m_format == PlyHeader::Format::Ascii ? next_token(type, name, value, what)
                                                    : next_bytes(type, value);
    }

    // Starts an element: in an ASCII file, the next line that is not blank.
    bool begin_element(std::string& what)
    {
        if (m_format != PlyHeader::Format::Ascii)
            return true;
        do {
            const LineRead read = read_mesh_line(m_in, m_line);
            ++m_number;
            m_at = 0;
            if (read == LineRead::End) {
                m_truncated = true;
                return false;
            }
            if (read == LineRead::TooLong) {
                what = line_too_long(m_number, m_line, "PLY data");
                return false;
            }
            m_terminated = read == LineRead::Line;
        } while (m_line.find_first_not_of(" \t\r") == m_line.npos);
        return true;
    }

    // Ends element `index` of `element`: in an ASCII file, its line must hold nothing more.
    bool end_element(const PlyElement& element, uint64_t index, std::string& what) const
    {
        if (m_format != PlyHeader::Format::Ascii
            || m_line.find_first_not_of(" \t\r", m_at) == m_line.npos)
            return true;
        what = at_line(m_number, m_line) + element.name + " " + std::to_string(index + 1)
            + " has more values than the header's properties (one element per line)";
        return false;
    }

    // After the last value: an ASCII file whose last line has no line break has lost its
    // end (a number cut short still parses).
    bool complete() const { return m_format != PlyHeader::Format::Ascii || m_terminated; }

    // Whether a value was asked for after the data's end.
    bool truncated() const { return m_truncated; }

private:
    bool next_token(PlyType type, const ValueName& name, double& value, std::string& what)
    {
        if (m_line.find_first_not_of(" \t\r", m_at) == m_line.npos) {
            m_truncated = !m_terminated; // the file ends in this line: it was cut
            what = at_line(m_number, m_line) + "the line ends before " + name.text()
                + " (one element per line)";
            return false;
        }
        const size_t begin = m_line.find_first_not_of(" \t\r", m_at);
        size_t end = m_line.find_first_of(" \t\r", begin);
        if (end == m_line.npos)
            end = m_line.size();
        m_at = end;
        const std::string token = m_line.substr(begin, end - begin);
        char* stop = nullptr;
        value = std::strtod(token.c_str(), &stop);
        const PlyTypeTraits& t = ply_type_traits(type);
        if (stop != token.c_str() + token.size() || !std::isfinite(value) || value < t.low
            || value > t.high || (t.integer && value != std::floor(value))) {
            what = at_line(m_number, m_line) + name.text() + ": '" + token.substr(0, 24)
                + "' is not " + (t.integer ? "an integer" : "a finite number") + " of PLY type "
                + t.name;
            return false;
        }
        return true;
    }

    bool next_bytes(PlyType type, double& value)
    {
        const int size = ply_type_traits(type).size;
        unsigned char bytes[8];
        if (!m_in.read(reinterpret_cast<char*>(bytes), size)) {
            m_truncated = true;
            return false;
        }
        uint64_t bits = 0; // the value's bits, least significant byte first in `bytes`
        for (int k = 0; k < size; ++k) {
            const int from = m_format == PlyHeader::Format::BinaryLittleEndian ? k : size - 1 - k;
            bits |= uint64_t(bytes[from]) << (8 * k);
        }
        switch (type) {
        case PlyType::Int8:
            value = int8_t(bits);
            break;
        case PlyType::UInt8:
            value = uint8_t(bits);
            break;
        case PlyType::Int16:
            value = int16_t(bits);
            break;
        case PlyType::UInt16:
            value = uint16_t(bits);
            break;
        case PlyType::Int32:
            value = int32_t(bits);
            break;
        case PlyType::UInt32:
            value = uint32_t(bits);
            break;
        case PlyType::Float32: {
            const uint32_t b = uint32_t(bits);
            float f;
            std::memcpy(&f, &b, 4);
            value = f;
            break;
        }
        case PlyType::Float64:
            std::memcpy(&value, &bits, 8);
            break;
        }
        return true;
    }

    std::istream& m_in;
    PlyHeader::Format m_format;
    std::string m_line;
    size_t m_at = 0;
    uint64_t m_number; // of m_line, counting the header's lines
    bool m_terminated = true;
    bool m_truncated = false;
};

// What texsyn takes from an element's properties: the index of each in the element's
// property list, or -1.
struct PlyRoles {
    int x = -1, y = -1, z = -1, u = -1, v = -1; // vertex
    int indices = -1, texcoords = -1;           // face lists
};

int property_index(const PlyElement& element, const char* name, bool list)
{
    for (size_t k = 0; k < element.properties.size(); ++k)
        if (element.properties[k].name == name && (element.properties[k].count_size > 0) == list)
            return int(k);
    return -1;
}

PlyRoles vertex_roles(const PlyElement& vertex)
{
    PlyRoles roles;
    roles.x = property_index(vertex, "x", false);
    roles.y = property_index(vertex, "y", false);
    roles.z = property_index(vertex, "z", false);
    for (const auto& [u, v] : { std::pair { "u", "v" }, std::pair { "s", "t" },
             std::pair { "texture_u", "texture_v" }, std::pair { "texture_s", "texture_t" } })
        if (roles.u < 0 && property_index(vertex, u, false) >= 0
            && property_index(vertex, v, false) >= 0) {
            roles.u = property_index(vertex, u, false);
            roles.v = property_index(vertex, v, false);
        }
    return roles;
}

PlyRoles face_roles(const PlyElement& face)
{
    PlyRoles roles;
    roles.indices = property_index(face, "vertex_indices", true);
    if (roles.indices < 0)
        roles.indices = property_index(face, "vertex_index", true);
    roles.texcoords = property_index(face, "texcoord", true);
    return roles;
}

// Whether the file is at least as long as the header's counts need with the shortest
// records (a face list of 3): checked before reading, so that a binary file cut short is
// refused at once, with its sizes.
bool binary_size_suffices(const std::string& path, const PlyHeader& header,
    const std::string& announced, std::string& what)
{
    uint64_t smallest = 0;
    for (const PlyElement& e : header.elements) {
        const PlyRoles roles = e.name == "face" ? face_roles(e) : PlyRoles();
        uint64_t record = 0;
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            const uint64_t items = int(k) == roles.indices ? 3 : int(k) == roles.texcoords ? 6 : 0;
            record += p.count_size > 0 ? p.count_size + items * p.size : p.size;
        }
        smallest += e.count * record;
    }
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (ec || size < header.bytes + smallest) {
        what = "is truncated: " + announced + " (at least "
            + std::to_string(header.bytes + smallest) + " bytes), but the file has "
            + std::to_string(ec ? 0 : size);
        return false;
    }
    return true;
}

class PlyRecordReader {
public:
    PlyRecordReader(PlyValues& values, MeshRecord& record)
        : m_values(values)
        , m_record(record)
    { }

    bool read_element(const PlyElement& element, std::string& what)
    {
        const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
        const PlyRoles roles = is_vertex ? vertex_roles(element)
            : is_face                    ? face_roles(element)
                                         : PlyRoles();
        std::vector<double> scalars(element.properties.size());
        for (uint64_t i = 0; i < element.count; ++i) {
            m_face_texcoords.clear();
            if (!m_values.begin_element(what))
                return false;
            for (size_t k = 0; k < element.properties.size(); ++k) {
                const PlyProperty& p = element.properties[k];
                const ValueName name { element, i, p };
                if (p.count_size == 0) {
                    if (!m_values.next(p.type, name, scalars[k], what))
                        return false;
                } else if (!read_list(
                               name, int(k) == roles.indices, int(k) == roles.texcoords, what)) {
                    return false;
                }
            }
            if (!m_values.end_element(element, i, what))
                return false;
            if (is_vertex)
                add_vertex(roles, scalars);
            if (is_face && !add_face(roles, i, what))
                return false;
        }
        return true;
    }

private:
    bool read_list(const ValueName& name, bool indices, bool texcoords, std::string& what)
    {
        const PlyProperty& p = name.property;
        double count = 0;
        if (!m_values.next(p.count_type, { name.element, name.index, p, true }, count, what))
            return false;
        if (count < 0 || count > double(kMaxMeshElements)) {
            what = name.text() + " has " + std::to_string(int64_t(count)) + " items";
            return false;
        }
        for (uint64_t j = 0; j < uint64_t(count); ++j) {
            double value = 0;
            if (!m_values.next(p.type, name, value, what))
                return false;
            if (indices)
                m_record.corners.push_back(int64_t(value));
            else if (texcoords)
                m_face_texcoords.push_back(float(value));
        }
        return true;
    }

    void add_vertex(const PlyRoles& roles, const std::vector<double>& scalars)
    {
        m_record.points.emplace_back(
            float(scalars[roles.x]), float(scalars[roles.y]), float(scalars[roles.z]));
        if (roles.u >= 0)
            m_record.vertex_uvs.emplace_back(float(scalars[roles.u]), float(scalars[roles.v]));
    }

    bool add_face(const PlyRoles& roles, uint64_t i, std::string& what)
    {
        const size_t begin = m_record.polygon_start.back(), n = m_record.corners.size() - begin;
        for (size_t c = begin; c < m_record.corners.size(); ++c)
            if (m_record.corners[c] < 0) {
                what = "face " + std::to_string(i + 1) + " has the vertex index "
                    + std::to_string(m_record.corners[c]) + " (PLY counts from 0)";
                return false;
            }
        if (roles.texcoords >= 0) {
            if (m_face_texcoords.size() != 2 * n) {
                what = "face " + std::to_string(i + 1) + " has " + std::to_string(n)
                    + " corners but " + std::to_string(m_face_texcoords.size())
                    + " texcoord values (two per corner)";
                return false;
            }
            for (size_t k = 0; k < n; ++k)
                m_record.corner_uvs.emplace_back(
                    m_face_texcoords[2 * k], m_face_texcoords[2 * k + 1]);
        }
        m_record.end_polygon();
        m_triangles += n > 2 ? n - 2 : 0;
        return !too_many_mesh_elements(m_triangles, "triangles", what);
    }

    PlyValues& m_values;
    MeshRecord& m_record;
    std::vector<float> m_face_texcoords;
    uint64_t m_triangles = 0;
};

bool check_ply_header(const PlyHeader& header, std::string& what)
{
    const PlyElement* vertex = header.element("vertex");
    const PlyElement* face = header.element("face");
    const PlyRoles v = vertex ? vertex_roles(*vertex) : PlyRoles();
    if (v.x < 0 || v.y < 0 || v.z < 0) {
        what = "the PLY header has no vertex element with x, y and z";
        return false;
    }
    const PlyRoles f = face ? face_roles(*face) : PlyRoles();
    if (f.indices < 0) {
        what = "the PLY header has no face element with a vertex_indices list";
        return false;
    }
    if (!ply_type_traits(face->properties[f.indices].type).integer) {
        what = std::string("the PLY face element's ") + face->properties[f.indices].name
            + " list is of type " + ply_type_traits(face->properties[f.indices].type).name
            + " (vertex indices are integers)";
        return false;
    }
    for (const PlyElement& e : header.elements)
        if (too_many_mesh_elements(e.count,
                e.name == "vertex"     ? "vertices"
                    : e.name == "face" ? "faces"
                                       : "'" + e.name + "' elements",
                what))
            return false;
    return true;
}

} // namespace

bool read_ply_record(const std::string& path, MeshRecord& record, std::string& what)
{
    record = MeshRecord();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        what = cannot_open_mesh();
        return false;
    }
    PlyHeader header;
    if (!read_ply_header(in, header, what) || !check_ply_header(header, what))
        return false;
    const std::string announced = "its header announces "
        + std::to_string(header.element("vertex")->count) + " vertices and "
        + std::to_string(header.element("face")->count) + " faces";
    if (header.format != PlyHeader::Format::Ascii
        && !binary_size_suffices(path, header, announced, what))
        return false;

    PlyValues values(in, header.format, header.lines + 1);
    PlyRecordReader reader(values, record);
    for (const PlyElement& element : header.elements)
        if (!reader.read_element(element, what)) {
            if (values.truncated())
                what = "is truncated: " + announced + ", but the data stops before their end";
            return false;
        }
    if (!values.complete()) {
        what = "is truncated: " + announced + ", but the data stops before their end";
        return false;
    }
    return true;
}

} // namespace texsyn::detail
