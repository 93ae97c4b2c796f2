# SPDX-License-Identifier: Apache-2.0
"""Images in and out (docs/python.md, "What goes in and what comes out"): numpy arrays,
OpenImageIO ImageBufs (Debian's python3-openimageio) and file names; uint8, uint16 and float
pixels; H x W arrays; arrays in the other byte order or not contiguous."""
import pathlib

import numpy as np
import OpenImageIO as oiio
import pytest

import texsyn

SMALL = dict(size=(32, 32), iterations=1, seed=5)


def test_a_float_array_gives_a_float32_array(stucco_linear):
    out = texsyn.pyramid(stucco_linear, **SMALL)
    assert isinstance(out, np.ndarray)
    assert out.shape == (32, 32, 3) and out.dtype == np.float32


def test_a_file_name_is_read_as_the_tool_reads_it(samples, stucco_linear):
    from_str = texsyn.pyramid(str(samples["stucco.png"]), **SMALL)
    from_path = texsyn.pyramid(pathlib.Path(samples["stucco.png"]), **SMALL)
    assert from_str.dtype == np.float32 and from_str.shape == (32, 32, 3)
    assert np.array_equal(from_str, from_path)
    # Scene-linear: the same as the sample converted to linear first. OIIO's own OCIO
    # conversion may differ from texsyn's in the last bit of a value.
    np.testing.assert_allclose(texsyn.pyramid(stucco_linear, **SMALL), from_str, atol=1e-5)


def test_an_imagebuf_gives_an_imagebuf_of_its_type_with_the_synth_metadata(samples, stucco_u8):
    buf = oiio.ImageBuf(str(samples["stucco.png"]))
    out = texsyn.pyramid(buf, **SMALL)
    assert isinstance(out, oiio.ImageBuf)
    spec = out.spec()
    assert (spec.width, spec.height, spec.nchannels) == (32, 32, 3)
    assert spec.format == oiio.UINT8
    assert spec.get_string_attribute("synth:method") == "pyramid"
    assert spec.get_int_attribute("synth:seed") == 5
    assert spec.get_string_attribute("synth:sample") == "stucco.png"  # the file, by name
    assert "size=32x32" in spec.get_string_attribute("synth:options")
    assert spec.get_string_attribute("synth:version") == texsyn.__version__
    assert spec.get_string_attribute("synth:colorspace") == "sRGB - Texture"
    # The same pixels as from the file's encoded values in an array.
    assert np.array_equal(out.get_pixels(oiio.UINT8), texsyn.pyramid(stucco_u8, **SMALL))


def test_an_imagebuf_result_is_an_ordinary_imagebuf(stucco_linear, tmp_path):
    spec = oiio.ImageSpec(64, 64, 3, oiio.FLOAT)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), stucco_linear)
    out = texsyn.pyramid(buf, **SMALL)
    assert out.spec().format == oiio.FLOAT
    assert out.spec().get_string_attribute("synth:sample") == "sample"  # no file behind it
    assert np.array_equal(out.get_pixels(oiio.FLOAT), texsyn.pyramid(stucco_linear, **SMALL))
    # OIIO's own algorithms and writers take it.
    assert out.write(str(tmp_path / "out.exr"))
    back = oiio.ImageBuf(str(tmp_path / "out.exr"))
    assert np.array_equal(back.get_pixels(oiio.FLOAT), out.get_pixels(oiio.FLOAT))
    assert back.spec().get_string_attribute("synth:method") == "pyramid"
    assert oiio.ImageBufAlgo.computePixelStats(out).max[0] > 0


def test_a_windowed_imagebuf_is_read_from_its_origin(stucco_linear):
    spec = oiio.ImageSpec(64, 64, 3, oiio.FLOAT)
    spec.x, spec.y = 10, 20
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(10, 74, 20, 84), stucco_linear)
    assert np.array_equal(texsyn.pyramid(buf, **SMALL).get_pixels(oiio.FLOAT),
                          texsyn.pyramid(stucco_linear, **SMALL))


def test_uint8_and_uint16_arrays_are_their_encoded_values(stucco_u8):
    u8 = texsyn.pyramid(stucco_u8, **SMALL)
    assert u8.dtype == np.uint8
    u16 = texsyn.pyramid(stucco_u8.astype(np.uint16) * 257, **SMALL)  # the same values
    assert u16.dtype == np.uint16
    # The same synthesis, rounded to 8 and to 16 bits.
    assert np.abs(u16 / 257.0 - u8).max() <= 0.5 + 1e-9
    # Floats of the same encoded values, said to be sRGB and asked back as sRGB.
    f = texsyn.pyramid(stucco_u8 / np.float32(255), iscolorspace="sRGB - Texture",
                       tocolorspace="sRGB - Texture", **SMALL)
    assert f.dtype == np.float32
    assert np.abs(f * 255 - u8).max() <= 0.5 + 1e-3  # rounding, and float's last bits


def test_float16_and_float64_arrays(stucco_linear):
    half = stucco_linear.astype(np.float16)
    f16 = texsyn.pyramid(half, **SMALL)
    assert f16.dtype == np.float16
    # Read by value, and the float result rounded to half on the way out.
    assert np.array_equal(f16, texsyn.pyramid(half.astype(np.float32), **SMALL).astype(np.float16))
    f32 = texsyn.pyramid(stucco_linear, **SMALL)
    f64 = texsyn.pyramid(stucco_linear.astype(np.float64), **SMALL)
    assert f64.dtype == np.float32  # the library works in float32
    assert np.array_equal(f64, f32)


