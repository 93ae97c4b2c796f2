// SPDX-License-Identifier: Apache-2.0
// The compiled part of the `texsyn` Python package (texsyn/__init__.py makes one function
// per registry row from it). docs/python.md is the user's guide.
#include <pybind11/pybind11.h>

#include <texsyn/version.h>

#include "py_apply_map.h"
#include "py_methods.h"
#include "py_objects.h"
#include "py_recipe.h"
#include "py_run.h"

PYBIND11_MODULE(_texsyn, m)
{
    m.doc() = "texsyn's library: texture synthesis on OpenImageIO and OpenColorIO.";
    m.attr("__version__") = texsyn::version();
    texsyn::python::register_objects(m);
    texsyn::python::register_methods(m);
    texsyn::python::register_apply_map(m);
    texsyn::python::register_recipe(m);
    // Before the interpreter finalizes (and ends daemon threads), the runs in progress stop.
    pybind11::module_::import("atexit").attr("register")(
        pybind11::cpp_function(&texsyn::python::stop_runs_at_exit));
}
