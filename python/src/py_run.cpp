// SPDX-License-Identifier: Apache-2.0
#include "py_run.h"

#include <chrono>
#include <exception>
#include <set>
#include <stdexcept>
#include <thread>

#include <texsyn/memory.h>
#include <texsyn/methods.h>

#include "py_errors.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

// Keyword `k`'s integer `value` (an int or an integer like numpy's, not a bool) in
// [lo, hi]; ValueError otherwise.
int64_t int_keyword(const std::string& k, py::handle value, int64_t lo, int64_t hi)
{
    if (PyIndex_Check(value.ptr()) && !py::isinstance<py::bool_>(value)) {
        const long long v = PyLong_AsLongLong(
            py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())).ptr());
        if (!PyErr_Occurred() && v >= lo && v <= hi)
            return v;
        PyErr_Clear();
    }
    raise_error(ErrorKind::Value,
        k + "=" + py::repr(value).cast<std::string>() + " : expected an integer in "
            + std::to_string(lo) + ".." + std::to_string(hi));
}

// The runs in progress (RunControl::run), for stop_runs_at_exit.
struct ActiveRuns {
    std::mutex mutex;
    std::condition_variable ended;
    std::set<RunControl*> runs;
    std::atomic<bool> finalizing { false }; ///< stop_runs_at_exit ran
};

ActiveRuns& active_runs()
{
    static ActiveRuns* runs = new ActiveRuns; // never destroyed: threads may outlive exit()
    return *runs;
}

// A run in the registry while it lives.
class Registration {
public:
    explicit Registration(RunControl* run)
        : m_run(run)
    {
        std::lock_guard<std::mutex> lock(active_runs().mutex);
        active_runs().runs.insert(run);
    }
    ~Registration()
    {
        std::lock_guard<std::mutex> lock(active_runs().mutex);
        active_runs().runs.erase(m_run);
        active_runs().ended.notify_all();
    }
    Registration(const Registration&) = delete;
    Registration& operator=(const Registration&) = delete;

private:
    RunControl* m_run;
};

bool finalizing()
{
    return active_runs().finalizing || _Py_IsFinalizing();
}

} // namespace

ReleaseGil::ReleaseGil()
    : m_state(PyEval_SaveThread())
{ }

ReleaseGil::~ReleaseGil()
{
    while (finalizing()) // the process is ending: never return into Python
        std::this_thread::sleep_for(std::chrono::hours(1));
    PyEval_RestoreThread(m_state);
}

void stop_runs_at_exit()
{
    ActiveRuns& a = active_runs();
    a.finalizing = true;
    py::gil_scoped_release release; // the runs may be taking it to look at Python
    std::unique_lock<std::mutex> lock(a.mutex);
    for (RunControl* run : a.runs)
        run->request_stop();
    a.ended.wait_for(lock, std::chrono::minutes(1), [&] { return a.runs.empty(); });
}

uint64_t seed_keyword(py::handle value)
{
    return uint64_t(int_keyword("seed", value, 0, max_seed));
}

int threads_keyword(py::handle value)
{
    return int(int_keyword("threads", value, 0, max_threads));
}

size_t memory_keyword(py::handle value)
{
    if (value.is_none())
        return 0;
    if (py::isinstance<py::str>(value)) {
        size_t bytes = 0;
        std::string error;
        if (!parse_memory_size(value.cast<std::string>(), bytes, error))
            raise_error(ErrorKind::Value,
                "max_memory=" + py::repr(value).cast<std::string>() + " : " + error);
        return bytes;
    }
    return size_t(int_keyword("max_memory", value, 1, int64_t(1) << 60));
}

RunControl::RunControl(py::object callback)
    : m_callback(callback.is_none() ? py::object() : std::move(callback))
{
    if (m_callback && !PyCallable_Check(m_callback.ptr()))
        throw py::type_error("progress= : expected a callable taking the fraction done, or None");
}

RunControl::~RunControl()
{
    // error_already_set and the callback hold Python references: drop them with the GIL.
    if (m_stopped || m_callback) {
        py::gil_scoped_acquire gil;
        m_stopped.reset();
        m_callback = py::object();
    }
}

std::function<void(float)> RunControl::progress()
{
    return [this](float fraction) {
        m_progressed = true;
        const auto now = std::chrono::steady_clock::now();
        if (fraction < 1.0f && m_handed && now - m_handed_at < python_interval)
            return;
        m_handed = true;
        m_handed_at = now;
        std::unique_lock<std::mutex> lock(m_mutex);
        m_step = fraction;
        m_step_pending = true;
        m_wake.notify_all();
        m_wake.wait(lock, [this] { return !m_step_pending || m_stop; });
    };
}

void RunControl::request_stop()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
    m_wake.notify_all();
}

void RunControl::look_at_python(bool step, float fraction)
{
    if (m_stop || finalizing())
        return; // stopped, or Python is ending: nothing more is asked of it
    py::gil_scoped_acquire gil;
    try {
        if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
        if (step && m_callback)
            m_callback(fraction);
    } catch (py::error_already_set& e) {
        m_stopped = std::make_unique<py::error_already_set>(std::move(e));
        m_stop = true;
    }
}

bool RunControl::run(const std::function<bool()>& work)
{
    bool ok = false;
    std::exception_ptr failure;
    std::thread worker([&] {
        try {
            ok = work();
        } catch (...) {
            failure = std::current_exception();
        }
        std::lock_guard<std::mutex> lock(m_mutex);
        m_done = true;
        m_wake.notify_all();
    });
    try {
        ReleaseGil release;
        // Out of the registry (after the worker's join below) before the GIL is taken back.
        const Registration registered(this);
        std::unique_lock<std::mutex> lock(m_mutex);
        while (!m_done) {
            m_wake.wait_for(lock, python_interval, [this] { return m_done || m_step_pending; });
            if (m_done)
                break;
            const bool step = m_step_pending;
            const float fraction = m_step;
            lock.unlock();
            look_at_python(step, fraction);
            lock.lock();
            if (step) {
                m_step_pending = false;
                m_wake.notify_all();
            }
        }
        lock.unlock();
        worker.join();
    } catch (...) { // (taking the GIL or a lock failed) the run must not outlive this frame
        request_stop();
        if (worker.joinable()) {
            ReleaseGil release;
            worker.join();
        }
        throw;
    }
    if (failure)
        std::rethrow_exception(failure);
    return ok;
}

void RunControl::raise_if_stopped()
{
    if (!m_stopped)
        return;
    py::error_already_set e = std::move(*m_stopped);
    m_stopped.reset();
    throw e;
}

} // namespace texsyn::python
