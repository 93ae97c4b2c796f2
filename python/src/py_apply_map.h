// SPDX-License-Identifier: Apache-2.0
// texsyn.apply_map: a source map re-applied to another map of the same material.
#pragma once

#include <pybind11/pybind11.h>

namespace texsyn::python {

/// Defines apply_map() in `m`.
void register_apply_map(pybind11::module_& m);

} // namespace texsyn::python
