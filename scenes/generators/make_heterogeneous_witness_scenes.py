#!/usr/bin/env python3
"""Writes two heterogeneous-media witness scenes (see their headers):
    python3 scenes/generators/make_heterogeneous_witness_scenes.py plume > scenes/media/plume-spot.pbrt
    python3 scenes/generators/make_heterogeneous_witness_scenes.py caustic > scenes/media/fog-caustic-grid.pbrt
"""
import math
import sys


def rows(values, per):
    return "\n".join("    " + " ".join(f"{v:g}" for v in values[i:i + per]) for i in range(0, len(values), per))


def plume_density(nx=10, ny=16, nz=10):
    """A column of smoke that widens and thins as it rises, with a twist of denser filaments."""
    values = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                x, y, z = (i + 0.5) / nx - 0.5, (j + 0.5) / ny, (k + 0.5) / nz - 0.5
                radius = 0.12 + 0.3 * y
                r = math.hypot(x, z)
                core = max(0.0, 1 - r / radius)
                swirl = 1 + 0.6 * math.sin(6 * math.atan2(z, x) + 9 * y)
                values.append(round(4 * core * core * (1 - 0.7 * y) * swirl, 4))
    return values, (nx, ny, nz)


def layered_fog(nx=6, ny=6, nz=6):
    """Fog that thickens towards the floor, in patches."""
    values = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                h = (j + 0.5) / ny
                patch = 1 + 0.5 * math.cos(2.5 * i) * math.cos(1.7 * k)
                values.append(round(max(0.0, 1.3 - 1.1 * h) * patch, 4))
    return values, (nx, ny, nz)


def plume():
    density, (nx, ny, nz) = plume_density()
    return f"""# A smoke plume under a spot light (issue 18's first pbrt-v4 agreement scene): a "uniformgrid"
# column that widens and thins as it rises, with denser swirling filaments, in a box of
# "interface" faces with outward normals, lit by a spot light from above and to the side. The
# camera and the light are outside the smoke. One of the heterogeneous-media witness scenes
# (tests/integrators/heterogeneous_media_witness_test.cpp; the pbrt-v4 reference is made by
# scripts/make-pbrt-references.sh; this file by scenes/generators/make_heterogeneous_witness_scenes.py).
LookAt 0 1.1 3.8  0 0.9 0  0 1 0
Camera "perspective" "float fov" [ 40 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ]
Sampler "independent" "integer pixelsamples" [ 64 ]
Integrator "volpath" "integer maxdepth" [ 20 ]
WorldBegin
LightSource "spot" "point3 from" [ 1.6 2.8 1.2 ] "point3 to" [ 0 0.7 0 ]
  "float coneangle" [ 22 ] "float conedeltaangle" [ 6 ] "rgb I" [ 28 26 22 ]
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
  Shape "bilinearmesh" "point3 P" [ -4 0 -4   4 0 -4   -4 0 4   4 0 4 ]
  Shape "bilinearmesh" "point3 P" [ -4 0 -1.5   4 0 -1.5   -4 4 -1.5   4 4 -1.5 ]
AttributeEnd
AttributeBegin
  Translate -0.6 0.01 -0.6
  Scale 1.2 2 1.2
  MakeNamedMedium "smoke" "string type" "uniformgrid" "integer nx" {nx} "integer ny" {ny} "integer nz" {nz}
    "rgb sigma_a" [ 0.3 0.35 0.4 ] "rgb sigma_s" [ 2.2 2.4 2.6 ] "float g" 0.4
    "float density" [
{rows(density, nx)}
    ]
  MediumInterface "smoke" ""
  Material "interface"
  Shape "trianglemesh" "integer indices" [ 0 2 1 0 3 2  4 5 6 4 6 7  0 5 4 0 1 5  1 6 5 1 2 6  2 7 6 2 3 7  3 4 7 3 0 4 ]
    "point3 P" [ 0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1 ]
AttributeEnd"""


def caustic():
    density, (nx, ny, nz) = layered_fog()
    return f"""# A volumetric caustic in heterogeneous fog (issue 18's second pbrt-v4 agreement scene): a small
# downward-facing disk light focused by a glass ball into a "uniformgrid" fog that thickens towards
# the floor, in patches. The camera, the light and the ball sit inside the fog (scenes/hard/
# fog-caustic.pbrt is the homogeneous version; its header says why the light is a small area
# light rather than a spot light). The camera is at the origin: pbrt-v4 places a medium defined
# before the Camera directive in its camera-centred render space, Caustica in world space, and
# the two coincide only there. One of the heterogeneous-media witness scenes
# (tests/integrators/heterogeneous_media_witness_test.cpp; the pbrt-v4 reference is made by
# scripts/make-pbrt-references.sh; this file by scenes/generators/make_heterogeneous_witness_scenes.py).
MakeNamedMedium "fog" "string type" "uniformgrid" "integer nx" {nx} "integer ny" {ny} "integer nz" {nz}
  "point3 p0" [ -6 -1.01 -10 ] "point3 p1" [ 6 4 2 ]
  "rgb sigma_a" [ 0.02 0.02 0.02 ] "rgb sigma_s" [ 0.15 0.16 0.17 ] "float g" 0.3
  "float density" [
{rows(density, nx)}
  ]
MediumInterface "" "fog"
LookAt 0 0 0   0 0.7 -4   0 1 0
Camera "perspective" "float fov" [ 60 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ]
Sampler "independent" "integer pixelsamples" [ 64 ]
Integrator "volpath" "integer maxdepth" [ 8 ]
WorldBegin
MediumInterface "fog" "fog"
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 16 16 16 ]
  Material "diffuse" "rgb reflectance" [ 0 0 0 ]
  Translate 0 3.4 -4
  Rotate 90 1 0 0
  Shape "disk" "float radius" [ 0.3 ]
AttributeEnd
AttributeBegin
  Material "dielectric" "float eta" [ 1.5 ]
  Translate 0 2.4 -4
  Shape "sphere" "float radius" [ 0.35 ]
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
  Shape "trianglemesh" "integer indices" [ 0 2 1 0 3 2 ]
    "point3 P" [ -20 -1 -24  20 -1 -24  20 -1 16  -20 -1 16 ]
AttributeEnd"""


if __name__ == "__main__":
    print({"plume": plume, "caustic": caustic}[sys.argv[1]]())
