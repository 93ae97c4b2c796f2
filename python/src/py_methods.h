// SPDX-License-Identifier: Apache-2.0
// The registry's rows as Python functions: what texsyn/__init__.py generates them from,
// and the one function that runs any of them.
#pragma once

#include <pybind11/pybind11.h>

namespace texsyn::python {

/// Defines _method_table() and _run_method() (which runs any row) in `m`.
void register_methods(pybind11::module_& m);

} // namespace texsyn::python
