# SPDX-License-Identifier: Apache-2.0
"""Fixtures of the `texsyn` Python module's tests (pytest, Debian's /usr/bin/python3).

ctest runs each test_*.py on its own (tests/CMakeLists.txt) with TEXSYN_TOOL (the built
`texsyn` tool), TEXSYN_DATA (the repository's data/ folder), OIIO_LIBRARY_PATH (the OIIO
plugin's folder) and PYTHONPATH (the build tree's python/ folder) set. By hand, from the
repository's root:

    PYTHONPATH=build/python OIIO_LIBRARY_PATH=build/plugins /usr/bin/python3 -m pytest -q tests/python

Samples are small (64x64 to 96x96) and sizes smaller still: the whole suite runs in seconds.
"""
import os
import pathlib
import subprocess

import numpy as np
import pytest

# The bundled OCIO config and no result cache, here and in the tool the tests run.
os.environ.pop("OCIO", None)
os.environ.pop("TEXSYN_CACHE", None)

import OpenImageIO as oiio  # noqa: E402  (after the environment is set)

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("TEXSYN_DATA", REPO / "data"))
TOOL = os.environ.get("TEXSYN_TOOL", str(REPO / "build" / "oiiotool-ext" / "texsyn"))

# The samples the tests use: (file in data/samples, x, y, side) crops, written as 8-bit
# PNGs like the originals.
_CROPS = {
    "stucco.png": ("stucco_yellow.png", 0, 0, 64),
    "rust.png": ("rust.png", 32, 32, 64),
    "bricks.png": ("bricks.png", 0, 0, 96),
    "bricks_height.png": ("bricks_height.png", 0, 0, 96),
    "bricks_normal.png": ("bricks_normal.png", 0, 0, 96),
}


def read_pixels(path, fmt=oiio.FLOAT):
    """The pixels of image file `path` as an H x W x C array of `fmt`, read by OIIO."""
    buf = oiio.ImageBuf(str(path))
    pixels = buf.get_pixels(fmt)
    assert not buf.has_error, buf.geterror()
    return pixels


def write_pixels(path, pixels, fmt=None):
    """Writes array `pixels` (H x W x C) to `path` with OIIO, as `fmt` (default: its type)."""
    pixels = np.asarray(pixels)
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    types = {np.dtype(np.uint8): oiio.UINT8, np.dtype(np.uint16): oiio.UINT16,
             np.dtype(np.float16): oiio.HALF, np.dtype(np.float32): oiio.FLOAT}
    spec = oiio.ImageSpec(pixels.shape[1], pixels.shape[0], pixels.shape[2],
                          fmt or types[pixels.dtype])
    buf = oiio.ImageBuf(spec)
    assert buf.set_pixels(oiio.ROI(), pixels), buf.geterror()
    assert buf.write(str(path)), buf.geterror()


@pytest.fixture(scope="session")
def samples(tmp_path_factory):
    """The test samples by name ("stucco.png", ...): paths in a scratch folder."""
    folder = tmp_path_factory.mktemp("samples")
    paths = {}
    for name, (source, x, y, side) in _CROPS.items():
        pixels = read_pixels(DATA / "samples" / source, oiio.UINT8)
        write_pixels(folder / name, pixels[y:y + side, x:x + side])
        paths[name] = folder / name
    return paths


@pytest.fixture(scope="session")
def stucco(samples):
    """The stucco sample as OIIO reads it into float: 64 x 64 x 3 float32, the file's
    encoded values / 255."""
    return read_pixels(samples["stucco.png"])


@pytest.fixture(scope="session")
def bricks(samples):
    """The bricks sample as OIIO reads it into float: 96 x 96 x 3 float32."""
    return read_pixels(samples["bricks.png"])


@pytest.fixture(scope="session")
def bricks_height(samples):
    """The bricks' height map: 96 x 96 x 1 uint8."""
    return read_pixels(samples["bricks_height.png"], oiio.UINT8)


@pytest.fixture(scope="session")
def bricks_normal(samples):
    """The bricks' tangent-space normal map (OpenGL): 96 x 96 x 3 uint8."""
    return read_pixels(samples["bricks_normal.png"], oiio.UINT8)


@pytest.fixture(scope="session")
def stucco_u8(samples):
    """The stucco sample's encoded values: a 64 x 64 x 3 uint8 array."""
    return read_pixels(samples["stucco.png"], oiio.UINT8)


@pytest.fixture(scope="session")
def stucco_linear(samples):
    """The stucco sample in scene-linear (the bundled config's sRGB texture space to its
    scene_linear role, converted by OIIO's own OCIO): 64 x 64 x 3 float32."""
    buf = oiio.ImageBuf()
    buf.copy(oiio.ImageBuf(str(samples["stucco.png"])), oiio.FLOAT)  # not converted to uint8
    out = oiio.ImageBufAlgo.colorconvert(buf, "sRGB - Texture", "scene_linear",
                                         colorconfig=str(REPO / "ocio-configs" / "config.ocio"))
    assert not out.has_error, out.geterror()
    return out.get_pixels(oiio.FLOAT)


class Cli:
    """The built `texsyn` tool, run in a scratch folder."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)

    def run(self, *args):
        """Runs `texsyn ARGS...` in the folder: the CompletedProcess (text output)."""
        return subprocess.run([TOOL, *map(str, args)], cwd=self.folder, capture_output=True,
                              text=True, timeout=120, check=False)

    def float_result(self, *args, seed=0, out="out.exr"):
        """Runs `texsyn --seed SEED ARGS... -d float -o OUT` and gives OUT's pixels as a
        float32 array, as OIIO reads them."""
        r = self.run("--seed", seed, *args, "-d", "float", "-o", out)
        assert r.returncode == 0, r.stderr
        return read_pixels(self.folder / out)

    def path(self, name):
        return self.folder / name


@pytest.fixture
def cli(tmp_path):
    """The tool, run in this test's scratch folder."""
    return Cli(tmp_path)
