// SPDX-License-Identifier: Apache-2.0
// The state of one `texsyn` run: the global options, the stack and the outputs.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <OpenImageIO/typedesc.h>

#include <texsyn/color.h>
#include <texsyn/methods.h>

#include "output_transaction.h"
#include "progress_meter.h"
#include "stack.h"

namespace texsyn::cli {

struct CliState {
    // Global options.
    uint64_t seed = 0;
    int threads = 0;
    size_t max_memory = 0; ///< --max-memory in bytes; 0 = the default limit
    bool verbose = false;
    bool subbands = false;
    ProgressMode progress = ProgressMode::Off; ///< progress_mode(-v, stderr is a terminal)
    double progress_interval = 5.0;            ///< Lines mode: seconds between lines
    std::string colorconfig_path;
    std::string pending_iscolorspace; ///< --iscolorspace seen before any input
    std::string pending_tocolorspace; ///< --tocolorspace seen before any image
    OIIO::TypeDesc data_format;       ///< -d: output pixel type; unknown = the default
    std::string command_line;

    Stack stack;
    OutputTransaction outputs;
    /// Each command's options as the check pass parsed them, by argument index.
    std::map<size_t, MethodOptions> options;

    /// The colour config, loaded on first use (so --colorconfig anywhere before the first
    /// input counts).
    const ColorConfig& colors();

private:
    std::unique_ptr<ColorConfig> m_colors;
};

} // namespace texsyn::cli
