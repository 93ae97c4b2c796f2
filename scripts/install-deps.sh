#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs texsyn's build and test dependencies from Debian 12 (bookworm) packages.
# Idempotent: apt-get skips what is already installed. Needs root (or sudo).
set -euo pipefail

packages=(
  cmake g++ make ninja-build pkg-config ccache
  libopenimageio-dev openimageio-tools      # tools: the OIIO CMake config imports them
  libopencolorio-dev opencolorio-tools      # ociocheck validates the bundled config
  libopenexr-dev openexr libimath-dev python3-imath
  libkissfft-dev                            # default (permissive) FFT backend
  libfftw3-dev                              # optional GPL backend (-DTEXSYN_WITH_FFTW=ON)
  libeigen3-dev nlohmann-json3-dev
  libssl-dev                                # HMAC-SHA256 for a shared result cache's entries (TEXSYN_CACHE_SECRET)
  libtiff-dev                               # checks that JPEG-compressed TIFF inputs decode whole
  libnanoflann-dev                          # kd-tree search (--neighborhood:search=kdtree)
  libopenmesh-dev                           # surface meshes: remeshing (BSD-3)
  libcgal-dev                               # optional GPL remeshing backend (-DTEXSYN_WITH_CGAL=ON)
  libopenvdb-dev libboost-iostreams-dev      # solid textures: .vdb output (OpenVDB's CMake module needs Boost.Iostreams)
  python3-openimageio                       # tests open recipes from Python
  pybind11-dev python3-dev python3-numpy    # the texsyn Python module (python/)
  python3-pytest                            # its tests
  python3-jsonschema                        # tests validate recipes with docs/recipe.schema.json
  libgtest-dev libbenchmark-dev
  clang-format                              # the style check (tests: clang_format)
  clang libclang-rt-14-dev                  # sanitizer builds and libFuzzer (scripts/sanitize.sh, tests/fuzz/run)
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi
echo "texsyn: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=900 install -y -q --no-install-recommends "${missing[@]}"
