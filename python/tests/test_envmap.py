"""illum.envmap.sh against closed forms and `illum envmap sh`."""

import math

import numpy as np
import pytest

import illum
from illum import envmap

Y1 = math.sqrt(3 / (4 * math.pi))  # 0.488603: the band-1 basis functions are Y1 * (y, z, x)


def latlong_z(height):
    """cos θ at the texel centres of a latlong map (rows from the +z pole down)."""
    theta = (np.arange(height) + 0.5) / height * math.pi
    return np.cos(theta)[:, None] * np.ones((1, 2 * height))


def l20_of_constant(height):
    """L20 of a constant latlong map of radiance 1 by the projection's rule (Y at the texel centres, exact
    solid angles): 0.315392 Σ_rows 2π (cos θ0 - cos θ1) (3 cos² θc - 1). The integral is 0; the rule's error
    falls as 1/height²."""
    edges = np.arange(height + 1) / height * math.pi
    centres = (np.arange(height) + 0.5) / height * math.pi
    rings = 2 * math.pi * (np.cos(edges[:-1]) - np.cos(edges[1:]))
    return 0.315392 * np.sum(rings * (3 * np.cos(centres) ** 2 - 1))


def parse_cli_sh(stdout):
    rows = [line.split() for line in stdout.splitlines()[1:]]
    assert [r[0] for r in rows] == list(envmap.SH_NAMES)
    return np.array([[float(x) for x in r[1:]] for r in rows])


def test_constant_map_has_only_the_dc_coefficient(cli, tmp_path):
    # L constant: L00 = L ∫ Y00 dω = L 4π / sqrt(4π) = 2 sqrt(π) L, every other coefficient 0 (bands 1 and
    # the other band-2 ones by symmetry exactly; L20 up to the texel-centre rule, which is known exactly).
    colour = np.array([1.0, 2.0, 0.5], dtype=np.float32)
    path = tmp_path / "constant.exr"
    illum.write_image(path, np.broadcast_to(colour, (16, 32, 3)))
    sh = envmap.sh(path)
    assert sh.shape == (9, 3) and sh.dtype == np.float64
    np.testing.assert_allclose(sh[0], 2 * math.sqrt(math.pi) * colour, rtol=1e-5)
    np.testing.assert_allclose(sh[6], l20_of_constant(16) * colour, rtol=1e-5)
    assert 0 < l20_of_constant(256) < l20_of_constant(16) / 200 < 1e-4  # the rule converges as 1/h²
    assert np.abs(np.delete(sh, [0, 6], axis=0)).max() < 1e-6
    # As the CLI prints it (6 significant digits).
    r = cli("envmap", "sh", path)
    assert r.returncode == 0, r.stderr
    np.testing.assert_allclose(sh, parse_cli_sh(r.stdout), rtol=5e-6, atol=1e-6)


def test_linear_map_has_dc_and_l10():
    # L = 1 + z: L00 = 2 sqrt(π), L10 = Y1 ∫ z² dω = Y1 4π/3; the rest 0 (up to the texel-centre rule,
    # which gives L00 exactly and the others to about 1/height²).
    z = latlong_z(64)
    sh = envmap.sh(np.repeat((1 + z)[:, :, None], 3, axis=2))
    np.testing.assert_allclose(sh[0], 2 * math.sqrt(math.pi), rtol=1e-5)
    np.testing.assert_allclose(sh[2], Y1 * 4 * math.pi / 3, rtol=1e-3)
    assert np.abs(np.delete(sh, [0, 2], axis=0)).max() < 1e-3


def test_array_and_file_agree(tmp_path):
    rng = np.random.default_rng(5)
    pixels = rng.random((8, 16, 3), dtype=np.float32)
    illum.write_image(tmp_path / "m.pfm", pixels)
    assert np.array_equal(envmap.sh(tmp_path / "m.pfm"), envmap.sh(pixels))
    assert np.array_equal(envmap.sh(str(tmp_path / "m.pfm"), layout="latlong"), envmap.sh(pixels))


def test_envmap_errors(tmp_path):
    with pytest.raises(ValueError, match='unknown layout "sphere"'):
        envmap.sh(np.ones((8, 16, 3)), layout="sphere")
    with pytest.raises(illum.Error, match="must be 2:1 \\(latlong\\)"):
        envmap.sh(np.ones((8, 13, 3)))
    with pytest.raises(illum.Error, match="high-dynamic-range"):
        envmap.sh(tmp_path / "m.png")
    with pytest.warns(UserWarning, match="the map is black"):
        assert not envmap.sh(np.zeros((8, 16, 3))).any()
