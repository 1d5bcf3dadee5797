#!/usr/bin/env python3
"""Writes checker.png: a 256x256 8-bit greyscale checkerboard of 8x8-texel checks (black 0.05 and white
0.8 after sRGB decoding), the texture of texture-filtering.pbrt. Standard library only."""
import struct
import zlib

N, CHECK = 256, 8
DARK, LIGHT = 63, 231  # sRGB codes of about 0.05 and 0.8 linear


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


rows = b"".join(b"\0" + bytes(LIGHT if ((x // CHECK + y // CHECK) & 1) == 0 else DARK for x in range(N))
                for y in range(N))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", N, N, 8, 0, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
with open("checker.png", "wb") as f:
    f.write(png)
