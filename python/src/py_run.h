// SPDX-License-Identifier: Apache-2.0
// Library work run from Python: its seed= and threads=, run on a thread of its own without
// the GIL, with progress reported to a Python callable and stopped by Ctrl-C.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>

#include <pybind11/pybind11.h>

#include <texsyn/stop.h>

#include "py_errors.h"

namespace texsyn::python {

/// seed= as --seed takes it: an integer in 0..max_seed (methods.h); ValueError otherwise.
uint64_t seed_keyword(pybind11::handle value);

/// threads= as --threads takes it: an integer in 0..max_threads (0 = all cores);
/// ValueError otherwise.
int threads_keyword(pybind11::handle value);

/// max_memory= (RunSettings::max_memory): None (the process-wide limit), bytes as an
/// integer, or a size as --max-memory takes it ("2G", "512M", "25%"); ValueError otherwise.
size_t memory_keyword(pybind11::handle value);

/// Releases the GIL for library work, like pybind11's gil_scoped_release, but never takes
/// it back while the interpreter is finalizing: a thread that did (a daemon thread still in
/// texsyn when Python exits) would be ended by pthread_exit inside a destructor, which ends
/// the process with std::terminate. Such a thread waits instead until the process exits.
class ReleaseGil {
public:
    ReleaseGil();
    ~ReleaseGil();
    ReleaseGil(const ReleaseGil&) = delete;
    ReleaseGil& operator=(const ReleaseGil&) = delete;

private:
    PyThreadState* m_state;
};

/// Registered with Python's atexit at import: stops every run in progress (as Ctrl-C
/// would) and waits, without the GIL, until each has ended (they end within about a second;
/// at most a minute), so that no library work outlives the interpreter. From then on
/// ReleaseGil never takes the GIL back.
void stop_runs_at_exit();

/// One run's link to Python. Construct with the GIL held, give the run progress() and
/// stop() (RunSettings), and start it with run().
class RunControl {
public:
    /// `callback`: None, or a callable taking the fraction done (0..1).
    explicit RunControl(pybind11::object callback);
    ~RunControl();
    RunControl(const RunControl&) = delete;
    RunControl& operator=(const RunControl&) = delete;

    /// How often the calling thread looks at Python while a run works: it runs Python's
    /// signal handlers (Ctrl-C raises KeyboardInterrupt there) this often, and hands the
    /// callback a step at most this often (besides the first and the last).
    static constexpr std::chrono::milliseconds python_interval { 50 };

    /// Runs `work` (library calls with progress() and stop(), no Python) on a thread of
    /// its own while the calling thread releases the GIL and looks at Python every
    /// python_interval. If a signal handler or the callback raises, keeps that exception
    /// and sets stop(): the library then ends the run within about a second. Call with
    /// the GIL held; returns work's result (a C++ exception from it is rethrown here),
    /// then raise_if_stopped().
    bool run(const std::function<bool()>& work);

    /// The run's RunSettings::progress: records the fraction done; at the first step, then
    /// at most every python_interval, and at the end (1.0), waits for the calling thread
    /// to give it to the callback, as a synchronous call would.
    std::function<void(float)> progress();

    /// The run's RunSettings::stop: set once Python raised.
    const StopFlag* stop() const { return &m_stop; }

    /// With the GIL held, after a run: re-raises the Python exception that stopped it, if
    /// one did (else returns).
    void raise_if_stopped();

    /// From any thread: stops the run (stop_runs_at_exit).
    void request_stop();

    /// What a failed run's message becomes: ValueError if the run was refused before it
    /// reported any progress (a memory estimate beyond the limit, options that cannot apply
    /// to these inputs: methods check before they work), else RuntimeError.
    ErrorKind failure_kind() const { return m_progressed ? ErrorKind::Runtime : ErrorKind::Value; }

private:
    // With the GIL released, on the calling thread: takes it, runs the signal handlers and,
    // for a step, the callback; an exception sets m_stop.
    void look_at_python(bool step, float fraction);

    pybind11::object m_callback;
    std::unique_ptr<pybind11::error_already_set> m_stopped;
    StopFlag m_stop { false };
    std::atomic<bool> m_progressed { false }; ///< progress() was called

    // The hand-over of a step from the run's thread to the calling thread.
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_done = false;         ///< the run's thread has finished
    bool m_step_pending = false; ///< m_step waits for the callback
    float m_step = 0.0f;
    // The run's thread's own: when it last handed a step over.
    bool m_handed = false;
    std::chrono::steady_clock::time_point m_handed_at;
};

} // namespace texsyn::python
