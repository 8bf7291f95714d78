"""Writes scenes/cameras/apertures/crescent.png, the aperture image of
scenes/cameras/realistic-crescent.pbrt: a 64x64 8-bit greyscale disc (radius 0.9 of the stop's)
with a bite (radius 0.45, centred at x 0.5, y 0.25, y up) taken out of it. The shape is
symmetric about no axis, so a mirrored or turned lookup changes the image, and its centre is open,
as pbrt-v4 needs to focus the lens (its paraxial rays pass the stop's centre through the mask).
Black and white only, so that sRGB decoding leaves it unchanged in every reader.

    python3 scenes/generators/make_crescent_aperture.py scenes/cameras/apertures/crescent.png
"""
import sys

from png_file import write_png

SIZE = 64


def main(path):
    def pixel(x, y):
        u, v = -1 + 2 * (x + 0.5) / SIZE, 1 - 2 * (y + 0.5) / SIZE
        in_disc = u * u + v * v <= 0.9 ** 2
        in_bite = (u - 0.5) ** 2 + (v - 0.25) ** 2 <= 0.45 ** 2
        return 255 if in_disc and not in_bite else 0

    write_png(path, SIZE, SIZE, pixel)


if __name__ == "__main__":
    main(sys.argv[1])
