# SPDX-License-Identifier: Apache-2.0
# Finds texsyn's dependencies on Debian 12, with workarounds for four broken package configs.
find_package(PkgConfig REQUIRED)

# OIIO's exported target lists /usr/include/opencv4 even when libopencv-dev is absent.
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
list(FILTER _oiio_inc EXCLUDE REGEX "opencv4")
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_inc}")

# OCIO's config package is installed where CMake does not look; pkg-config works.
find_package(OpenColorIO 2.1 CONFIG QUIET)
if(NOT TARGET OpenColorIO::OpenColorIO)
  pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET GLOBAL OpenColorIO>=2.1)
  add_library(OpenColorIO::OpenColorIO ALIAS PkgConfig::OCIO)
endif()

find_package(Imath CONFIG REQUIRED)
find_package(Eigen3 3.3 CONFIG REQUIRED)
# libtiff: decodes every strip of JPEG-compressed TIFF inputs (src/image/tiff_extent.cpp).
find_package(TIFF 4.5 REQUIRED)
find_package(nlohmann_json 3 CONFIG REQUIRED)
# HMAC-SHA256 authenticates entries of a shared result cache ($TEXSYN_CACHE_SECRET).
find_package(OpenSSL 3 REQUIRED COMPONENTS Crypto)
# Header-only (the kd-tree search back-end); Debian's config is in /usr/share/nanoflann/cmake.
find_package(nanoflann CONFIG REQUIRED)
# Debian ships only the shared float build; without SHARED the config looks for static targets.
find_package(kissfft CONFIG REQUIRED COMPONENTS SHARED float)

if(TEXSYN_WITH_FFTW)
  pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
endif()
if(TEXSYN_WITH_CGAL)
  find_package(CGAL 5.5 CONFIG REQUIRED)
endif()

# OpenVDB (solid textures' .vdb output): Debian ships a find module, not a config package.
# It needs libboost-iostreams-dev too (its find module looks for Boost.Iostreams).
list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
find_package(OpenVDB REQUIRED)

# OpenMesh (BSD-3; surface meshes, src/surface/): Debian's config has no version file, so no
# version may be asked for, and its targets (OpenMeshCore, OpenMeshTools) have no namespace
# (a misspelt name would silently become -lName): link the alias. Its only configuration,
# "None", serves every build type.
find_package(OpenMesh CONFIG REQUIRED)
add_library(OpenMesh::Core ALIAS OpenMeshCore)
