# SPDX-License-Identifier: Apache-2.0
"""Every function the module makes from the method registry runs, gives back what its
docstring says, and keeps what its method promises (docs/python.md, "Methods and their
keywords")."""
import inspect

import numpy as np
import OpenImageIO as oiio
import pytest

import texsyn
from conftest import DATA, read_pixels

# The methods this file runs: a method added to the registry must be added here too.
TESTED = {"pyramid", "solid", "mix", "transfer", "neighborhood", "choosy", "choosy_surface",
          "patch", "fill", "tileable", "material", "cascade", "analyze", "check"}


def test_every_registry_method_is_a_function_and_is_tested_here():
    assert set(texsyn.method_names) == TESTED
    for name in texsyn.method_names:
        f = getattr(texsyn, name)
        assert callable(f) and f.__name__ == name
        assert name in texsyn.__all__


def test_signatures_and_help_come_from_the_option_tables():
    sig = inspect.signature(texsyn.pyramid)
    assert list(sig.parameters)[0] == "sample"
    assert sig.parameters["sample"].kind is inspect.Parameter.POSITIONAL_ONLY
    assert sig.parameters["iterations"].default == 5  # PyramidOptions' default (the paper's)
    assert sig.parameters["orientations"].default == 4
    for common in ("seed", "threads", "progress", "colorconfig", "iscolorspace",
                   "tocolorspace"):
        assert sig.parameters[common].kind is inspect.Parameter.KEYWORD_ONLY
    assert "subbands" in sig.parameters
    doc = texsyn.pyramid.__doc__
    assert "iterations=5" in doc and "0..100" in doc and "texsyn " in doc
    # A written file (the source map) is returned, not a keyword.
    assert "map" not in inspect.signature(texsyn.patch).parameters
    assert "map= image" in texsyn.patch.__doc__


def test_pyramid_matches_the_samples_histogram(stucco):
    out = texsyn.pyramid(stucco, size=(64, 48), iterations=2, seed=3)
    assert out.shape == (48, 64, 3) and out.dtype == np.float32
    assert np.isfinite(out).all()
    # The last step matches each channel's histogram to the sample's: equal means within
    # what resampling 4096 quantiles onto 3072 pixels moves them.
    np.testing.assert_allclose(out.mean(axis=(0, 1)), stucco.mean(axis=(0, 1)), atol=2e-3)


def test_pyramid_subbands(stucco):
    out, bands = texsyn.pyramid(stucco, size=(64, 64), iterations=1, scales=2,
                                orientations=2, subbands=True)
    assert out.shape == (64, 64, 3)
    assert {"sample.s0.o0", "synth.s1.o1", "synth.highpass", "synth.lowpass"} <= set(bands)
    assert bands["synth.s0.o0"].shape == (64, 64, 3)
    assert all(b.dtype == np.float32 for b in bands.values())


def test_solid_is_a_volume(stucco):
    out = texsyn.solid(stucco, size=(16, 12, 8), iterations=1)
    assert out.shape == (8, 12, 16, 3) and out.dtype == np.float32
    assert np.isfinite(out).all()


def test_mix_takes_its_palette_from_the_palette_sample(stucco, samples):
    rust = read_pixels(samples["rust.png"], oiio.UINT8)
    out = texsyn.mix([stucco, rust], palette=0, pattern=1, size=(32, 32), iterations=1)
    assert out.shape == (32, 32, 3) and out.dtype == np.float32  # the palette's form
    out = texsyn.mix([rust, stucco], palette=0, pattern=1, size=(32, 32), iterations=1)
    assert out.shape == (32, 32, 3) and out.dtype == np.uint8


def test_transfer_keeps_the_images_layout(stucco, bricks):
    out = texsyn.transfer(bricks, stucco, iterations=1)
    assert out.shape == bricks.shape and out.dtype == np.float32


@pytest.mark.parametrize("method, options", [
    ("neighborhood", dict(size=(32, 32), levels=2)),
    ("choosy", dict(size=(32, 32), levels=2)),
    ("patch", dict(size=(48, 48))),
])
def test_copying_methods_return_their_source_map(stucco, method, options):
    out, coords = getattr(texsyn, method)(stucco, seed=1, **options)
    width, height = options["size"]
    assert out.shape == (height, width, 3)
    assert coords.shape == out.shape[:2] + (2,) and coords.dtype == np.float32
    assert (coords >= 0).all() and (coords < 64).all()
    # Every pixel is a sample pixel: the map re-applied to the sample gives the result.
    assert np.array_equal(texsyn.apply_map(coords, stucco), out)


def test_a_turned_source_map_array_turns_normal_maps(bricks, bricks_normal):
    # isotropic=1 gives a three-channel array (x, y, t); apply_map takes it as it is.
    maps, coords = texsyn.patch({"albedo": bricks, "normal": bricks_normal}, size=(48, 48),
                                isotropic=1, seed=2)
    assert coords.shape == (48, 48, 3)
    assert np.array_equal(texsyn.apply_map(coords, bricks_normal, normal="opengl"),
                          maps["normal"])


def twice(image):
    """`image` at twice its size, each pixel a 2 x 2 block."""
    return np.repeat(np.repeat(image, 2, axis=0), 2, axis=1)


