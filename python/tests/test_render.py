"""Scenes rendered from Python give the same pixels as `illum render` with the same arguments."""

import numpy as np
import pytest

import illum


def render_cli(cli, tmp_path, *args):
    out = tmp_path / "cli.pfm"  # float, exact (an EXR is half by default, as pbrt-v4 writes its film)
    r = cli("render", *args, "--quiet", "-o", out)
    assert r.returncode == 0, r.stderr
    return illum.read_image(out)


def test_cornell_box_identical_to_cli(cli, tmp_path):
    cli_pixels = render_cli(cli, tmp_path, "--spp", 4, "--seed", 7, "--resolution", "40x30")
    py_pixels = illum.cornell_box().render(spp=4, seed=7, resolution=(40, 30))
    assert py_pixels.shape == (30, 40, 3) and py_pixels.dtype == np.float32
    assert py_pixels.mean() > 0.01  # the scene is lit
    assert np.array_equal(py_pixels, cli_pixels)


def test_scene_file_identical_to_cli(cli, tmp_path, scene_file):
    # The scene's own spp, resolution and integrator (volpath), then overrides of each, and spectral mode.
    scene = illum.load(scene_file)
    assert scene.resolution == (48, 32) and scene.spp == 8 and scene.integrator == "volpath"
    assert np.array_equal(scene.render(seed=3), render_cli(cli, tmp_path, scene_file, "--seed", 3))
    assert np.array_equal(
        scene.render(spp=3, seed=11, resolution=(24, 20), integrator="path", max_depth=3),
        render_cli(cli, tmp_path, scene_file, "--spp", 3, "--seed", 11, "--resolution", "24x20",
                   "--integrator", "path", "--max-depth", 3))
    assert np.array_equal(scene.render(spp=2, seed=5, spectral=True),
                          render_cli(cli, tmp_path, scene_file, "--spp", 2, "--seed", 5, "--spectral"))


@pytest.mark.parametrize("integrator", ["bdpt", "lightpath", "sppm"])
def test_other_render_loops_identical_to_cli(cli, tmp_path, scene_file, integrator):
    # The integrators that run their own render loop (splatting, photon mapping), not the tiled one.
    scene = illum.load(scene_file)
    assert np.array_equal(scene.render(spp=2, seed=1, integrator=integrator, resolution=(24, 16)),
                          render_cli(cli, tmp_path, scene_file, "--spp", 2, "--seed", 1, "--integrator",
                                     integrator, "--resolution", "24x16"))


def test_threads_and_rebuilds_do_not_change_pixels():
    scene = illum.cornell_box()
    a = scene.render(spp=2, seed=1, resolution=(32, 24), threads=1)
    b = scene.render(spp=2, seed=1, resolution=(32, 24), threads=2)
    assert np.array_equal(a, b)
    # Another resolution rebuilds the scene; coming back gives the same image again.
    assert scene.render(spp=1, resolution=(8, 6)).shape == (6, 8, 3)
    assert np.array_equal(a, scene.render(spp=2, seed=1, resolution=(32, 24)))
    assert not np.array_equal(a, scene.render(spp=2, seed=2, resolution=(32, 24)))  # the seed matters


def test_stats():
    image, stats = illum.cornell_box().render(spp=2, resolution=(16, 8), stats=True)
    assert image.shape == (8, 16, 3)
    assert stats["spp"] == 2 and stats["samples"] == 16 * 8 * 2 and stats["integrator"] == "path"
    assert stats["mode"] == "rgb" and stats["rays"] > 0


def test_adaptive_identical_to_cli(cli, tmp_path):
    args = dict(spp=32, seed=5, resolution=(40, 30))
    cli_pixels = render_cli(cli, tmp_path, "--spp", 32, "--seed", 5, "--resolution", "40x30", "--adaptive")
    py_pixels, stats = illum.cornell_box().render(adaptive=True, stats=True, **args)
    assert np.array_equal(py_pixels, cli_pixels)
    assert not np.array_equal(py_pixels, illum.cornell_box().render(**args))
    assert stats["samples"] <= 40 * 30 * 32 and stats["adaptive"]["min_spp"] == 16
    with pytest.raises(ValueError):
        illum.cornell_box().render(spp=4, adaptive_threshold=-1.0)
    with pytest.raises(illum.Error):
        illum.cornell_box().render(spp=4, adaptive=True, integrator="sppm")


def test_render_releases_the_gil():
    # Two renders from two Python threads at once finish, and give what one thread alone gives.
    import threading
    scene = illum.cornell_box()
    alone = scene.render(spp=2, seed=4, resolution=(24, 24))
    results = [None, None]

    def work(i):
        results[i] = scene.render(spp=2, seed=4, resolution=(24, 24), threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(alone, r) for r in results)


def test_scene_seed_option_is_the_default_seed(cli, tmp_path, scene_file):
    # Option "seed" in the scene is the seed when none is given, in Python as on the command line; an
    # explicit seed wins in both.
    seeded = tmp_path / "seeded.pbrt"
    seeded.write_text('Option "seed" 9\n' + open(scene_file).read())
    scene = illum.load(seeded)
    assert np.array_equal(scene.render(), render_cli(cli, tmp_path, seeded))
    assert np.array_equal(scene.render(), illum.load(scene_file).render(seed=9))
    assert np.array_equal(scene.render(seed=0), render_cli(cli, tmp_path, seeded, "--seed", 0))
    assert not np.array_equal(scene.render(seed=0), scene.render())
