"""Writes scenes/cameras/apertures/crescent.png, the aperture image of
scenes/cameras/realistic-crescent.pbrt: a 64x64 8-bit greyscale disc (radius 0.9 of the stop's)
with a bite (radius 0.45, centred at x 0.5, y 0.25, y up) taken out of it. The shape is
symmetric about no axis, so a mirrored or turned lookup changes the image, and its centre is open,
as pbrt-v4 needs to focus the lens (its paraxial rays pass the stop's centre through the mask).
Black and white only, so that sRGB decoding leaves it unchanged in every reader.

    python3 scenes/generators/make_crescent_aperture.py scenes/cameras/apertures/crescent.png
"""
import struct
import sys
import zlib

SIZE = 64


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def main(path):
    rows = b""
    for y in range(SIZE):
        row = bytearray([0])  # filter type: none
        for x in range(SIZE):
            # PNG rows run from the top down.
            u, v = -1 + 2 * (x + 0.5) / SIZE, 1 - 2 * (y + 0.5) / SIZE
            in_disc = u * u + v * v <= 0.9 ** 2
            in_bite = (u - 0.5) ** 2 + (v - 0.25) ** 2 <= 0.45 ** 2
            row.append(255 if in_disc and not in_bite else 0)
        rows += bytes(row)
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0)  # 8-bit greyscale
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    main(sys.argv[1])
