// SPDX-License-Identifier: Apache-2.0
// What the OBJ and PLY readers share: lines of bounded length, and their messages' pieces.
#include <cerrno>
#include <cstring>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

std::string cannot_open_mesh()
{
    return std::string("cannot be opened (") + std::strerror(errno) + ")";
}

std::string at_line(uint64_t number, std::string line)
{
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
        line.pop_back();
    std::string text = line.substr(0, 48);
    if (text.size() < line.size())
        text += "...";
    return "line " + std::to_string(number) + ": '" + text + "': ";
}

LineRead read_mesh_line(std::istream& in, std::string& line)
{
    line.clear();
    std::istream::sentry ok(in, true);
    if (!ok)
        return LineRead::End;
    std::streambuf* buffer = in.rdbuf();
    for (;;) {
        const int c = buffer->sbumpc();
        if (c == std::char_traits<char>::eof()) {
            in.setstate(std::ios::eofbit);
            return line.empty() ? LineRead::End : LineRead::Unterminated;
        }
        if (c == '\n')
            return LineRead::Line;
        if (line.size() >= kMaxMeshLineBytes)
            return LineRead::TooLong;
        line.push_back(char(c));
    }
}

std::string line_too_long(uint64_t number, const std::string& line, const char* kind)
{
    return at_line(number, line) + "longer than " + std::to_string(kMaxMeshLineBytes >> 20)
        + " MiB (not " + kind + "?)";
}

bool too_many_mesh_elements(uint64_t count, const std::string& what_counted, std::string& what)
{
    if (count <= kMaxMeshElements)
        return false;
    what = "has more than " + std::to_string(kMaxMeshElements) + " " + what_counted
        + " (texsyn's limit for one surface)";
    return true;
}

} // namespace texsyn::detail
