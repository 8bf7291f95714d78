"""Writes scenes/textures/leaf-alpha.png, the colour and alpha map of the instanced leaves in
scenes/textures/alpha-cutouts.pbrt: a 32x32 8-bit RGBA leaf, an ellipse that narrows to a point
at both ends of its long (x) axis, with a soft edge about one texel wide so that bilinear lookups
give alpha values between 0 and 1 along the outline, as real leaf textures do. Its colour runs
from green at the stem (left) to yellow at the tip and stays on where alpha is 0, as in real
files whose colour is not multiplied by alpha: a reader that premultiplies darkens the soft
edge, and a float texture of the file reads its alpha (pbrt-v4's rule for files with alpha).

    python3 scenes/generators/make_leaf_alpha.py scenes/textures/leaf-alpha.png
"""
import sys

from png_file import write_png

SIZE = 32


def coverage(u, v):
    if abs(u) >= 1:
        return 0.0
    half_width = 0.45 * (1 - abs(u) ** 1.5) + 1e-6
    d = (u / 0.9) ** 2 + (v / half_width) ** 2
    return min(1.0, max(0.0, (1.15 - d) / 0.3))


def main(path):
    def pixel(x, y):
        u = (x + 0.5) / SIZE
        alpha = round(255 * coverage(-1 + 2 * u, -1 + 2 * (y + 0.5) / SIZE))
        return (round(60 + 150 * u), round(170 + 40 * u), 40, alpha)

    write_png(path, SIZE, SIZE, pixel)


if __name__ == "__main__":
    main(sys.argv[1])
