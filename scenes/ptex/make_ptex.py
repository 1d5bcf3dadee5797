#!/usr/bin/env python3
"""Writes faces.ptx, the Ptex file of ptex.pbrt (format: ptex.us, "Ptex File Format"): 18 faces of 8-bit
RGB texels, written as Ptex's own writer would (header, extended header with clamp borders, zipped face
info and constant data, the level info (not zipped), level 0 and the reduction levels, each face's data as zipped channel
planes). Faces 0-15 (the floor's 4 x 4 bilinear patches) are 16 x 16 texels: stripes, gradients and checks
of different frequencies and colours, so the footprint's filtering and the reductions show; faces 16 and 17
(the back wall's two triangle pairs) are 32 x 8 and 8 x 32. The adjacency is the meshes': the floor's faces
(u along +x, v along +z, face 4 j + i at column i, row j) meet their grid neighbours, the wall's two faces
meet each other, so the filter reaches across edges and corners. Standard library only."""
import struct
import zlib


def pattern(face, u, v, ures, vres):
    """The face's texel (u, v) as three 8-bit values."""
    x, y = (u + 0.5) / ures, (v + 0.5) / vres
    kind = face % 4
    base = [(230, 60, 40), (40, 200, 90), (50, 90, 230), (220, 210, 60)][(face // 4) % 4]
    if kind == 0:  # stripes along u, period 2 texels at most frequent
        period = 2 << (face // 4 % 3)
        on = (u // (period // 2)) % 2 == 0
    elif kind == 1:  # checks
        on = ((u // 2) + (v // 2)) % 2 == 0
    elif kind == 2:  # a gradient along v
        t = y
        return tuple(int(round(c * t + 20 * (1 - t))) for c in base)
    else:  # a ring
        on = ((x - 0.5) ** 2 + (y - 0.5) ** 2) < 0.12
    return base if on else (25, 25, 25)


FACES = [(4, 4)] * 16 + [(5, 3), (3, 5)]  # log2 resolutions (u, v)


def texels(face):
    ul, vl = FACES[face]
    ures, vres = 1 << ul, 1 << vl
    return [[pattern(face, u, v, ures, vres) for u in range(ures)] for v in range(vres)]


def reduce(t):
    """2 x 2 box, rounded down (Ptex's reduce for uint8)."""
    return [[tuple((t[2 * v][2 * u][c] + t[2 * v][2 * u + 1][c] + t[2 * v + 1][2 * u][c] +
                    t[2 * v + 1][2 * u + 1][c]) // 4 for c in range(3))
             for u in range(len(t[0]) // 2)] for v in range(len(t) // 2)]


def block(t):
    """Zipped channel planes (encoding 1)."""
    raw = bytes(t[v][u][c] for c in range(3) for v in range(len(t)) for u in range(len(t[0])))
    data = zlib.compress(raw, 9)
    return data, len(data) | (1 << 30)


def main():
    n = len(FACES)
    full = [texels(f) for f in range(n)]
    # Adjacent faces across the bottom, right, top and left edges, and the edge of the neighbour (the
    # opposite one, as every face has the same orientation).
    adjacent = []
    for f in range(n):
        if f < 16:
            i, j = f % 4, f // 4
            near = [f - 4 if j > 0 else -1, f + 1 if i < 3 else -1, f + 4 if j < 3 else -1, f - 1 if i > 0 else -1]
        else:
            near = [-1, 17 if f == 16 else -1, -1, 16 if f == 17 else -1]
        adjacent.append(near)
    edges = sum(((e + 2) % 4) << (2 * e) for e in range(4))
    info = b"".join(struct.pack("<bbBB4i", ul, vl, edges, 0, *adjacent[f]) for f, (ul, vl) in enumerate(FACES))
    # The face's mean, rounded down, as its constant data.
    const = b""
    for t in full:
        count = len(t) * len(t[0])
        const += bytes(sum(px[c] for row in t for px in row) // count for c in range(3))
    # Level 0, then level i with the faces whose smaller side is at least 2^(i+2), in the order of
    # decreasing smaller side (stable), as Ptex's writer orders them.
    order = sorted(range(n), key=lambda f: -min(FACES[f]))
    levels = []
    current = list(full)
    words, data = b"", b""
    for f in range(n):
        d, w = block(full[f])
        words, data = words + struct.pack("<I", w), data + d
    levels.append((words, data, n))
    level = 1
    while True:
        words, data, count = b"", b"", 0
        for f in order:
            if min(FACES[f]) - level < 2:
                break
            current[f] = reduce(current[f])
            d, w = block(current[f])
            words, data, count = words + struct.pack("<I", w), data + d, count + 1
        if count == 0:
            break
        levels.append((words, data, count))
        level += 1
    level_info, level_data = b"", b""
    for words, data, count in levels:
        zw = zlib.compress(words, 9)
        level_info += struct.pack("<QII", len(zw) + len(data), len(zw), count)
        level_data += zw + data
    ext = struct.pack("<HHHH", 0, 0, 0, 0)  # clamp borders
    zinfo, zconst, zlevel = zlib.compress(info, 9), zlib.compress(const, 9), level_info  # level info unzipped
    header = struct.pack("<4sIIIiHHIIIIIIQII", b"Ptex", 1, 1, 0, -1, 3, len(levels), n, len(ext), len(zinfo),
                         len(zconst), len(zlevel), 0, len(level_data), 0, 0)
    assert len(header) == 64
    with open("faces.ptx", "wb") as out:
        out.write(header + ext + zinfo + zconst + zlevel + level_data)


main()
