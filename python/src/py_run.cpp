// SPDX-License-Identifier: Apache-2.0
#include "py_run.h"

#include <stdexcept>

namespace py = pybind11;

namespace texsyn::python {

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
        py::gil_scoped_acquire gil;
        if (m_stopped)
            throw std::runtime_error("stopped");
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
