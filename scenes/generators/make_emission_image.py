"""Writes scenes/lights/emission-image.png, the emission image of the area lights in
scenes/lights/emission-image.pbrt: a 16x8 8-bit sRGB image of four coloured quadrants (red top
left, green top right, blue bottom left, warm white bottom right) with a dark stripe across the
top-left one. No two quadrants are alike and none is mirror-symmetric, so a flipped or turned
lookup changes the rendered image.

    python3 scenes/generators/make_emission_image.py scenes/lights/emission-image.png
"""
import sys

from png_file import write_png

WIDTH, HEIGHT = 16, 8


def colour(x, y):
    left, top = x < WIDTH // 2, y < HEIGHT // 2
    if left and top:
        return (40, 40, 40) if x == 2 else (255, 60, 40)
    if top:
        return (60, 230, 80)
    if left:
        return (50, 90, 255)
    return (255, 230, 190)


def main(path):
    write_png(path, WIDTH, HEIGHT, colour)


if __name__ == "__main__":
    main(sys.argv[1])
