// SPDX-License-Identifier: Apache-2.0
// The registry's rows as data: what texsyn/__init__.py makes one function per row from.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace texsyn::python {

/// An option's Python keyword: its name with '-' as '_'.
std::string keyword_of(const std::string& option);

/// Every row of the registry as a dict: its name, command, inputs, output, texts and
/// options (each with its keyword, type, help, allowed values and default).
pybind11::list method_table();

} // namespace texsyn::python
