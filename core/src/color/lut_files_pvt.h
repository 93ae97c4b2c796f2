// SPDX-License-Identifier: Apache-2.0
// The LUT files an OCIO config names.
#pragma once

#include <string>

#include <OpenColorIO/OpenColorIO.h>

namespace texsyn::detail {

/// Checks that every file a FileTransform of `config` names (in its colour spaces, looks,
/// view transforms and named transforms, groups included) that resolves on the config's
/// search path is a regular file: OCIO would block for ever reading a FIFO or /dev/zero.
/// Files that do not resolve are left to OCIO, which reports them when they are used.
/// On failure, `error` names the LUT and says what it is.
bool check_lut_files(const OCIO_NAMESPACE::ConstConfigRcPtr& config, std::string& error);

} // namespace texsyn::detail
