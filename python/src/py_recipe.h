// SPDX-License-Identifier: Apache-2.0
// texsyn.Recipe: synthesis recipes (recipe.h) from Python.
#pragma once

#include <pybind11/pybind11.h>

namespace texsyn::python {

/// Defines Recipe in `m`.
void register_recipe(pybind11::module_& m);

} // namespace texsyn::python