def test_an_h_x_w_array_gives_an_h_x_w_array(stucco_linear):
    grey = np.ascontiguousarray(stucco_linear[:, :, 1])
    out = texsyn.pyramid(grey, **SMALL)
    assert out.shape == (32, 32)
    assert np.array_equal(out, texsyn.pyramid(grey[:, :, None], **SMALL)[:, :, 0])
    image, coords = texsyn.patch(grey, size=(32, 32), seed=1)
    assert image.shape == (32, 32) and coords.shape == (32, 32, 2)
    assert texsyn.apply_map(coords, grey).shape == (32, 32)


@pytest.mark.parametrize("dtype", ["f4", "u2", "f2"])
def test_arrays_in_the_other_byte_order_are_read_by_value(stucco_linear, dtype):
    native = (stucco_linear * (65535 if dtype == "u2" else 1)).astype("=" + dtype)
    swapped = native.astype(">" + dtype if np.little_endian else "<" + dtype)
    out = texsyn.pyramid(swapped, **SMALL)
    assert out.dtype.isnative and out.dtype.kind == native.dtype.kind
    assert np.array_equal(out, texsyn.pyramid(native, **SMALL))


def test_strided_and_read_only_arrays_and_inputs_left_unchanged(stucco_linear):
    wide = np.zeros((64, 128, 3), np.float32)
    wide[:, ::2] = stucco_linear
    view = wide[:, ::2]  # every other column: not contiguous
    assert not view.flags.c_contiguous
    frozen = stucco_linear.copy()
    frozen.flags.writeable = False
    before = wide.copy()
    expected = texsyn.pyramid(stucco_linear, **SMALL)
    assert np.array_equal(texsyn.pyramid(view, **SMALL), expected)
    assert np.array_equal(texsyn.pyramid(frozen, **SMALL), expected)
    assert np.array_equal(wide, before)


@pytest.mark.parametrize("channels", [1, 2, 4, 5])
def test_every_channel_count(stucco_linear, channels):
    sample = np.concatenate([stucco_linear, stucco_linear[:, :, :2]], axis=2)[:, :, :channels]
    if channels in (2, 4):  # alpha: opaque
        sample = sample.copy()
        sample[:, :, -1] = 1
    out = texsyn.pyramid(np.ascontiguousarray(sample), **SMALL)
    assert out.shape == (32, 32, channels)
    assert np.isfinite(out).all()


def test_option_images_take_every_kind(bricks, tmp_path):
    mask = np.zeros(bricks.shape[:2], np.float32)
    mask[40:56, 40:56] = 1
    mask_buf = oiio.ImageBuf(oiio.ImageSpec(96, 96, 1, oiio.FLOAT))
    assert mask_buf.set_pixels(oiio.ROI(), mask[:, :, None])
    mask_buf.write(str(tmp_path / "mask.exr"))
    options = dict(patch=(7, 5), seed=2)
    from_array = texsyn.fill(bricks, mask=mask, **options)[0]
    assert not np.array_equal(from_array, bricks)
    assert np.array_equal(texsyn.fill(bricks, mask=mask_buf, **options)[0], from_array)
    assert np.array_equal(texsyn.fill(bricks, mask=str(tmp_path / "mask.exr"), **options)[0],
                          from_array)
    assert np.array_equal(texsyn.fill(bricks, mask=tmp_path / "mask.exr", **options)[0],
                          from_array)


def test_apply_map_gives_back_the_images_kind(samples, bricks_height, tmp_path):
    bricks_buf = oiio.ImageBuf(str(samples["bricks.png"]))
    image, coords = texsyn.patch(bricks_buf, size=(48, 48), seed=1)
    assert isinstance(image, oiio.ImageBuf) and isinstance(coords, oiio.ImageBuf)
    assert coords.spec().get_string_attribute("synth:sample_size") == "96x96"
    height = texsyn.apply_map(coords, bricks_height)
    assert height.dtype == np.uint8 and height.shape == (48, 48, 1)
    assert coords.write(str(tmp_path / "coords.exr"))
    assert np.array_equal(texsyn.apply_map(str(tmp_path / "coords.exr"), bricks_height), height)
    again = texsyn.apply_map(coords, bricks_buf)
    assert isinstance(again, oiio.ImageBuf)
    assert np.array_equal(again.get_pixels(oiio.UINT8), image.get_pixels(oiio.UINT8))


def test_sequences_whose_items_are_made_as_they_are_read(stucco, bricks):
    """An array's rows are new objects each time they are read: the samples of a stacked
    array, and a size given as an array, are held while the call uses them."""
    pair = [stucco, np.ascontiguousarray(bricks[:64, :64])]
    options = dict(palette=0, pattern=1, iterations=1, seed=1)
    from_list = texsyn.mix(pair, size=(32, 32), **options)
    assert np.array_equal(texsyn.mix(np.stack(pair), size=(32, 32), **options), from_list)
    assert np.array_equal(texsyn.mix(pair, size=np.array([32, 32]), **options), from_list)
    assert np.array_equal(texsyn.mix(tuple(pair), size=(32, 32), **options), from_list)
