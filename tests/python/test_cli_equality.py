# SPDX-License-Identifier: Apache-2.0
"""The module gives the tool's pixels, bit for bit: a file name in gives what
`texsyn --seed S FILE --METHOD:... -d float -o out.exr` writes (docs/python.md), an 8-bit
array what an 8-bit -o writes, and a recipe the same pixels in Recipe.run, the tool and
OpenImageIO reading it through texsyn's plugin."""
import pathlib

import numpy as np
import OpenImageIO as oiio
import pytest

import texsyn
from conftest import Cli, read_pixels

SEED = 7

# The tool's side: one run (a process costs about half a second), one command per case,
# each on a freshly read input (the generator first, while the stack is empty).
COMMANDS = {
    "cascade": ["--cascade:size=48x48:preset=cells"],
    "pyramid": ["stucco.png", "--pyramid:size=48x32:iterations=2"],
    "patch": ["bricks.png", "--patch:size=48x40:map=patch_map.exr"],
    "neighborhood": ["stucco.png", "--neighborhood:size=32x32:levels=2"],
    "choosy": ["stucco.png", "--choosy:size=32x32:levels=2"],
    "mix": ["stucco.png", "rust.png", "--mix:palette=0:pattern=1:size=32x32:iterations=1"],
}


@pytest.fixture(scope="module")
def tool(samples, tmp_path_factory):
    """The tool's results by case name, and its folder (with neighborhood.texsyn, the
    recipe of the neighborhood case)."""
    cli = Cli(samples["stucco.png"].parent)
    args = ["--seed", SEED, "-d", "float"]
    for name, command in COMMANDS.items():
        args += command + ["-o", name + ".exr"]
        if name == "neighborhood":
            args += ["--recipe", "neighborhood.texsyn"]
    r = cli.run(*args)
    assert r.returncode == 0, r.stderr
    return {name: read_pixels(cli.path(name + ".exr")) for name in COMMANDS}, cli


def test_pyramid(samples, tool):
    out = texsyn.pyramid(str(samples["stucco.png"]), size=(48, 32), iterations=2, seed=SEED)
    assert out.shape == (32, 48, 3)
    assert np.array_equal(out, tool[0]["pyramid"])


def test_patch_and_its_source_map(samples, tool):
    image, coords = texsyn.patch(str(samples["bricks.png"]), size=(48, 40), seed=SEED)
    assert np.array_equal(image, tool[0]["patch"])
    assert np.array_equal(coords, read_pixels(tool[1].path("patch_map.exr")))


def test_neighborhood(samples, tool):
    image, _ = texsyn.neighborhood(str(samples["stucco.png"]), size=(32, 32), levels=2,
                                   seed=SEED)
    assert np.array_equal(image, tool[0]["neighborhood"])


def test_choosy(samples, tool):
    image, _ = texsyn.choosy(str(samples["stucco.png"]), size=(32, 32), levels=2, seed=SEED)
    assert np.array_equal(image, tool[0]["choosy"])


def test_cascade(tool):
    out = texsyn.cascade(size=(48, 48), preset="cells", seed=SEED)
    assert np.array_equal(out, tool[0]["cascade"])


def test_mix(samples, tool):
    out = texsyn.mix([str(samples["stucco.png"]), str(samples["rust.png"])], palette=0,
                     pattern=1, size=(32, 32), iterations=1, seed=SEED)
    assert np.array_equal(out, tool[0]["mix"])


def test_a_recipe_gives_the_same_pixels_in_python_the_tool_and_oiio(tool):
    expected, cli = tool[0]["neighborhood"], tool[1]
    recipe = texsyn.Recipe.load(str(cli.path("neighborhood.texsyn")))
    assert recipe.method == "neighborhood" and recipe.seed == SEED
    assert np.array_equal(recipe.run(), expected)
    again = texsyn.Recipe.from_json(recipe.to_json())
    assert np.array_equal(again.run(threads=1), expected)
    # OpenImageIO opens the recipe through texsyn's plugin (OIIO_LIBRARY_PATH).
    buf = oiio.ImageBuf(str(cli.path("neighborhood.texsyn")))
    pixels = buf.get_pixels(oiio.FLOAT)
    assert not buf.has_error, buf.geterror()
    assert np.array_equal(pixels, expected)


def test_a_rest_name_is_a_recipe(samples, tool):
    name = f"{samples['stucco.png']}.texsyn?size=48x32&iterations=2&seed={SEED}"
    assert np.array_equal(texsyn.Recipe.load(name).run(), tool[0]["pyramid"])


def test_a_recipe_keeps_its_paths_after_a_chdir(samples, tool, tmp_path, monkeypatch):
    monkeypatch.chdir(samples["stucco.png"].parent)
    recipe = texsyn.Recipe.load(
        pathlib.Path(f"stucco.png.texsyn?size=48x32&iterations=2&seed={SEED}"))
    monkeypatch.chdir(tmp_path)
    assert np.array_equal(recipe.run(), tool[0]["pyramid"])
    assert '"sample": "stucco.png"' in recipe.to_json(base_dir=samples["stucco.png"].parent)


def test_an_8_bit_array_gives_what_an_8_bit_file_holds(samples, stucco_u8, cli):
    r = cli.run("--seed", 6, samples["stucco.png"], "--pyramid:size=40x40:iterations=1", "-o",
                "out.png")
    assert r.returncode == 0, r.stderr
    expected = read_pixels(cli.path("out.png"), oiio.UINT8)
    assert np.array_equal(texsyn.pyramid(stucco_u8, size=(40, 40), iterations=1, seed=6),
                          expected)
    buf = texsyn.pyramid(oiio.ImageBuf(str(samples["stucco.png"])), size=(40, 40),
                         iterations=1, seed=6)
    assert np.array_equal(buf.get_pixels(oiio.UINT8), expected)


def test_subbands_are_the_parts_of_the_tools_subbands_exr(samples, cli):
    r = cli.run("--subbands", samples["stucco.png"],
                "--pyramid:size=32x32:iterations=1:scales=2:orientations=2", "-d", "float",
                "-o", "bands.exr")
    assert r.returncode == 0, r.stderr
    parts = {}
    reader = oiio.ImageInput.open(str(cli.path("bands.exr")))
    subimage = 0
    while reader.seek_subimage(subimage, 0):
        parts[reader.spec().get_string_attribute("name")] = reader.read_image(oiio.FLOAT)
        subimage += 1
    reader.close()
    image, bands = texsyn.pyramid(str(samples["stucco.png"]), size=(32, 32), iterations=1,
                                  scales=2, orientations=2, subbands=True)
    assert np.array_equal(image, parts.pop("synth"))
    assert set(bands) == set(parts)
    for name, band in bands.items():
        assert np.array_equal(band, parts[name]), name
