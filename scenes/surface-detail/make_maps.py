#!/usr/bin/env python3
"""Writes the maps of scenes/surface-detail: a height field h(u, v) = (1 + sin(2π f u) sin(2π f v)) / 2
(bumps.pfm, grey) and the tangent-space normal map of the surface displaced by s h on a square of side W
with ∂p/∂u, ∂p/∂v along its sides (normals.pfm): n_t ∝ (-s ∂h/∂u / W, -s ∂h/∂v / W, 1), stored as
(n_t + 1) / 2. PFM rows run from the bottom (v = (row + 1/2) / N) as pbrt-v4 and illum read them.
Usage: make_maps.py [folder]"""
import math
import os
import struct
import sys

N, F = 64, 4  # texels per side, bumps per side
S_OVER_W = 0.05  # the normal map's displacement scale over the square's side


def h(u, v):
    return 0.5 * (1 + math.sin(2 * math.pi * F * u) * math.sin(2 * math.pi * F * v))


def dh(u, v):
    k = math.pi * F
    return (k * math.cos(2 * k * u) * math.sin(2 * k * v), k * math.sin(2 * k * u) * math.cos(2 * k * v))


def write_pfm(path, texel):
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (N, N))
        for row in range(N):  # bottom row first
            v = (row + 0.5) / N
            for col in range(N):
                f.write(struct.pack("<3f", *texel((col + 0.5) / N, v)))


def normal_texel(u, v):
    du, dv = dh(u, v)
    n = (-S_OVER_W * du, -S_OVER_W * dv, 1.0)
    l = math.sqrt(sum(c * c for c in n))
    return tuple((c / l + 1) / 2 for c in n)


folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
write_pfm(os.path.join(folder, "bumps.pfm"), lambda u, v: (h(u, v),) * 3)
write_pfm(os.path.join(folder, "normals.pfm"), normal_texel)
