// SPDX-License-Identifier: Apache-2.0
#include "quiet_stderr.h"

#include <cstdio>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

namespace texsyn::cli {

namespace {

QuietStderr* active = nullptr; // the tool is single-threaded where it silences stderr

} // namespace

QuietStderr::QuietStderr(std::string context)
    : m_context(std::move(context))
{
    std::fflush(stderr);
    m_saved = ::dup(STDERR_FILENO);
    m_captured = ::memfd_create("texsyn-stderr", MFD_CLOEXEC);
    if (m_saved >= 0 && m_captured >= 0) {
        ::dup2(m_captured, STDERR_FILENO);
        active = this;
    }
}

QuietStderr::~QuietStderr()
{
    std::fflush(stderr);
    if (active == this) {
        ::dup2(m_saved, STDERR_FILENO);
        active = nullptr;
    }
    if (m_saved >= 0)
        ::close(m_saved);
    if (m_captured >= 0)
        ::close(m_captured);
}

void QuietStderr::report_exit()
{
    QuietStderr* q = active;
    if (!q)
        return;
    active = nullptr;
    std::fflush(stderr);
    ::dup2(q->m_saved, STDERR_FILENO);
    // The library's own words, on one line.
    std::string said;
    char buf[512];
    ::lseek(q->m_captured, 0, SEEK_SET);
    for (ssize_t n; said.size() < 400 && (n = ::read(q->m_captured, buf, sizeof(buf))) > 0;)
        said.append(buf, size_t(n));
    for (char& c : said)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!said.empty() && said.back() == ' ')
        said.pop_back();
    if (said.empty())
        said = "an image library ended the process";
    std::fprintf(stderr, "texsyn ERROR: %s : %s\n", q->m_context.c_str(), said.c_str());
    std::fflush(stderr);
}

} // namespace texsyn::cli
