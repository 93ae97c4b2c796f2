// SPDX-License-Identifier: Apache-2.0
#include "py_errors.h"

#include <pybind11/pybind11.h>

#include <texsyn/error_text.h>

namespace texsyn::python {

void raise_error(ErrorKind kind, const std::string& message)
{
    PyObject* type = kind == ErrorKind::Value ? PyExc_ValueError
        : kind == ErrorKind::File             ? PyExc_OSError
                                              : PyExc_RuntimeError;
    PyErr_SetString(type, readable_message(message).c_str());
    throw pybind11::error_already_set();
}

} // namespace texsyn::python
