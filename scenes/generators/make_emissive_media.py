#!/usr/bin/env python3
"""Writes scenes/media/emissive.pbrt, the emissive-media witness scene (see its header):
    python3 scenes/generators/make_emissive_media.py > scenes/media/emissive.pbrt
"""
import math

N = 8  # the fireball's grid
M = 4  # the glow's grid


def rows(values, per):
    return "\n".join("    " + " ".join(f"{v:g}" for v in values[i:i + per]) for i in range(0, len(values), per))


def fireball():
    density, temperature = [], []
    for z in range(N):
        for y in range(N):
            for x in range(N):
                u = [(x + 0.5) / N - 0.5, (y + 0.5) / N - 0.5, (z + 0.5) / N - 0.5]
                core = max(0.0, 1 - 2 * math.sqrt(sum(c * c for c in u)))
                # Denser towards +x, so that the ball is lopsided.
                density.append(round(3 * core * (1 + 0.5 * u[0]), 4))
                temperature.append(round(900 + 1800 * core if core > 0 else 0, 1))
    return density, temperature


def glow():
    sigma_a, sigma_s, Le = [], [], []
    for z in range(M):
        for y in range(M):
            for x in range(M):
                on = (x + y + z) % 2 == 0
                sigma_a += [0.8] * 3 if on else [0.1] * 3
                sigma_s += [0.5] * 3
                Le += [0.1, 0.6, 1.0] if on else [0, 0, 0]
    return sigma_a, sigma_s, Le


BOX = """AttributeBegin
  {transform}
  MediumInterface "{name}" ""
  Material "interface"
  Shape "trianglemesh" "integer indices" [ 0 2 1 0 3 2  4 5 6 4 6 7  0 5 4 0 1 5  1 6 5 1 2 6  2 7 6 2 3 7  3 4 7 3 0 4 ]
    "point3 P" [ 0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1 ]
AttributeEnd"""

FIREBALL_TRANSFORM = "Translate -0.9 0.05 -0.5\n  Scale 1.1 1.1 1.1"
GLOW_TRANSFORM = "Translate 0.35 0.05 -0.2\n  Rotate 25 0 1 0\n  Scale 0.6 0.6 0.6"


def main():
    density, temperature = fireball()
    sigma_a, sigma_s, Le = glow()
    print(f"""# Emissive media (pbrt-v4's "Le", "Lescale" and "temperature"), against pbrt-v4's volpath.
# One of the heterogeneous-media witness scenes (tests/integrators/heterogeneous_media_witness_test.cpp;
# the pbrt-v4 reference is made by scripts/make-pbrt-references.sh; this file by
# scenes/generators/make_emissive_media.py):
# - a fireball: a "uniformgrid" ball whose density and temperature fall off from its lopsided
#   core (up to 2700 K raw, mapped by "temperatureoffset" and "temperaturescale"), emitting
#   blackbody light through a "Lescale" grid and scattering it (albedo 2/3);
# - a glow: a "rgbgrid" checkerboard of voxels that absorb and emit blue-green "rgb Le";
# - a dim sphere lamp, so that the lights' strategies mix with the media's emission;
# - a floor and a back wall, lit by all three. The wall fills the image behind the media: without
#   it, the blocks at the fireball's faint fringe held only rare contributions, whose variance two
#   runs cannot estimate.
# Both media fill boxes of "interface" faces with outward normals; the camera is outside.
LookAt 0 1.3 3.6  0 0.45 0  0 1 0
Camera "perspective" "float fov" [ 40 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ]
Sampler "independent" "integer pixelsamples" [ 64 ]
Integrator "volpath" "integer maxdepth" [ 20 ]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 1 1 1 ]
  Translate -1.2 2.2 0.5
  Shape "sphere" "float radius" [ 0.15 ]
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
  Shape "bilinearmesh" "point3 P" [ -3 0 -3   3 0 -3   -3 0 3   3 0 3 ]
  Shape "bilinearmesh" "point3 P" [ -3 0 -1.5   3 0 -1.5   -3 3 -1.5   3 3 -1.5 ]
AttributeEnd
AttributeBegin
  {FIREBALL_TRANSFORM}
  MakeNamedMedium "fireball" "string type" "uniformgrid" "integer nx" {N} "integer ny" {N} "integer nz" {N}
    "rgb sigma_a" [ 1 1 1 ] "rgb sigma_s" [ 2 2 2 ] "float scale" 1 "float g" 0.2
    "float temperatureoffset" 300 "float temperaturescale" 1.5
    "float density" [
{rows(density, 8)}
    ]
    "float Lescale" [
{rows([0.6] * N ** 3, 16)}
    ]
    "float temperature" [
{rows(temperature, 8)}
    ]
AttributeEnd
AttributeBegin
  {GLOW_TRANSFORM}
  MakeNamedMedium "glow" "string type" "rgbgrid" "integer nx" {M} "integer ny" {M} "integer nz" {M}
    "float scale" 2 "float Lescale" 0.3
    "rgb sigma_a" [
{rows(sigma_a, 12)}
    ]
    "rgb sigma_s" [
{rows(sigma_s, 12)}
    ]
    "rgb Le" [
{rows(Le, 12)}
    ]
AttributeEnd
{BOX.format(transform=FIREBALL_TRANSFORM, name="fireball")}
{BOX.format(transform=GLOW_TRANSFORM, name="glow")}""")


if __name__ == "__main__":
    main()
