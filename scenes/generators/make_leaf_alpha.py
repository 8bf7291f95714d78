"""Writes scenes/textures/leaf-alpha.png, the alpha map of the instanced leaves in
scenes/textures/alpha-cutouts.pbrt: a 32x32 8-bit greyscale leaf, an ellipse that narrows to a
point at both ends of its long (x) axis, with a soft edge about one texel wide so that bilinear
lookups give alpha values between 0 and 1 along the outline, as real leaf textures do.

    python3 scenes/generators/make_leaf_alpha.py scenes/textures/leaf-alpha.png
"""
import struct
import sys
import zlib

SIZE = 32


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def coverage(u, v):
    if abs(u) >= 1:
        return 0.0
    half_width = 0.45 * (1 - abs(u) ** 1.5) + 1e-6
    d = (u / 0.9) ** 2 + (v / half_width) ** 2
    return min(1.0, max(0.0, (1.15 - d) / 0.3))


def main(path):
    rows = b""
    for y in range(SIZE):
        row = bytearray([0])  # filter type: none
        for x in range(SIZE):
            u, v = -1 + 2 * (x + 0.5) / SIZE, -1 + 2 * (y + 0.5) / SIZE
            row.append(round(255 * coverage(u, v)))
        rows += bytes(row)
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0)  # 8-bit greyscale
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    main(sys.argv[1])
