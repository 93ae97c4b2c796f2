// SPDX-License-Identifier: Apache-2.0
// texsyn's version.
#pragma once

namespace texsyn {

/// texsyn's version string, e.g. "0.1.0" (synth:version in every output).
const char* version();

} // namespace texsyn
