"""Errors: illum.Error (a ValueError) with the CLI's message and position for scene errors; ValueError with
a message for bad arguments; never a crash of the interpreter."""

import numpy as np
import pytest

import illum


def cli_error(cli, *args):
    r = cli(*args)
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip().splitlines()[-1]
    assert line.startswith("error: ")
    return line[len("error: "):]


def test_broken_scene_names_file_line_column(cli, tmp_path):
    path = tmp_path / "broken.pbrt"
    path.write_text('WorldBegin\nMaterial "diffuse"\n  Material "foo"\nShape "sphere"\n')
    with pytest.raises(illum.Error) as e:
        illum.load(path)
    assert isinstance(e.value, ValueError)
    assert str(e.value) == f'{path}:3:3: unknown material type "foo"'
    assert (e.value.file, e.value.line, e.value.column) == (str(path), 3, 3)
    assert e.value.message == 'unknown material type "foo"'
    assert str(e.value) == cli_error(cli, "render", path, "-o", tmp_path / "x.exr")
    assert not (tmp_path / "x.exr").exists()


def test_build_error_and_missing_file_as_the_cli(cli, tmp_path):
    path = tmp_path / "count.pbrt"
    path.write_text('WorldBegin\nShape "sphere" "float radius" [1 2]\n')
    with pytest.raises(illum.Error, match=":2:16: ") as e:
        illum.load(str(path))
    assert str(e.value) == cli_error(cli, "render", path, "-o", tmp_path / "x.exr")
    missing = tmp_path / "missing.pbrt"
    with pytest.raises(illum.Error) as e:
        illum.load(missing)
    assert str(e.value) == cli_error(cli, "render", missing, "-o", tmp_path / "x.exr")
    assert e.value.line == 0 and e.value.file == ""


def test_strict_makes_warnings_errors(tmp_path):
    path = tmp_path / "u.pbrt"
    path.write_text('Film "rgb" "integer xresolution" [8] "integer yresolution" [8]\n'
                    'WorldBegin\nShape "sphere" "float radius" [1] "float radiuss" [2]\n')
    with pytest.warns(UserWarning, match='u.pbrt:3:35: shape "sphere": parameter "float radiuss" is not used'):
        scene = illum.load(path)
    assert len(scene.warnings) == 1
    with pytest.raises(illum.Error, match="u.pbrt:3:35:"):
        illum.load(path, strict=True)


def test_unknown_integrator_and_sampler_as_the_cli(cli, tmp_path):
    scene = illum.cornell_box()
    for option, kwargs in [("--integrator", {"integrator": "foo"}), ("--sampler", {"sampler": "foo"})]:
        with pytest.raises(illum.Error) as e:
            scene.render(spp=1, resolution=(4, 4), **kwargs)
        assert str(e.value) == cli_error(cli, "render", option, "foo", "--spp", 1, "--resolution", "4x4",
                                         "-q", "-o", tmp_path / "x.exr")


@pytest.mark.parametrize("kwargs,message", [
    ({"spp": -1}, "spp must be a positive whole number, not -1"),
    ({"spp": 0}, "spp must be a positive whole number, not 0"),
    ({"spp": 2.5}, "spp must be a positive whole number, not 2.5"),
    ({"spp": "4"}, "spp must be a positive whole number, not '4'"),
    ({"spp": 2**40}, "spp must be a positive whole number"),
    ({"resolution": (0, 10)}, "resolution's width must be a positive whole number, not 0"),
    ({"resolution": (10, -3)}, "resolution's height must be a positive whole number, not -3"),
    ({"resolution": (10,)}, "resolution must be (width, height)"),
    ({"resolution": "64x48"}, "resolution must be (width, height)"),
    ({"resolution": (10.5, 3)}, "resolution's width must be a positive whole number, not 10.5"),
    ({"resolution": 64}, "resolution must be (width, height)"),
    ({"seed": -1}, "seed must be a whole number in [0, 2^64), not -1"),
    ({"seed": 2**64}, "seed must be a whole number in [0, 2^64)"),
    ({"threads": 0}, "threads must be a positive whole number, not 0"),
    ({"max_depth": -2}, "max_depth must be a whole number in [-1, 100000]"),
    ({"time": -1.0}, "time must be a positive number of seconds"),
])
def test_bad_render_arguments_raise_value_error(kwargs, message):
    scene = illum.cornell_box()
    with pytest.raises(ValueError) as e:
        scene.render(**kwargs)
    assert message in str(e.value)


def test_numpy_integers_are_accepted():
    a = illum.cornell_box().render(spp=np.int64(1), resolution=np.array([6, 4]), seed=np.uint64(3))
    assert a.shape == (4, 6, 3)


def test_bad_images_raise_value_error(tmp_path):
    good = np.zeros((4, 5, 3), dtype=np.float32)
    for array, message in [(np.zeros((4, 5, 4), np.float32), "shape (height, width, 3), not (4, 5, 4)"),
                           (np.zeros((4, 5), np.float32), "not (4, 5)"),
                           (np.zeros((0, 5, 3), np.float32), "is empty"),
                           (good.astype(complex), "real numbers, not dtype complex128"),
                           (np.array([[["a", "b", "c"]]]), "real numbers"),
                           ("not an image", "real numbers")]:
        with pytest.raises(ValueError, match="the image ") as e:
            illum.write_image(tmp_path / "x.exr", array)
        assert message in str(e.value)
    with pytest.raises(ValueError, match='unknown tone map "filmic"'):
        illum.write_image(tmp_path / "x.png", good, tonemap="filmic")
    with pytest.raises(illum.Error, match='unknown image extension ".tiff"'):
        illum.write_image(tmp_path / "x.tiff", good)
    with pytest.raises(illum.Error, match="cannot write"):
        illum.write_image(tmp_path / "no-such-folder" / "x.exr", good)
    with pytest.raises(illum.Error, match="missing.exr"):
        illum.read_image(tmp_path / "missing.exr")
    assert not list(tmp_path.iterdir())  # nothing written, no temporary file left
