"""illum.brdf: the registry's models over arrays of directions, against closed forms, the CLI
(`illum brdf eval --json`, `illum brdf albedo`) and a Python loop over single evaluations."""

import json
import math

import numpy as np
import pytest

import illum
from illum import brdf


def direction_deg(theta, phi):
    """As the CLI's --wi/--wo θ,φ in degrees (bsdf/albedo.cpp's direction_deg, in double)."""
    t, p = math.radians(theta), math.radians(phi)
    return [math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)]


def random_directions(rng, n, upper=True):
    v = rng.normal(size=(n, 3))
    if upper:
        v[:, 2] = np.abs(v[:, 2])
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_models_are_the_registry():
    names = brdf.models()
    assert names[0] == "lambert" and {"rough-conductor", "ward", "coated-diffuse", "merl"} <= set(names)
    d = brdf.describe("lambert")
    assert d["params"][0]["name"] == "reflectance" and d["params"][0]["default"] == "0.5"


def test_lambert_is_albedo_over_pi_exactly():
    rng = np.random.default_rng(1)
    wi, wo = random_directions(rng, 1000), random_directions(rng, 1000)
    rho = np.array([0.2, 0.5, 0.9], dtype=np.float32)
    f = brdf.eval("lambert", {"reflectance": [0.2, 0.5, 0.9]}, wi, wo)
    assert f.shape == (1000, 3) and f.dtype == np.float32
    assert np.array_equal(f, np.broadcast_to(rho * np.float32(1 / math.pi), f.shape))
    # Opposite hemispheres: no reflection. One (3,) direction is used for every row.
    below = wi * [1, 1, -1]
    assert not brdf.eval("lambert", {}, below, [0, 0, 1]).any()
    assert brdf.eval("lambert", {}, [0, 0, 1], [0, 0, 1]).shape == (3,)


@pytest.mark.parametrize("model,params", [
    ("rough-conductor", {"alpha": 0.2}),
    ("ward", {"rho_d": "0.1,0.2,0.3", "alpha_x": 0.3, "alpha_y": 0.1}),
    ("oren-nayar", {"sigma": 20}),
    ("rough-dielectric", {"alpha": 0.25, "eta": 1.33}),
    ("coated-diffuse", {}),  # stochastic: the estimate is a deterministic function of the directions
])
def test_eval_and_pdf_agree_with_cli(cli, model, params):
    pairs = [((30, 0), (45, 180)), ((60, 90), (10, 200)), ((80, 10), (75, 190)), ((150, 20), (40, 180))]
    wi = [direction_deg(*a) for a, _ in pairs]
    wo = [direction_deg(*b) for _, b in pairs]
    m = brdf.Model(model, params)
    f, pdf = m.eval(wi, wo), m.pdf(wi, wo)
    for i, (a, b) in enumerate(pairs):
        args = ["brdf", "eval", model, "--wi", f"{a[0]},{a[1]}", "--wo", f"{b[0]},{b[1]}", "--json"]
        for k, v in params.items():
            args += ["-p", f"{k}={v}"]
        r = cli(*args)
        assert r.returncode == 0, r.stderr
        expected = json.loads(r.stdout)
        np.testing.assert_allclose(f[i], expected["f"], rtol=1e-6, atol=0)
        np.testing.assert_allclose(pdf[i], expected["pdf"], rtol=1e-6, atol=0)
    assert f[:3].any()  # the reflection pairs are lit


def test_importance_mode_differs_for_refraction():
    wi, wo = direction_deg(150, 0), direction_deg(40, 180)
    rad = brdf.eval("rough-dielectric", {"eta": 1.5}, wi, wo, mode="radiance")
    imp = brdf.eval("rough-dielectric", {"eta": 1.5}, wi, wo, mode="importance")
    assert rad[0] > 0 and imp[0] > 0 and not np.allclose(rad, imp)


