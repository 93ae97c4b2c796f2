// SPDX-License-Identifier: Apache-2.0
// PLY headers (Turk's format as MeshLab, Blender and OpenMesh write it). Only the header:
// ply_read.cpp reads the data.
#include <iterator>
#include <sstream>

#include "mesh_detail_pvt.h"

namespace texsyn::detail {

namespace {

// PLY's scalar types, in PlyType's order.
const PlyTypeTraits kPlyTypes[] = {
    { "char", "int8", 1, true, -128.0, 127.0 },
    { "uchar", "uint8", 1, true, 0.0, 255.0 },
    { "short", "int16", 2, true, -32768.0, 32767.0 },
    { "ushort", "uint16", 2, true, 0.0, 65535.0 },
    { "int", "int32", 4, true, -2147483648.0, 2147483647.0 },
    { "uint", "uint32", 4, true, 0.0, 4294967295.0 },
    { "float", "float32", 4, false, -3.4e38, 3.4e38 },
    { "double", "float64", 8, false, -3.4e38, 3.4e38 },
};

// A PLY scalar type's name (either spelling) as its type and its bytes, or 0 bytes.
int ply_type(const std::string& name, PlyType& type)
{
    for (size_t t = 0; t < std::size(kPlyTypes); ++t)
        if (name == kPlyTypes[t].name || name == kPlyTypes[t].alias) {
            type = PlyType(t);
            return kPlyTypes[t].size;
        }
    return 0;
}

// A header longer than this is not a PLY header (a binary file that starts with "ply").
constexpr uint64_t kMaxHeaderBytes = 1 << 20;

} // namespace

const PlyTypeTraits& ply_type_traits(PlyType type)
{
    return kPlyTypes[size_t(type)];
}

const PlyElement* PlyHeader::element(const std::string& name) const
{
    for (const PlyElement& e : elements)
        if (e.name == name)
            return &e;
    return nullptr;
}

bool read_ply_header(std::istream& in, PlyHeader& header, std::string& reason)
{
    header = PlyHeader();
    std::string line;
    bool have_format = false;
    for (int number = 1;; ++number) {
        const LineRead read = read_mesh_line(in, line);
        if (read == LineRead::End || read == LineRead::Unterminated) {
            reason = "the PLY header has no end_header line";
            return false;
        }
        if (read == LineRead::TooLong) {
            reason = "the PLY header is longer than 1 MiB";
            return false;
        }
        header.bytes += line.size() + 1;
        if (header.bytes > kMaxHeaderBytes) {
            reason = "the PLY header is longer than 1 MiB";
            return false;
        }
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (number == 1) {
            if (keyword != "ply" || words >> keyword) {
                reason = "not a PLY file (it does not start with a 'ply' line)";
                return false;
            }
            continue;
        }
        if (keyword == "end_header") {
            header.lines = uint64_t(number);
            break;
        }
        if (keyword == "comment" || keyword == "obj_info") {
            const size_t at = line.find_first_not_of(" \t", keyword.size());
            header.comments.push_back(at == std::string::npos ? "" : line.substr(at));
            continue;
        }
        if (keyword == "format") {
            std::string format, version;
            words >> format >> version;
            if (format == "ascii")
                header.format = PlyHeader::Format::Ascii;
            else if (format == "binary_little_endian")
                header.format = PlyHeader::Format::BinaryLittleEndian;
            else if (format == "binary_big_endian")
                header.format = PlyHeader::Format::BinaryBigEndian;
            else {
                reason = "unknown PLY format '" + format + "' on header line "
                    + std::to_string(number);
                return false;
            }
            have_format = true;
        } else if (keyword == "element") {
            PlyElement element;
            long long count = -1;
            words >> element.name >> count;
            if (!words || count < 0) {
                reason = "header line " + std::to_string(number)
                    + ": an element needs a name and a count";
                return false;
            }
            if (header.element(element.name)) {
                reason = "header line " + std::to_string(number) + ": a second element '"
                    + element.name + "'";
                return false;
            }
            element.count = uint64_t(count);
            header.elements.push_back(element);
        } else if (keyword == "property") {
            PlyProperty property;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string count_type;
                words >> count_type >> type;
                property.count_size = ply_type(count_type, property.count_type);
                if (property.count_size == 0 || property.count_type == PlyType::Float32
                    || property.count_type == PlyType::Float64) {
                    reason = "header line " + std::to_string(number) + ": list count type '"
                        + count_type + "' is not an integer type";
                    return false;
                }
            }
            property.size = ply_type(type, property.type);
            words >> property.name;
            if (property.size == 0 || property.name.empty() || header.elements.empty()) {
                reason = "header line " + std::to_string(number) + ": '" + line
                    + "' is not a property of an element";
                return false;
            }
            header.elements.back().properties.push_back(property);
        } else {
            reason
                = "header line " + std::to_string(number) + ": unknown keyword '" + keyword + "'";
            return false;
        }
    }
    if (!have_format) {
        reason = "the PLY header has no format line";
        return false;
    }
    return true;
}

} // namespace texsyn::detail
