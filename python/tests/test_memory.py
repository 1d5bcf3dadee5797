"""The arrays the module returns wrap the library's own Image, without a copy of the pixels."""

import gc
import tracemalloc

import numpy as np

import illum


def assert_wraps_an_image(a):
    assert a.dtype == np.float32 and a.flags.c_contiguous
    assert not a.flags.owndata  # NumPy did not allocate the pixels...
    assert type(a.base).__name__ == "PyCapsule"  # ...a capsule owns them,
    # and they are the Image's own buffer: a copy would live at another address.
    assert illum._image_data_address(a.base) == a.ctypes.data


def test_render_returns_the_image_itself():
    before = illum._live_images()
    a = illum.cornell_box().render(spp=1, resolution=(20, 10))
    assert_wraps_an_image(a)
    assert illum._live_images() == before + 1
    # A view shares the memory and keeps the Image alive after the array is gone; the last reference
    # frees it.
    view = a[2:5, ::2]
    assert np.shares_memory(view, a)
    a[3, 0, 1] = 42.0
    assert view[1, 0, 1] == 42.0
    del a
    gc.collect()
    assert illum._live_images() == before + 1
    assert view[1, 0, 1] == 42.0
    del view
    gc.collect()
    assert illum._live_images() == before


def test_no_pixel_memory_is_allocated_through_python():
    # NumPy reports its allocations to tracemalloc; the Image's pixels come from C++ and are not seen. A
    # copy of this 200 x 150 image (360 kB) would show up in the traced peak.
    scene = illum.cornell_box()
    scene.render(spp=1, resolution=(200, 150))  # builds the scene at this resolution first
    gc.collect()
    tracemalloc.start()
    try:
        a = scene.render(spp=1, resolution=(200, 150))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert a.nbytes == 200 * 150 * 12
    assert peak < a.nbytes / 10, peak
    assert_wraps_an_image(a)


def test_read_image_returns_the_image_itself(tmp_path):
    pixels = np.random.default_rng(1).random((5, 7, 3), dtype=np.float32)
    illum.write_image(tmp_path / "r.exr", pixels)
    a = illum.read_image(tmp_path / "r.exr")
    assert_wraps_an_image(a)
    assert np.array_equal(a, pixels)
