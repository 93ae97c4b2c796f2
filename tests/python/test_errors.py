# SPDX-License-Identifier: Apache-2.0
"""Bad input raises, never crashes the interpreter (docs/python.md, "Errors"): ValueError
for bad options, arrays and what a method refuses before it works, OSError for files,
TypeError for objects that are not images; the messages are the tool's (the cases of
tests/cli/cli_test.cpp and fill_cli_test.cpp, through the module)."""
import os
import re

import numpy as np
import OpenImageIO as oiio
import pytest

import texsyn
from conftest import write_pixels


@pytest.fixture(scope="module")
def bad_files(samples, tmp_path_factory):
    """Files the tool refuses: a cut PNG, a text file named .png, a folder, a non-finite EXR,
    a bad recipe and a bad analysis file."""
    folder = tmp_path_factory.mktemp("bad")
    png = samples["stucco.png"].read_bytes()
    (folder / "cut.png").write_bytes(png[:len(png) // 3])
    (folder / "notes.png").write_text("this is not a PNG file\n")
    (folder / "folder").mkdir()
    (folder / "bad.texsyn").write_text("{bad json")
    (folder / "bad.tsa").write_text("not an analysis\n")
    nan = np.full((32, 32, 3), 0.5, np.float32)
    nan[4, 3, 0] = np.nan
    write_pixels(folder / "nan.exr", nan)
    return folder


def refuses(call, exception, message):
    """Asserts that call() raises `exception` (exactly that class or a subclass) whose text
    contains `message`."""
    with pytest.raises(exception) as caught:
        call()
    assert message in str(caught.value), str(caught.value)
    return str(caught.value)


# Options: the tool's messages (Cli.MalformedCommandsAndOptionsAreRefused), without its
# "texsyn ERROR: --pyramid : " prefix.
@pytest.mark.parametrize("options, message", [
    (dict(iterations=-1), "iterations=-1 : out of range 0..100"),
    (dict(orientations=99), "orientations=99 : out of range 1..8"),
    (dict(size="abc"), "size=abc : not a size (expected WxH, e.g. 1024x1024)"),
    (dict(size=(0, 10)), "size=0x10 : out of range 1..1048576 (each side)"),
    (dict(size=(1, 2, 3)), "size=1x2x3 : not a size"),
    (dict(iterations=2.5), "iterations=2.5 : not an integer"),
    (dict(pyramid="nope"), "pyramid=nope : not one of steerable|laplacian"),
    (dict(iterations=None), "iterations=None : iterations has no unset value"),
    (dict(iterations=object()), "iterations= : expected a number or a string, got object"),
    (dict(levels=3), "texsyn.pyramid: unknown keyword 'levels'"),
    (dict(iteration=3), "unknown keyword 'iteration', did you mean 'iterations'?"),
    (dict(tocolorspace="Nope"), "tocolorspace=Nope : unknown colour space 'Nope' (known: "
                                "Linear Rec.709 (sRGB), sRGB - Texture, ACEScg, Raw, "
                                "CIE-XYZ-D65; texsyn --colorspaces describes them)"),
    (dict(iscolorspace="Nope"), "iscolorspace=Nope : unknown colour space 'Nope'"),
    (dict(iscolorspace=["ACEScg", "ACEScg"]), "2 colour spaces for 1 inputs"),
    (dict(colorconfig="missing.ocio"), "colour config 'missing.ocio': no such file"),
    (dict(seed=-1), "seed=-1 : expected an integer in 0..2147483647"),
    (dict(seed=2 ** 31), "seed=2147483648 : expected an integer in 0..2147483647"),
    (dict(seed="7"), "seed='7' : expected an integer"),
    (dict(threads=-2), "threads=-2 : expected an integer in 0..1024"),
    (dict(threads=True), "threads=True : expected an integer"),
])
def test_bad_options_are_value_errors(stucco, options, message):
    refuses(lambda: texsyn.pyramid(stucco, **options), ValueError, message)


def test_the_returned_map_is_not_a_keyword(stucco):
    refuses(lambda: texsyn.patch(stucco, map="coords.exr"), ValueError,
            "unknown keyword 'map' (map= is returned, not written)")


def allowed_range(option):
    """(lo, hi) of an integer or real option's "lo..hi" allowed text."""
    lo, hi = re.match(r"(-?[\d.]+)\.\.(-?[\d.]+)", option["allowed"]).groups()
    return (int(lo), int(hi)) if option["type"] == "integer" else (float(lo), float(hi))


def test_every_method_reports_a_range_error_the_same_way(stucco):
    """As Cli.EveryCommandReportsARangeErrorTheSameWay: each method's first number option
    just above its range."""
    inputs = {"none": (), "optional_image": (), "image": (stucco,), "sample": (stucco,),
              "image_and_sample": (stucco, stucco), "samples": ([stucco, stucco],)}
    checked = 0
    for row in texsyn._texsyn._method_table():
        numbers = [o for o in row["options"] if o["type"] in ("integer", "real")]
        if not numbers:  # check takes no options, material files, names and lists
            continue
        option = numbers[0]
        lo, hi = allowed_range(option)
        value = hi + 1
        refuses(lambda: getattr(texsyn, row["name"])(*inputs[row["inputs"]],
                                                     **{option["name"]: value}),
                ValueError, f"{option['option']}={value} : out of range {lo}..{hi}")
        checked += 1
    assert checked == len(texsyn.method_names) - 2


@pytest.mark.parametrize("dtype", [np.int32, np.int8, np.bool_, np.complex64, object])
def test_arrays_of_other_types_are_value_errors(stucco, dtype):
    refuses(lambda: texsyn.pyramid(stucco.astype(dtype)), ValueError,
            "sample: numpy arrays of uint8, uint16 or floating point are taken, got "
            + np.dtype(dtype).name)


@pytest.mark.parametrize("shape, message", [
    ((64 * 64 * 3,), "expected an array of H x W or H x W x C, got 1 dimensions"),
    ((1, 64, 64, 3), "got 4 dimensions"),
    ((0, 64, 3), "an array of 0 x 64 x 3 is not an image"),
    ((64, 64, 0), "an array of 64 x 64 x 0 is not an image"),
])
def test_arrays_of_other_shapes_are_value_errors(shape, message):
    refuses(lambda: texsyn.pyramid(np.zeros(shape, np.float32)), ValueError, message)


def test_objects_that_are_not_images_are_type_errors(stucco):
    refuses(lambda: texsyn.pyramid(42), TypeError,
            "sample: expected a numpy array, an OpenImageIO.ImageBuf or a file name, got int")
    refuses(lambda: texsyn.pyramid(stucco, progress=3), TypeError,
            "progress= : expected a callable")


def test_input_counts(stucco):
    refuses(lambda: texsyn.pyramid(), ValueError, "texsyn.pyramid takes 1 input, got 0")
    refuses(lambda: texsyn.pyramid(stucco, stucco), ValueError, "takes 1 input, got 2")
    refuses(lambda: texsyn.mix("a.png"), ValueError, "texsyn.mix: expected one list of samples")
    refuses(lambda: texsyn.pyramid({"albedo": stucco}), ValueError,
            "a material set is synthesized by the copying methods (neighborhood, choosy, "
            "patch and fill), one set at a time")


@pytest.mark.parametrize("value, what", [(np.nan, "is NaN"), (np.inf, "is infinite"),
                                         (-np.inf, "is infinite")])
def test_non_finite_pixels_are_value_errors(stucco, value, what):
    bad = stucco.copy()
    bad[4, 3, 0] = value
    refuses(lambda: texsyn.pyramid(bad), ValueError,
            f"sample: pixel (3, 4) channel R {what}; texsyn needs finite pixel values")


def test_non_finite_pixels_in_a_file(bad_files):
    path = str(bad_files / "nan.exr")
    refuses(lambda: texsyn.pyramid(path), ValueError,
            f"{path}: pixel (3, 4) channel R is NaN; texsyn needs finite pixel values")


def test_non_finite_pixels_in_a_material_map(bad_files):
    """Issue #34: a map with NaN was carried into the synthesized set (a normal map with
    1,530 NaN came back); it is refused when read, as a sample is."""
    albedo = np.full((32, 32, 3), 0.5, np.float32)
    path = str(bad_files / "nan.exr")
    refuses(lambda: texsyn.material(albedo, normal=path), ValueError,
            f"normal={path} : pixel (3, 4) channel R is NaN; texsyn needs finite pixel values")


def test_a_constant_image_is_synthesized_as_constant():
    flat = np.full((64, 64, 3), 0.25, np.float32)
    assert (texsyn.pyramid(flat, size=(32, 32), iterations=1) == 0.25).all()
    image, _ = texsyn.patch(flat, size=(32, 32))
    assert (image == 0.25).all()
    assert "homogeneity score" in texsyn.check(flat)


@pytest.mark.parametrize("method, options, message", [
    ("neighborhood", {}, "the sample (1x1) is smaller than the n=9 neighbourhood"),
    ("choosy", {}, "the sample (1x1) is smaller than the 5x5 neighbourhood"),
    ("pyramid", {}, "sample is 1x1: the pyramid method needs at least 16x16"),
    ("patch", {}, "the sample (1x1) is smaller than the 3-pixel patch"),
])
def test_too_small_samples_are_value_errors(method, options, message):
    tiny = np.full((1, 1, 3), 0.5, np.float32)
    refuses(lambda: getattr(texsyn, method)(tiny, **options), ValueError, message)


@pytest.mark.parametrize("call, message", [
    (lambda s: texsyn.pyramid(s, size=(200000, 200000)), "size=200000x200000 would need about "),
    (lambda s: texsyn.patch(s, size=(60000, 60000)), "size=60000x60000 would need about "),
    (lambda s: texsyn.solid(s, size=(4000, 4000, 4000)), "size=4000x4000x4000 would need about"),
    (lambda s: texsyn.neighborhood(s, size=(100000, 100000)),
     "size=100000x100000 : out of range 1..65536 (each side)"),
])
def test_absurd_sizes_are_refused_before_allocating(stucco, call, message):
    refuses(lambda: call(stucco), ValueError, message)


def test_copies_of_views_are_checked_against_the_memory_limit(monkeypatch):
    """Issue #34: a zero-stride view of 40000 x 40000 pixels takes no memory until it is
    copied; the copy went past 4 GB under TEXSYN_MAX_MEMORY=2G."""
    monkeypatch.setenv("TEXSYN_MAX_MEMORY", "2G")
    view = np.broadcast_to(np.float32(0.5), (40000, 40000, 3))
    refuses(lambda: texsyn.pyramid(view), ValueError,
            "sample: a copy of its pixels would need about 17.9 GB of memory")
    big_endian = np.broadcast_to(np.array(0.5, ">f4"), (40000, 40000, 3))
    refuses(lambda: texsyn.pyramid(big_endian), ValueError, "a copy of its pixels would need")
    as_float64 = np.broadcast_to(np.float64(0.5), (40000, 40000, 3))
    refuses(lambda: texsyn.pyramid(as_float64), ValueError, "a copy of its pixels would need")


def test_bad_files_are_os_errors(bad_files):
    for name, message in [("missing.png", "no such file"),
                          ("notes.png", "cannot read image (Not a PNG file)"),
                          ("cut.png", "cannot read image"),
                          ("folder", "is a directory, not an image")]:
        path = str(bad_files / name)
        refuses(lambda: texsyn.pyramid(path), OSError, f"texsyn.pyramid: {path}: {message}")
    refuses(lambda: texsyn.pyramid("/dev/zero"), OSError,
            "/dev/zero: is not a regular file (a FIFO, device or socket), not an image")
    refuses(lambda: texsyn.pyramid(oiio.ImageBuf(str(bad_files / "missing.png"))), OSError,
            "sample: the ImageBuf holds no image")
    refuses(lambda: texsyn.pyramid(oiio.ImageBuf(str(bad_files / "cut.png"))), OSError,
            "sample: ")
    refuses(lambda: texsyn.pyramid(oiio.ImageBuf()), ValueError,
            "sample: the ImageBuf holds no image")
    assert isinstance(pytest.raises(OSError, texsyn.pyramid, str(bad_files / "missing.png")
                                    ).value, OSError)


# Masks: FillCli.BadMasksAreRefusedWithOneLine's cases, in memory and as files.
def test_bad_masks(bricks, bad_files):
    mask = np.zeros(bricks.shape[:2], np.float32)
    mask[40:56, 40:56] = 1
    refuses(lambda: texsyn.fill(bricks), ValueError,
            "mask= : give the mask image (pixels above 0 are filled)")
    refuses(lambda: texsyn.fill(bricks, mask=str(bad_files / "missing.png")), OSError,
            "no such file")
    refuses(lambda: texsyn.fill(bricks, mask=np.ascontiguousarray(mask[:, :48])), ValueError,
            "mask=array : the mask is 48x96 with 1 channel; it must be one channel of the "
            "image's size (96x96)")
    refuses(lambda: texsyn.fill(bricks, mask=np.repeat(mask[:, :, None], 3, axis=2)),
            ValueError, "with 3 channels")
    refuses(lambda: texsyn.fill(bricks, mask=mask, patch=(7, 9)), ValueError,
            "patch=7,9 : list the sizes largest first")
    refuses(lambda: texsyn.fill(bricks, mask=np.ones_like(mask)), ValueError,
            "the mask covers the whole image: give a sample to fill it from")
    nan = mask.copy()
    nan[0, 0] = np.nan
    refuses(lambda: texsyn.fill(bricks, mask=nan), ValueError, "is NaN")
    refuses(lambda: texsyn.fill(bricks, mask=mask * 2.5), ValueError,
            "the mask has the value 2.5 at 40,40; its values must be in 0..1")
    refuses(lambda: texsyn.fill(bricks, mask=mask, sample=bricks[:, :, :1].copy()), ValueError,
            "the sample has 1 channel and the image 3 channels")


def test_inputs_that_do_not_go_together(stucco, bricks):
    refuses(lambda: texsyn.mix([stucco, stucco[:, :, :1].copy()], palette=0, pattern=1),
            ValueError, "the samples of a mix need the same channels")
    refuses(lambda: texsyn.transfer(stucco, stucco[:, :, :1].copy()), ValueError,
            "a transfer needs the same channels")
    refuses(lambda: texsyn.tileable(bricks, band=90), ValueError,
            "band=90 : too wide for a 96x96 image (at most a third of its shorter side, 32)")
    refuses(lambda: texsyn.material(stucco, height=bricks), ValueError,
            "the height map is 96x96 and the albedo 64x64")
    refuses(lambda: texsyn.patch({"height": stucco}), ValueError,
            "a dict of maps needs an \"albedo\"")
    refuses(lambda: texsyn.patch({"albedo": stucco, "bogus": stucco}), ValueError,
            "no map called \"bogus\"")


def test_meshes(stucco, bad_files):
    refuses(lambda: texsyn.choosy_surface(stucco), ValueError,
            "mesh= : a mesh file is needed (OBJ or PLY)")
    refuses(lambda: texsyn.choosy_surface(stucco, mesh=stucco), ValueError,
            "mesh= : a mesh is given by its file name")
    refuses(lambda: texsyn.choosy_surface(stucco, mesh=str(bad_files / "missing.obj")),
            OSError, "no such file")


def test_apply_map(stucco, bad_files):
    coords = np.zeros((8, 8, 2), np.float32)
    # An array of three channels is taken as x, y, t: an image is not a map.
    refuses(lambda: texsyn.apply_map(stucco, stucco), ValueError,
            "the source map's pixel (0, 0) holds (0.8862746, 0.81568635, 0.525490): not an "
            "integer position inside the 64x64 sample with a transform 0..7")
    refuses(lambda: texsyn.apply_map(coords + 100, stucco), ValueError,
            "the source map's pixel (0, 0) holds (100, 100): not an integer position inside "
            "the 64x64 sample")
    refuses(lambda: texsyn.apply_map(coords, stucco, normal="up"), ValueError,
            "normal=up : expected none, opengl or directx")
    for size in ("abc", (0, 1), (64,)):
        refuses(lambda: texsyn.apply_map(coords, stucco, sample_size=size), ValueError,
                "sample_size= : expected (width, height)")
    refuses(lambda: texsyn.apply_map(np.zeros((8, 8, 4), np.float32), stucco), ValueError,
            "the source map has 4 channels; expected the channels x, y (and t, m)")
    refuses(lambda: texsyn.apply_map(str(bad_files / "missing.exr"), stucco), OSError,
            "no such file")


def test_recipes_and_analyses(stucco, bad_files):
    refuses(lambda: texsyn.Recipe.load(str(bad_files / "bad.texsyn")), ValueError,
            "malformed JSON")
    refuses(lambda: texsyn.Recipe.from_json("{bad"), ValueError, "malformed JSON")
    refuses(lambda: texsyn.Recipe.load(bad_files / "missing.texsyn"), OSError,
            "missing.texsyn: no such recipe file or sample")
    missing_sample = texsyn.Recipe.from_json(
        '{"texsyn_recipe": 1, "sample": "missing.png", "method": "pyramid"}',
        base_dir=str(bad_files))
    refuses(missing_sample.run, ValueError, "missing.png: no such file")
    refuses(lambda: texsyn.Analysis.load(str(bad_files / "missing.tsa")), OSError,
            "no such file")
    refuses(lambda: texsyn.Analysis.load(str(bad_files / "bad.tsa")), OSError,
            "not a texsyn analysis file")
    before = sorted(os.listdir(bad_files))
    refuses(lambda: texsyn.analyze(stucco).save(str(bad_files / "no" / "a.tsa")), OSError,
            "cannot write the analysis file")
    assert sorted(os.listdir(bad_files)) == before  # nothing left behind


def test_recipe_files_over_a_megabyte_are_refused_from_their_size(tmp_path):
    """A 10 GB sparse recipe file used to be read whole (20 GB resident)."""
    huge = tmp_path / "huge.texsyn"
    with open(huge, "wb") as f:
        f.truncate(2 << 20)
    refuses(lambda: texsyn.Recipe.load(huge), ValueError,
            "huge.texsyn: is 2.0 MB, more than a recipe can be (1.0 MB)")
    refuses(lambda: texsyn.Recipe.from_json(" " * (2 << 20)), ValueError,
            "is 2.0 MB, more than a recipe can be (1.0 MB)")


def test_analysis_save_refuses_a_device(stucco, tmp_path):
    """Given /dev/full, Analysis.save used to replace the machine's /dev/full with a regular
    file; a device or FIFO is refused and left as it is."""
    import stat
    analysis = texsyn.analyze(stucco)
    refuses(lambda: analysis.save("/dev/full"), OSError,
            "exists and is not a regular file (a device, FIFO or socket)")
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)
    assert not [n for n in os.listdir("/dev") if ".texsyn-tmp" in n]  # refused before writing
    os.mkfifo(tmp_path / "a.tsa")
    refuses(lambda: analysis.save(str(tmp_path / "a.tsa")), OSError,
            "exists and is not a regular file (a device, FIFO or socket)")
    assert stat.S_ISFIFO(os.stat(tmp_path / "a.tsa").st_mode)
    assert os.listdir(tmp_path) == ["a.tsa"]  # no temporary left behind


def test_colour_spaces_of_the_wrong_type(stucco):
    refuses(lambda: texsyn.pyramid(stucco, iscolorspace=5), ValueError,
            "iscolorspace= : expected a colour space name, or a list of one per input")
