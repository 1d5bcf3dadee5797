"""How much a vectorised illum.brdf.eval over 10^6 directions saves against a Python loop of single calls.

A benchmark, not a test: the figure depends on the machine and its load (docs/performance.md, "Python
bindings"). Run from the repository after `make build`:

    PYTHONPATH=build/python python3 python/bench/brdf_vectorised.py
"""

import math
import time

import numpy as np

from illum import brdf

MODELS = [("lambert", {}), ("rough-conductor", {"alpha": 0.2}), ("ward", {}), ("coated-diffuse", {})]


def best_of(runs, f):
    best = math.inf
    for _ in range(runs):
        t = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t)
    return best


def random_directions(rng, n):
    v = rng.normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2])
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def main(n=10**6, single_calls=3000):
    rng = np.random.default_rng(4)
    wi, wo = random_directions(rng, n), random_directions(rng, n)
    print(f"| model | vectorised, {n} | Python loop, {n} (from {single_calls} calls) | ratio |")
    print("|---|---|---|---|")
    for model, params in MODELS:
        vectorised = best_of(3, lambda: brdf.eval(model, params, wi, wo))

        def loop():
            for i in range(single_calls):
                brdf.eval(model, params, wi[i], wo[i])

        looped = best_of(3, loop) * n / single_calls
        print(f"| {model} | {vectorised * 1e3:.1f} ms | {looped:.2f} s | {looped / vectorised:.0f}x |")


if __name__ == "__main__":
    main()
