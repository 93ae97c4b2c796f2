// SPDX-License-Identifier: Apache-2.0
// Library work run from Python: its seed= and threads=, run without the GIL, with progress
// reported to a Python callable, and stopped by Ctrl-C.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>

#include <pybind11/pybind11.h>

#include "py_errors.h"

namespace texsyn::python {

/// seed= as --seed takes it: an integer in 0..max_seed (methods.h); ValueError otherwise.
uint64_t seed_keyword(pybind11::handle value);

/// threads= as --threads takes it: an integer in 0..max_threads (0 = all cores);
/// ValueError otherwise.
int threads_keyword(pybind11::handle value);

/// One run's link to Python. Construct with the GIL held; call progress() from the thread
/// that made it, without the GIL (RunSettings::progress).
class RunControl {
public:
    /// `callback`: None, or a callable taking the fraction done (0..1).
    explicit RunControl(pybind11::object callback);
    ~RunControl();
    RunControl(const RunControl&) = delete;
    RunControl& operator=(const RunControl&) = delete;

    /// How often, at most, progress() takes the GIL (besides the last step, 1.0).
    static constexpr std::chrono::milliseconds python_interval { 50 };

    /// The RunSettings::progress of the run: at most every python_interval, and at the
    /// end, takes the GIL, runs Python's signal handlers (Ctrl-C raises KeyboardInterrupt
    /// there) and the callback; if either raises, keeps that exception and throws to stop
    /// the run.
    std::function<void(float)> progress();

    /// With the GIL held, after a run: re-raises the Python exception that stopped it, if
    /// one did (else returns).
    void raise_if_stopped();

    /// What a failed run's message becomes: ValueError if the run was refused before it
    /// reported any progress (a memory estimate beyond the limit, options that cannot apply
    /// to these inputs: methods check before they work), else RuntimeError.
    ErrorKind failure_kind() const { return m_progressed ? ErrorKind::Runtime : ErrorKind::Value; }

private:
    pybind11::object m_callback;
    std::unique_ptr<pybind11::error_already_set> m_stopped;
    bool m_progressed = false;                     ///< progress() was called (on the run's thread)
    std::chrono::steady_clock::time_point m_asked; ///< when progress() last took the GIL
};

} // namespace texsyn::python
