#!/usr/bin/env python3
"""Writes the images the scenes in this folder read (small PFM files, linear RGB; rerun to regenerate).

gonio.pfm   32x32 equal-area octahedral intensity diagram (pbrt-v4's layout): a bright lobe about the image's
            +z with a dimmer ring, zero below the equator.
slide.pfm   24x16 projector slide: coloured stripes with a dark cross.
panel.pfm   16x16 emitter image: a warm-to-cool gradient with a bright square.
sky.pfm     64x64 equal-area octahedral sky: blue, brighter towards +z, with a small warm sun.
"""
import math
import struct


def write_pfm(path, w, h, pixel):
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        for y in reversed(range(h)):  # PFM stores the bottom row first
            for x in range(w):
                f.write(struct.pack("<3f", *pixel(x, y)))


def octahedral_to_sphere(u, v):
    # Clarberg's equal-area octahedral map (pbrt-v4's EqualAreaSquareToSphere), (u, v) in [0, 1]².
    p, q = 2 * u - 1, 2 * v - 1
    ap, aq = abs(p), abs(q)
    sd = 1 - (ap + aq)
    r = 1 - abs(sd)
    phi = (1.0 if r == 0 else (aq - ap) / r + 1) * math.pi / 4
    z = math.copysign(1 - r * r, sd)
    s = r * math.sqrt(max(0.0, 2 - r * r))
    return (math.copysign(math.cos(phi), p) * s, math.copysign(math.sin(phi), q) * s, z)


def gonio(x, y):
    d = octahedral_to_sphere((x + 0.5) / 32, (y + 0.5) / 32)
    v = 0.0
    if d[2] > 0:
        v = 0.3 + 2.0 * d[2] ** 8 + (0.6 if 0.3 < d[2] < 0.5 else 0.0) * (1 + 0.5 * d[0])
    return (v, v, v)


def slide(x, y):
    if x in (11, 12) or y in (7, 8):
        return (0.02, 0.02, 0.02)
    band = (x // 4) % 3
    c = [(1.0, 0.2, 0.1), (0.2, 1.0, 0.2), (0.1, 0.3, 1.0)][band]
    k = 0.5 + y / 16
    return (c[0] * k, c[1] * k, c[2] * k)


def panel(x, y):
    u, v = (x + 0.5) / 16, (y + 0.5) / 16
    r, g, b = 1.0 - 0.6 * u, 0.6, 0.3 + 0.7 * u
    if 4 <= x < 8 and 9 <= y < 13:
        return (6.0, 5.0, 3.0)
    return (r * (0.5 + v), g * (0.5 + v), b * (0.5 + v))


def sky(x, y):
    d = octahedral_to_sphere((x + 0.5) / 64, (y + 0.5) / 64)
    t = max(0.0, d[2])
    c = [0.25 + 0.3 * t, 0.35 + 0.45 * t, 0.6 + 0.6 * t]
    if d[2] < 0:
        c = [0.15, 0.13, 0.1]
    sun = (0.35, 0.25, 0.9)
    n = math.sqrt(sum(s * s for s in sun))
    if sum(a * b / n for a, b in zip(d, sun)) > 0.985:
        c = [c[0] + 40, c[1] + 32, c[2] + 20]
    return tuple(c)


if __name__ == "__main__":
    write_pfm("gonio.pfm", 32, 32, gonio)
    write_pfm("slide.pfm", 24, 16, slide)
    write_pfm("panel.pfm", 16, 16, panel)
    write_pfm("sky.pfm", 64, 64, sky)
