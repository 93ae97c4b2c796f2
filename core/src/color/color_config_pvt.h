// SPDX-License-Identifier: Apache-2.0
// What a ColorConfig holds, shared by the files that implement it.
#pragma once

#include <string>

#include <OpenColorIO/OpenColorIO.h>

#include <texsyn/color.h>

namespace texsyn {

struct ColorConfig::Impl {
    OCIO_NAMESPACE::ConstConfigRcPtr config;
    std::string source;
    std::string origin;
    bool bundled = false;
};

} // namespace texsyn