def test_lambert_sampling_weight_is_the_albedo():
    rng = np.random.default_rng(2)
    n = 10000
    s = brdf.sample("lambert", {"reflectance": 0.3}, random_directions(rng, n), rng.random((n, 2)))
    assert s["valid"].all()
    assert s["wi"].shape == (n, 3) and (s["wi"][:, 2] > 0).all()
    np.testing.assert_allclose(s["weight"], 0.3, rtol=1e-5)
    np.testing.assert_allclose(s["pdf"], s["wi"][:, 2] / math.pi, rtol=1e-5)
    assert (s["flags"] == brdf.REFLECTION | brdf.DIFFUSE).all()


def test_sample_agrees_with_eval_and_pdf():
    rng = np.random.default_rng(3)
    n = 5000
    m = brdf.Model("rough-conductor", {"alpha": 0.3})
    wo = random_directions(rng, n)
    s = m.sample(wo, rng.random((n, 2)), uc=rng.random(n))
    ok = s["valid"]
    assert ok.mean() > 0.9
    np.testing.assert_allclose(s["f"][ok], m.eval(s["wi"][ok], wo[ok]), rtol=1e-4)
    np.testing.assert_allclose(s["pdf"][ok], m.pdf(s["wi"][ok], wo[ok]), rtol=1e-4)
    cos = np.abs(s["wi"][ok, 2])[:, None]
    np.testing.assert_allclose(s["weight"][ok], s["f"][ok] * cos / s["pdf"][ok, None], rtol=1e-5)
    # Failed samples are zero throughout.
    assert not s["f"][~ok].any() and not s["pdf"][~ok].any() and not s["wi"][~ok].any()


def test_dielectric_lobe_choice():
    # A smooth dielectric chooses reflection or refraction by uc: both occur with a stream of uc, and the
    # default stream (seed) is deterministic.
    n = 4000
    wo, u = np.tile(direction_deg(30, 0), (n, 1)), np.full((n, 2), 0.5)
    s = brdf.sample("dielectric", {"eta": 1.5}, wo, u)
    refl = (s["flags"] & brdf.REFLECTION) != 0
    assert (s["flags"] & brdf.SPECULAR).all() and 0.01 < refl.mean() < 0.2  # Fresnel at 30°: about 4%
    assert np.array_equal(s["wi"], brdf.sample("dielectric", {"eta": 1.5}, wo, u)["wi"])
    assert not np.array_equal(s["wi"], brdf.sample("dielectric", {"eta": 1.5}, wo, u, seed=1)["wi"])
    np.testing.assert_allclose(s["eta"][~refl], 1.5)


def test_albedo_agrees_with_cli(cli):
    r = cli("brdf", "albedo", "rough-conductor", "-p", "alpha=0.2", "--theta", "0,60", "--samples", 20000,
            "--quad", 64, "--seed", 3)
    assert r.returncode == 0, r.stderr
    rows = [line.split() for line in r.stdout.splitlines() if not line.startswith("#")][1:]
    a = brdf.albedo("rough-conductor", {"alpha": 0.2}, [0, 60], samples=20000, quad=64, seed=3)
    for i, row in enumerate(rows):
        np.testing.assert_allclose(a["quadrature"][i], [float(x) for x in row[1:4]], atol=5.1e-5)
        np.testing.assert_allclose(a["mc"][i], [float(x) for x in row[4:7]], atol=5.1e-5)
        np.testing.assert_allclose(a["mc_stderr"][i], [float(x) for x in row[8:11]], atol=5.1e-5)
    lam = brdf.albedo("lambert", {"reflectance": 0.7}, 45, samples=1000, quad=64)
    assert lam["quadrature"].shape == (3,)
    np.testing.assert_allclose(lam["quadrature"], 0.7, rtol=1e-3)
    assert brdf.albedo("mirror", {}, 10, samples=1000)["quadrature"] is None  # a delta model


def test_vectorised_eval_is_the_single_calls():
    # The vectorised call evaluates each row as a single call does: the same floats. (How much time it
    # saves is a benchmark's question, not a test's: python/bench/brdf_vectorised.py.)
    rng = np.random.default_rng(4)
    wi, wo = random_directions(rng, 200), random_directions(rng, 200)
    for model, params in [("lambert", {}), ("rough-conductor", {"alpha": 0.2}), ("ward", {})]:
        f = brdf.eval(model, params, wi, wo)
        for i in range(len(wi)):
            assert np.array_equal(f[i], brdf.eval(model, params, wi[i], wo[i])), (model, i)


