// SPDX-License-Identifier: Apache-2.0
// Progress lines for terminals and farm logs (progress_meter.h).
#include "progress_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace texsyn::cli {

ProgressMode progress_mode(bool verbose, bool terminal)
{
    return terminal ? ProgressMode::Live : verbose ? ProgressMode::Lines : ProgressMode::Off;
}

bool progress_interval(const char* env, double& seconds, std::string& error)
{
    seconds = 5.0;
    if (!env)
        return true;
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end == env || *end != '\0' || !(v >= 0.01 && v <= 3600.0)) {
        error = std::string("TEXSYN_PROGRESS_INTERVAL=") + env
            + " : expected seconds between progress lines, 0.01..3600";
        return false;
    }
    seconds = v;
    return true;
}

std::string format_duration(double seconds)
{
    const long s = seconds > 0 ? long(std::floor(seconds)) : 0;
    char text[32];
    if (s < 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    return text;
}

ProgressMeter::ProgressMeter(std::string command, ProgressMode mode, double interval)
    : m_command(std::move(command))
    , m_mode(mode)
    , m_interval(interval)
{ }

std::string ProgressMeter::line(float fraction, double elapsed) const
{
    const int percent = int(std::lround(std::clamp(fraction, 0.0f, 1.0f) * 100.0f));
    // The rate so far; nothing done yet gives no estimate.
    const std::string eta = fraction > 0.0f
        ? format_duration(elapsed * double(1.0f - std::min(fraction, 1.0f)) / double(fraction))
        : "-:--";
    char text[64];
    std::snprintf(text, sizeof text, "%3d%%", percent);
    return "texsyn: " + m_command + " " + text + " elapsed " + format_duration(elapsed) + " eta "
        + eta;
}

std::string ProgressMeter::start()
{
    return m_mode == ProgressMode::Live ? update(0.0f, 0.0) : "";
}

std::string ProgressMeter::update(float fraction, double elapsed)
{
    std::string text = line(fraction, elapsed);
    if (m_mode == ProgressMode::Live) {
        m_shown = std::max(m_shown, text.size());
        return "\r" + text + std::string(m_shown - text.size(), ' ');
    }
    const bool done = fraction >= 1.0f;
    if ((done && m_ended) || (!done && elapsed - m_last < m_interval))
        return "";
    m_last = elapsed;
    m_ended = m_ended || done;
    return text + "\n";
}

std::string ProgressMeter::finish(bool ok, double elapsed)
{
    if (m_mode == ProgressMode::Live)
        return (ok ? update(1.0f, elapsed) : "") + "\n";
    return ok && !m_ended ? update(1.0f, elapsed) : "";
}

} // namespace texsyn::cli
