// SPDX-License-Identifier: Apache-2.0
// The Python classes of results that are not images: analyses, material sets and
// textured meshes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include <texsyn/material.h>
#include <texsyn/stats.h>
#include <texsyn/surface.h>

#include "py_colours.h"

namespace texsyn::python {

/// texsyn.Analysis: a sample's statistics (what `texsyn --analyze` writes to a .tsa file),
/// taken wherever a method takes a sample's analysis.
struct PyAnalysis {
    std::shared_ptr<const TextureStatistics> stats;
};

/// texsyn.Material: an albedo and its other maps, for a copying method to synthesize
/// together. Each map is given back as its input was given.
struct PyMaterial {
    std::shared_ptr<const Material> material;
    std::vector<OutputForm> forms;     ///< per map, in material->maps' order
    ColourOutput albedo;               ///< how the albedo is given back
    std::string name = "material set"; ///< its albedo's name, for messages
    /// The maps given back: name -> image (the albedo colour managed, the others as numbers).
    pybind11::dict maps() const;
    /// The same for `synthesized`, a synthesis of this material (same maps, same order).
    pybind11::dict maps_of(const Material& synthesized) const;
};

/// texsyn.Surface: a texture grown on a mesh.
struct PySurface {
    std::shared_ptr<const SurfaceTexture> texture;
    ColourOutput bake; ///< how its UV bakes are given back
};

/// Defines Analysis, Material and Surface in `m`.
void register_objects(pybind11::module_& m);

} // namespace texsyn::python
