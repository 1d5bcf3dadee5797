#!/usr/bin/env python3
"""Writes a pbrt-v4 scene with many small lights, for measuring light selection (docs/performance.md).

A square of ground under a grid of lamps: small one-sided quads facing down at mixed heights and colours,
point lights near the ground, and boxes between them that cast shadows. The camera looks across the square
so that near and far lamps share the frame: next-event estimation chosen by power alone spends most of its
samples on lamps far from the point it lights. The same file renders in pbrt-v4 and illum.

  scripts/many_lights.py OUT.pbrt [--lamps 400] [--points 64] [--spp 16] [--res 320x180]
                         [--lightsampler bvh] [--integrator path] [--seed 1]
"""
import argparse
import random


def quad(x0, y, z0, x1, z1, down=True):
    idx = "0 1 2 0 2 3" if down else "0 2 1 0 3 2"
    return (f'Shape "trianglemesh" "point3 P" [{x0} {y} {z0}  {x1} {y} {z0}  {x1} {y} {z1}  {x0} {y} {z1}] '
            f'"integer indices" [{idx}]')


def box(x, z, w, h):
    c = [(x - w, 0, z - w), (x + w, 0, z - w), (x + w, 0, z + w), (x - w, 0, z + w),
         (x - w, h, z - w), (x + w, h, z - w), (x + w, h, z + w), (x - w, h, z + w)]
    faces = [0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6,
             3, 0, 4, 3, 4, 7]
    pts = "  ".join(f"{a} {b} {c_}" for a, b, c_ in c)
    return f'Shape "trianglemesh" "point3 P" [{pts}] "integer indices" [{" ".join(map(str, faces))}]'


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--lamps", type=int, default=400)
    ap.add_argument("--points", type=int, default=64)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--res", default="320x180")
    ap.add_argument("--lightsampler", default="bvh")
    ap.add_argument("--integrator", default="path")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    w, h = a.res.split("x")
    out = [f'Film "rgb" "integer xresolution" [{w}] "integer yresolution" [{h}] "string filename" "many-lights.exr"',
           'LookAt 0 9 26  0 0 -4  0 1 0',
           'Camera "perspective" "float fov" [45]',
           f'Sampler "zsobol" "integer pixelsamples" [{a.spp}]',
           f'Integrator "{a.integrator}" "integer maxdepth" [5] "string lightsampler" "{a.lightsampler}"',
           'WorldBegin',
           'Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]',
           quad(-30, 0, -30, 30, 30, down=False),
           'Material "diffuse" "rgb reflectance" [0.4 0.3 0.25]']
    for _ in range(40):
        out.append(box(rng.uniform(-18, 18), rng.uniform(-18, 18), rng.uniform(0.3, 1.2), rng.uniform(0.5, 4)))
    side = max(1, round(a.lamps ** 0.5))
    for i in range(a.lamps):
        gx, gz = i % side, i // side
        x = -20 + 40 * (gx + rng.uniform(0.2, 0.8)) / side
        z = -20 + 40 * (gz + rng.uniform(0.2, 0.8)) / side
        y = rng.uniform(2.5, 6)
        s = rng.uniform(0.08, 0.2)
        r, g, b = (rng.uniform(0.3, 1) for _ in range(3))
        k = rng.uniform(20, 60)
        out.append("AttributeBegin")
        out.append(f'  AreaLightSource "diffuse" "rgb L" [{k * r:.3f} {k * g:.3f} {k * b:.3f}]')
        out.append("  " + quad(x - s, y, z - s, x + s, z + s))
        out.append("AttributeEnd")
    for _ in range(a.points):
        x, z, y = rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(0.3, 1.5)
        k = rng.uniform(0.5, 3)
        out.append(f'LightSource "point" "point3 from" [{x:.3f} {y:.3f} {z:.3f}] "rgb I" [{k:.3f} {k * 0.8:.3f} {k * 0.6:.3f}]')
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
