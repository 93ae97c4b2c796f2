// SPDX-License-Identifier: Apache-2.0
// Silences stderr for a scope: image libraries (libpng, libtiff) print their own
// diagnostics before OIIO reports the error, and the tool states each error once, on one
// line.
#pragma once

#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace texsyn::cli {

class QuietStderr {
public:
    QuietStderr()
    {
        std::fflush(stderr);
        m_saved = ::dup(STDERR_FILENO);
        int devnull = ::open("/dev/null", O_WRONLY);
        if (m_saved >= 0 && devnull >= 0)
            ::dup2(devnull, STDERR_FILENO);
        if (devnull >= 0)
            ::close(devnull);
    }
    ~QuietStderr()
    {
        std::fflush(stderr);
        if (m_saved >= 0) {
            ::dup2(m_saved, STDERR_FILENO);
            ::close(m_saved);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

private:
    int m_saved = -1;
};

} // namespace texsyn::cli