def test_the_speed_benchmark_runs(capsys):
    # python/bench/brdf_vectorised.py, on a few directions: it stays runnable (its figures are not checked).
    import importlib.util
    import pathlib
    path = pathlib.Path(__file__).resolve().parents[1] / "bench" / "brdf_vectorised.py"
    spec = importlib.util.spec_from_file_location("brdf_vectorised", path)
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    bench.main(n=1000, single_calls=10)
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("| ")]
    assert len(rows) == 1 + len(bench.MODELS)  # the header and one row per model


@pytest.mark.parametrize("call,message", [
    (lambda: brdf.eval("nope", {}, [0, 0, 1], [0, 0, 1]), "unknown BRDF model 'nope' (known: lambert, "),
    (lambda: brdf.eval("lambert", {"foo": 1}, [0, 0, 1], [0, 0, 1]),
     "model 'lambert' has no parameter 'foo' (parameters: reflectance)"),
    (lambda: brdf.eval("lambert", {"reflectance": 2}, [0, 0, 1], [0, 0, 1]),
     "parameter 'reflectance' of 'lambert' must be in [0, 1], got 2"),
    (lambda: brdf.eval("lambert", {"reflectance": None}, [0, 0, 1], [0, 0, 1]), "expected a number"),
    (lambda: brdf.eval("lambert", {"reflectance": [1, 2]}, [0, 0, 1], [0, 0, 1]), "three numbers"),
    (lambda: brdf.eval("lambert", [("reflectance", 1)], [0, 0, 1], [0, 0, 1]), "params must be a dict"),
    (lambda: brdf.eval("lambert", {}, np.zeros((4, 2)), [0, 0, 1]), "wi must have shape (N, 3) or (3,)"),
    (lambda: brdf.eval("lambert", {}, np.zeros((2, 2, 3)), [0, 0, 1]), "not (2, 2, 3)"),
    (lambda: brdf.eval("lambert", {}, np.ones((4, 3)), np.ones((5, 3))), "wo has 5 rows but wi has 4"),
    (lambda: brdf.eval("lambert", {}, np.ones((4, 3), dtype=complex), [0, 0, 1]), "real numbers"),
    (lambda: brdf.eval("lambert", {}, np.array([["a", "b", "c"]]), [0, 0, 1]), "real numbers"),
    (lambda: brdf.eval("lambert", {}, [[0, 0, 1], [0, 0, 0]], [0, 0, 1]), "wi[1] is not a direction"),
    (lambda: brdf.eval("lambert", {}, [0, 0, 1], [0, np.nan, 1]), "wo[0] is not a direction"),
    (lambda: brdf.eval("lambert", {}, [0, 0, 1], [0, 0, 1], mode="sideways"), "radiance or importance"),
    (lambda: brdf.sample("lambert", {}, [0, 0, 1], [[0.5, 0.5], [0.5, 1.5]]), "u[1] is not in [0, 1]"),
    (lambda: brdf.sample("lambert", {}, [0, 0, 1], [0.5, 0.5], uc=-1), "uc[0] is not in [0, 1]"),
    (lambda: brdf.sample("lambert", {}, [0, 0, 1], [0.5, 0.5], seed=-1), "seed must be a whole number"),
    (lambda: brdf.albedo("lambert", {}, 90), "theta_deg values must be in [0, 90), got 90"),
    (lambda: brdf.albedo("lambert", {}, 10, samples=10), "samples must be a whole number in [100"),
])
def test_bad_arguments_raise_value_error(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)


def test_errors_match_the_cli(cli):
    r = cli("brdf", "eval", "lambert", "-p", "reflectance=2")
    assert r.returncode == 2
    with pytest.raises(illum.Error) as e:
        brdf.Model("lambert", {"reflectance": 2})
    assert r.stderr.strip() == f"error: {e.value}"
