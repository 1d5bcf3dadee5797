"""illum.read_image and illum.write_image: the library's formats, written atomically."""

import numpy as np
import pytest

import illum


@pytest.mark.parametrize("ext", [".exr", ".pfm"])
def test_linear_formats_round_trip_exactly(tmp_path, ext):
    pixels = np.random.default_rng(6).random((7, 9, 3), dtype=np.float32) * 10
    path = tmp_path / f"x{ext}"
    illum.write_image(path, pixels)
    assert np.array_equal(illum.read_image(path), pixels)
    assert [p.name for p in tmp_path.iterdir()] == [path.name]  # the temporary file was renamed


def test_png_is_tone_mapped(tmp_path):
    pixels = np.full((2, 3, 3), 0.5, dtype=np.float32)
    illum.write_image(tmp_path / "x.png", pixels, exposure=1.0)  # 0.5 * 2 = 1 after exposure: white
    np.testing.assert_allclose(illum.read_image(tmp_path / "x.png"), 1.0, atol=1e-6)
    illum.write_image(tmp_path / "y.png", pixels, tonemap="reinhard")
    np.testing.assert_allclose(illum.read_image(tmp_path / "y.png"), 1 / 3, atol=3e-3)  # x / (1 + x)


def test_any_layout_and_real_dtype_is_written(tmp_path):
    pixels = np.random.default_rng(7).random((5, 6, 3), dtype=np.float32)
    illum.write_image(tmp_path / "t.exr", np.ascontiguousarray(pixels.transpose(1, 0, 2)).transpose(1, 0, 2))
    assert np.array_equal(illum.read_image(tmp_path / "t.exr"), pixels)
    illum.write_image(tmp_path / "d.exr", pixels.astype(np.float64))
    assert np.array_equal(illum.read_image(tmp_path / "d.exr"), pixels)


def test_existing_file_survives_a_failed_write(tmp_path):
    path = tmp_path / "keep.exr"
    illum.write_image(path, np.ones((2, 2, 3), np.float32))
    before = path.read_bytes()
    with pytest.raises(ValueError):
        illum.write_image(path, np.ones((2, 2, 4), np.float32))
    assert path.read_bytes() == before
