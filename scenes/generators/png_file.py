"""Writes 8-bit PNG files (greyscale, RGB or RGBA) without image libraries, for the scene
generators."""
import struct
import zlib


def _chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def write_png(path, width, height, pixel):
    """pixel(x, y) gives an int in [0, 255] (greyscale) or a tuple of three (RGB) or four (RGBA,
    alpha not premultiplied); y runs from the top of the image down, as PNG rows do."""
    channels = 1 if isinstance(pixel(0, 0), int) else len(pixel(0, 0))
    rows = b""
    for y in range(height):
        row = bytearray([0])  # filter type: none
        for x in range(width):
            value = pixel(x, y)
            row += bytes([value] if channels == 1 else value)
        rows += bytes(row)
    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(rows)) + _chunk(b"IEND", b""))
