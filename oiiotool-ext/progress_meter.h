// SPDX-License-Identifier: Apache-2.0
// What a long command says about its progress on stderr: on a terminal one live line,
// rewritten in place; in a farm log (-v, stderr not a terminal) a line every few seconds
// and one at 100%. Pure text: the caller passes the time and prints what it gets.
#pragma once

#include <string>

namespace texsyn::cli {

/// How progress is shown: not at all (a pipeline), a live line, or periodic lines.
enum class ProgressMode { Off, Live, Lines };

/// The mode for a run: Live on a terminal, Lines with -v elsewhere, else Off.
ProgressMode progress_mode(bool verbose, bool terminal);

/// Seconds between two periodic lines: 5, or `env` ($TEXSYN_PROGRESS_INTERVAL) when it is
/// not null. False with a one-line message if `env` is not a number of seconds in
/// 0.01..3600.
bool progress_interval(const char* env, double& seconds, std::string& error);

/// "m:ss", or "h:mm:ss" from an hour on; seconds rounded down, negatives shown as 0:00.
std::string format_duration(double seconds);

/// The progress of one command (e.g. "--pyramid") in Live or Lines mode. Each call returns
/// the text to print (maybe ""); lines read
/// "texsyn: --pyramid  42% elapsed 0:12 eta 0:17", where eta assumes the rate so far and
/// is "-:--" before anything is done.
class ProgressMeter {
public:
    ProgressMeter(std::string command, ProgressMode mode, double interval);
    /// When the command starts: Live, the line at 0%; Lines, nothing.
    std::string start();
    /// After `fraction` (0..1) of the work took `elapsed` seconds. Live: the line, rewritten.
    /// Lines: a line when `interval` seconds have passed since the last one (or the start),
    /// and once at 100%.
    std::string update(float fraction, double elapsed);
    /// When the command ends after `elapsed` seconds. `ok`: the 100% line unless Lines mode
    /// printed it already; Live also ends its line with a newline either way.
    std::string finish(bool ok, double elapsed);

private:
    std::string line(float fraction, double elapsed) const;

    std::string m_command;
    ProgressMode m_mode;
    double m_interval;
    double m_last = 0.0;  ///< when Lines mode printed last
    bool m_ended = false; ///< the 100% line was printed
    size_t m_shown = 0;   ///< Live: the longest line so far, to blank a shorter one
};

} // namespace texsyn::cli
