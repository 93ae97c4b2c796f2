// SPDX-License-Identifier: Apache-2.0
#include "py_run.h"

#include <chrono>
#include <stdexcept>

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

} // namespace

uint64_t seed_keyword(py::handle value)
{
    return uint64_t(int_keyword("seed", value, 0, max_seed));
}

int threads_keyword(py::handle value)
{
    return int(int_keyword("threads", value, 0, max_threads));
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
        if (m_stopped)
            throw std::runtime_error("stopped");
        // Taking the GIL waits for the Python thread that holds it to let go (up to the
        // interpreter's switch interval, 5 ms): a busy thread beside a run of many short
        // steps would slow it several times over. Python is asked at most every
        // python_interval, and at the end.
        const auto now = std::chrono::steady_clock::now();
        if (fraction < 1.0f && now - m_asked < python_interval)
            return;
        m_asked = now;
        py::gil_scoped_acquire gil;
        try {
            if (PyErr_CheckSignals() != 0)
                throw py::error_already_set();
            if (m_callback)
                m_callback(fraction);
        } catch (py::error_already_set& e) {
            m_stopped = std::make_unique<py::error_already_set>(std::move(e));
            throw std::runtime_error("stopped from Python");
        }
    };
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
