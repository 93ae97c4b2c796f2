// SPDX-License-Identifier: Apache-2.0
// Silences stderr for a scope: image libraries (libpng, libtiff) print their own
// diagnostics before OIIO reports the error, and the tool states each error once, on one
// line. What they print is kept, not thrown away: a library that ends the process inside
// the scope (libjpeg calls exit() on a write error) still gets its cause reported.
#pragma once

#include <string>

namespace texsyn::cli {

class QuietStderr {
public:
    /// Silences stderr until destruction. `context` ("-o out.jpg") starts the error line
    /// printed if the process exits before then.
    explicit QuietStderr(std::string context);
    ~QuietStderr();
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

    /// For std::atexit, once: if the process is ending inside a QuietStderr scope, restores
    /// stderr and prints "texsyn ERROR: CONTEXT : what the library printed".
    static void report_exit();

private:
    std::string m_context;
    int m_saved = -1;    ///< the real stderr
    int m_captured = -1; ///< an anonymous file receiving stderr meanwhile
};

} // namespace texsyn::cli
