// SPDX-License-Identifier: Apache-2.0
// The LUT files an OCIO config names.
#pragma once

#include <cstdint>
#include <string>

#include <OpenColorIO/OpenColorIO.h>

namespace texsyn::detail {

/// The largest LUT file a config may name: a 65^3 3-D LUT as text is about 10 MB.
inline constexpr uintmax_t max_lut_file_bytes = uintmax_t(128) << 20;

/// Checks that every file a FileTransform of `config` names (in its colour spaces, looks,
/// view transforms and named transforms, groups included) that resolves on the config's
/// search path is a regular file of at most max_lut_file_bytes: OCIO would block for ever
/// reading a FIFO or /dev/zero, and take minutes over a file of gigabytes.
/// Files that do not resolve are left to OCIO, which reports them when they are used.
/// On failure, `error` names the LUT and says what it is.
bool check_lut_files(const OCIO_NAMESPACE::ConstConfigRcPtr& config, std::string& error);

} // namespace texsyn::detail
