// SPDX-License-Identifier: Apache-2.0
// texsyn: an oiiotool-style command line over libtexsyn. Parsing and dispatch only: every
// command is a row of the method registry (texsyn/methods.h).
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include "cli_error.h"
#include "command_line.h"
#include "commands.h"
#include "quiet_stderr.h"

#include <texsyn/error_text.h>
#include <texsyn/io.h>
#include <texsyn/memory.h>
#include <texsyn/options.h>

namespace texsyn::cli {

namespace {

// Does args[i] (and the arguments it takes), as check_command_line has checked it; returns
// the index of its last argument.
size_t run_argument(CliState& state, const std::vector<std::string>& args, size_t i)
{
    const std::string& a = args[i];
    if (takes_argument(a)) {
        const std::string& v = args[++i];
        if (a == "-o")
            write_output(state, v);
        else if (a == "--recipe")
            write_recipe(state, v);
        else if (a == "--iscolorspace") {
            if (state.stack.empty())
                state.pending_iscolorspace = v;
            else
                reinterpret_input(state, v);
        } else if (a == "--tocolorspace") {
            if (state.stack.empty())
                state.pending_tocolorspace = v;
            else
                state.stack.top(a).output_colorspace = v;
        }
    } else if (is_apply_map(a)) {
        run_apply_map(state, a, args[i + 1], args[i + 2]);
        i += 2;
    } else if (is_flag(a)) {
        return i;
    } else if (!a.empty() && a[0] == '-') {
        const auto [command, modifiers] = split_command(a);
        run_method_command(state, *find_method(command.substr(2)), state.options.at(i), modifiers);
    } else {
        push_input(state, a);
    }
    return i;
}

// The second pass: does what check_command_line has checked, left to right. Memory that
// runs out despite the estimates (an address-space limit, other processes) is reported
// against the argument that needed it.
void run(CliState& state, const std::vector<std::string>& args)
{
    for (size_t i = 0; i < args.size(); ++i) {
        try {
            i = run_argument(state, args, i);
        } catch (const std::bad_alloc&) {
            throw CliError(args[i]
                + " : not enough memory (a memory or address-space limit "
                  "was reached: try a smaller size or raise the limit)");
        }
    }
}

// Throws unless everything printed to stdout (help, reports) reached it: a full disk or a
// closed pipe must not end in success.
void check_stdout()
{
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        throw CliError(std::string("standard output: write error")
            + (errno ? " (" + std::string(std::strerror(errno)) + ")" : ""));
}

// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE: remove every temporary output file and end
// at once with 128 + the signal's number (130 for Ctrl-C, 143 for SIGTERM).
extern "C" void end_on_signal(int sig)
{
    texsyn::remove_live_temporaries();
    ::_exit(128 + sig);
}

// A library calling exit() (libjpeg on a write error) still reports its cause and leaves
// no temporary file.
void end_on_exit()
{
    QuietStderr::report_exit();
    texsyn::remove_live_temporaries();
}

void install_handlers()
{
    struct sigaction sa { };
    sa.sa_handler = end_on_signal;
    sigemptyset(&sa.sa_mask);
    // A signal ignored by whoever started texsyn (SIGINT and SIGQUIT for a background job
    // of a non-interactive shell, SIGHUP under nohup) stays ignored, as the shell meant.
    for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE }) {
        struct sigaction inherited { };
        if (::sigaction(sig, nullptr, &inherited) == 0 && inherited.sa_handler == SIG_IGN)
            continue;
        ::sigaction(sig, &sa, nullptr);
    }
    // Past a file-size limit (ulimit -f) a write fails with EFBIG, reported like a full
    // disk, instead of killing the process with its files half-written.
    std::signal(SIGXFSZ, SIG_IGN);
    std::atexit(end_on_exit);
}

} // namespace

} // namespace texsyn::cli

int main(int argc, char* argv[])
{
    using namespace texsyn::cli;
    std::vector<std::string> args(argv + 1, argv + argc);
    install_handlers();
    CliState state;
    state.command_line = OIIO::Strutil::join(std::vector<std::string>(argv, argv + argc), " ");
    try {
        if (args.empty()) {
            print_help();
            return 1;
        }
        if (check_command_line(state, args) == Early::Exit) {
            check_stdout();
            return 0;
        }
        state.progress = progress_mode(state.verbose, ::isatty(STDERR_FILENO));
        if (std::string error; !progress_interval(
                std::getenv("TEXSYN_PROGRESS_INTERVAL"), state.progress_interval, error))
            throw CliError(error);
        texsyn::set_memory_limit(state.max_memory);
        if (state.threads > 0)
            OIIO::attribute("threads", state.threads);
        run(state, args);
        check_stdout();
        state.outputs.commit();
    } catch (const std::exception& e) {
        state.outputs.discard();
        std::fprintf(stderr, "texsyn ERROR: %s\n", texsyn::readable_message(e.what()).c_str());
        return 1;
    }
    return 0;
}