def test_apply_map_scales_to_another_size_and_copies_values_exactly(stucco):
    out, coords = texsyn.neighborhood(stucco, size=(16, 16), levels=1, seed=2)
    # A map at twice the sample's size: each pixel's 2 x 2 block is copied whole.
    applied = texsyn.apply_map(coords, twice(stucco), sample_size=(64, 64))
    assert applied.shape == (32, 32, 3)
    assert np.array_equal(applied, twice(out))


def test_fill_keeps_every_pixel_outside_the_mask(bricks):
    mask = np.zeros(bricks.shape[:2], np.float32)
    mask[36:60, 36:60] = 1
    out, coords = texsyn.fill(bricks, mask=mask, patch=(7, 5), seed=1)
    assert out.shape == bricks.shape and out.dtype == np.float32
    keep = mask == 0
    assert np.array_equal(out[keep], bricks[keep])
    assert not np.array_equal(out[~keep], bricks[~keep])
    # The source map: x, y and the mask as m; each kept pixel its own position, and applied
    # to the image it gives the fill (outline=copy: exact copies, no offsets).
    assert coords.shape == bricks.shape[:2] + (3,)
    ys, xs = np.nonzero(keep)
    assert np.array_equal(coords[ys, xs, 0], xs) and np.array_equal(coords[ys, xs, 1], ys)
    assert np.array_equal(coords[:, :, 2], mask)
    copied, _ = texsyn.fill(bricks, mask=mask, patch=(7, 5), seed=1, outline="copy")
    assert np.array_equal(texsyn.apply_map(coords, bricks), copied)


def test_fill_from_a_sample_has_no_source_map(bricks):
    mask = np.zeros(bricks.shape[:2], np.float32)
    mask[36:60, 36:60] = 1
    out, coords = texsyn.fill(bricks, mask=mask, sample=bricks, patch=(7, 5), seed=1)
    assert out.shape == bricks.shape and coords is None


def test_tileable_keeps_everything_outside_its_band(bricks):
    out = texsyn.tileable(bricks, band=12, patch=(7, 5), seed=1)
    assert out.shape == bricks.shape
    inner = (slice(12, -12), slice(12, -12))
    assert np.array_equal(out[inner], bricks[inner])
    assert not np.array_equal(out, bricks)


def test_a_material_set_moves_every_map_with_one_source_map(bricks, bricks_height):
    material = texsyn.material(bricks, height=bricks_height)
    assert isinstance(material, texsyn.Material)
    assert material.names == ["albedo", "height"]
    maps, coords = texsyn.patch(material, size=(48, 48), seed=3)
    assert set(maps) == {"albedo", "height"}
    assert maps["albedo"].dtype == np.float32 and maps["height"].dtype == np.uint8
    assert np.array_equal(maps["height"], texsyn.apply_map(coords, bricks_height))
    # A dict of maps is the same material set.
    same, same_coords = texsyn.patch({"albedo": bricks, "height": bricks_height},
                                     size=(48, 48), seed=3)
    assert np.array_equal(same_coords, coords)
    assert np.array_equal(same["height"], maps["height"])


def test_cascade_generates_without_an_input():
    grey = texsyn.cascade(size=(64, 32), seed=2)
    assert grey.shape == (32, 64, 1) and grey.dtype == np.float32
    cells = texsyn.cascade(size=(32, 32), preset="cells", seed=2)
    assert cells.shape == (32, 32, 3)
    # The logistic map keeps values in [0, r/4].
    assert grey.min() >= 0 and grey.max() <= 3.9 / 4 + 1e-6


def test_analyze_gives_an_analysis_that_synthesizes_like_its_sample(stucco, tmp_path):
    analysis = texsyn.analyze(stucco)
    assert isinstance(analysis, texsyn.Analysis)
    assert analysis.size == (64, 64)
    assert analysis.channelnames == ["R", "G", "B"]
    path = tmp_path / "stucco.tsa"
    analysis.save(str(path))
    loaded = texsyn.Analysis.load(str(path))
    assert loaded.size == (64, 64)
    # At the sample's size (the analysis fixes the pyramid's scales; a smaller size would
    # choose fewer from the sample).
    direct = texsyn.pyramid(stucco, size=(64, 64), iterations=1, seed=4)
    assert np.array_equal(texsyn.pyramid(analysis, size=(64, 64), iterations=1, seed=4), direct)
    assert np.array_equal(texsyn.pyramid(loaded, size=(64, 64), iterations=1, seed=4), direct)


def test_check_reports_as_text(stucco):
    report = texsyn.check(stucco)
    assert isinstance(report, str)
    assert "homogeneity score" in report and "illumination gradient" in report


def test_choosy_surface_grows_a_texture_on_a_mesh(stucco, tmp_path):
    surface = texsyn.choosy_surface(stucco, mesh=str(DATA / "meshes" / "sphere.obj"), levels=1,
                                    seed=1)
    assert isinstance(surface, texsyn.Surface)
    faces, vertices, colours = surface.faces, surface.vertices, surface.colours
    assert faces.shape[1] == 3 and vertices.shape[1] == 3
    assert colours.shape == (faces.shape[0], 3) and colours.dtype == np.float32
    assert faces.max() < vertices.shape[0]
    assert surface.bakes == {}  # the sphere has no UVs
    surface.write_ply(str(tmp_path / "sphere.ply"))
    assert (tmp_path / "sphere.ply").read_bytes().startswith(b"ply\n")
