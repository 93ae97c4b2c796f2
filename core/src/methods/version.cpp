// SPDX-License-Identifier: Apache-2.0
#include <texsyn/version.h>

namespace texsyn {

const char* version()
{
    return TEXSYN_VERSION_STRING;
}

int version_number()
{
    return TEXSYN_VERSION;
}

std::string gpl_components()
{
    std::string names;
#ifdef TEXSYN_HAVE_FFTW
    names += "FFTW";
#endif
#ifdef TEXSYN_HAVE_CGAL
    names += names.empty() ? "CGAL" : ", CGAL";
#endif
    return names;
}

} // namespace texsyn
