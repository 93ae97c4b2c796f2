// SPDX-License-Identifier: Apache-2.0
// The OpenVDB writer: the only translation unit that includes OpenVDB (its headers are slow
// to compile).
#include <texsyn/volume.h>

#include <filesystem>
#include <new>
#include <stdexcept>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <texsyn/io.h>

#include "image/io_pvt.h"

namespace texsyn {

namespace {

openvdb::CoordBBox block_bounds(const PlanarVolume& v)
{
    return openvdb::CoordBBox(
        openvdb::Coord(0, 0, 0), openvdb::Coord(v.width() - 1, v.height() - 1, v.depth() - 1));
}

// Dense x-fastest values into a grid whose every voxel of the block is active: copyFromDense
// leaves voxels equal to the background inactive, so the block's topology is added back
// (their values are the background already).
template <class GridT>
typename GridT::Ptr dense_grid(
    const openvdb::CoordBBox& bbox, typename GridT::ValueType* values, const std::string& name)
{
    using ValueT = typename GridT::ValueType;
    typename GridT::Ptr grid = GridT::create(openvdb::zeroVal<ValueT>());
    openvdb::tools::Dense<ValueT, openvdb::tools::LayoutXYZ> dense(bbox, values);
    openvdb::tools::copyFromDense(dense, *grid, openvdb::zeroVal<ValueT>());
    openvdb::MaskTree block(false);
    block.fill(bbox, true, true);
    grid->tree().topologyUnion(block);
    grid->setName(name);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(1.0));
    return grid;
}

openvdb::FloatGrid::Ptr float_grid(
    const openvdb::CoordBBox& bbox, const Volume& channel, const std::string& name)
{
    // Dense only reads through this pointer.
    return dense_grid<openvdb::FloatGrid>(bbox, const_cast<float*>(channel.data()), name);
}

openvdb::Vec3SGrid::Ptr colour_grid(const openvdb::CoordBBox& bbox, const PlanarVolume& v)
{
    const int ncolor = v.ncolor();
    const Volume& r = v.channels[0];
    const Volume* g = ncolor == 1 ? &r : ncolor >= 2 ? &v.channels[1] : nullptr;
    const Volume* b = ncolor == 1 ? &r : ncolor >= 3 ? &v.channels[2] : nullptr;
    std::vector<openvdb::Vec3s> rgb(r.size());
    for (size_t i = 0; i < rgb.size(); ++i)
        rgb[i] = openvdb::Vec3s(r.data()[i], g ? g->data()[i] : 0.0f, b ? b->data()[i] : 0.0f);
    auto grid = dense_grid<openvdb::Vec3SGrid>(bbox, rgb.data(), "Cd");
    grid->setVectorType(openvdb::VEC_INVARIANT);
    return grid;
}

openvdb::MetaMap file_metadata(const PlanarVolume& v)
{
    openvdb::MetaMap meta;
    for (const OIIO::ParamValue& p : v.attributes) {
        const std::string name = p.name().string();
        if (p.type() == OIIO::TypeString)
            meta.insertMeta(name, openvdb::StringMetadata(p.get_string()));
        else if (p.type() == OIIO::TypeInt)
            meta.insertMeta(name, openvdb::Int32Metadata(p.get_int()));
        else if (p.type() == OIIO::TypeFloat)
            meta.insertMeta(name, openvdb::FloatMetadata(p.get_float()));
    }
    return meta;
}

void write_grids(const std::string& path, const PlanarVolume& v)
{
    openvdb::initialize();
    const openvdb::CoordBBox bbox = block_bounds(v);
    openvdb::GridPtrVec grids;
    if (v.ncolor() > 0)
        grids.push_back(colour_grid(bbox, v));
    for (int c = 0; c < v.nchannels(); ++c) {
        if (c == v.alpha_channel) {
            auto density = float_grid(bbox, v.channels[size_t(c)], "density");
            density->setGridClass(openvdb::GRID_FOG_VOLUME);
            grids.push_back(density);
        } else if (c >= 3 || (c >= v.ncolor())) {
            grids.push_back(float_grid(bbox, v.channels[size_t(c)], v.channel_names[size_t(c)]));
        }
    }
    openvdb::io::File file(path);
    file.write(grids, file_metadata(v));
    file.close();
}

// OpenVDB writes through a std::ofstream whose errors it does not check: read every grid
// back, so that a file truncated by a full disk is not committed.
void read_back(const std::string& path)
{
    try {
        openvdb::io::File file(path);
        file.open(false);
        for (auto name = file.beginName(); name != file.endName(); ++name)
            file.readGrid(name.gridName());
        file.close();
    } catch (const std::exception& e) {
        throw std::runtime_error(
            "the written file is incomplete (disk full?): " + one_line(e.what()));
    }
}

} // namespace

bool write_volume_vdb(const std::string& filename, const PlanarVolume& v, std::string& error)
{
    if (!check_output_destination(filename, error))
        return false;
    const std::string tmp = temporary_path_for(filename);
    std::string reason;
    try {
        write_grids(tmp, v);
        if (sync_written_file(tmp, reason)) {
            read_back(tmp);
            return commit_file(tmp, filename, error);
        }
        error = filename + ": cannot write (" + reason + ")";
    } catch (const std::bad_alloc&) {
        error = filename + ": out of memory writing the OpenVDB file";
    } catch (const std::exception& e) {
        error = filename + ": cannot write (" + one_line(e.what()) + ")";
    }
    discard_temporary(tmp);
    return false;
}

} // namespace texsyn
