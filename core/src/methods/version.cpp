// SPDX-License-Identifier: Apache-2.0
#include <texsyn/version.h>

namespace texsyn {

const char* version()
{
    return TEXSYN_VERSION_STRING;
}

} // namespace texsyn
