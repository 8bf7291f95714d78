#!/usr/bin/env python3
"""Writes scenes/lights/many-lights.pbrt: a long hall lit by 200 small lamps (400 emissive
triangles), each facing a different way, most of them far from any given point of the floor, the
case a light sampler that knows where lights are and which way they face is for. Deterministic
(its own linear congruential generator)."""
import math

state = 12345


def rand():
    global state
    state = (1103515245 * state + 12345) % 2**31
    return state / 2**31


lines = [
    "# A hall lit by 200 small lamps of different colours and orientations (400 emissive",
    "# triangles). Written by scenes/generators/make_many_lights.py.",
    "LookAt 0 1.6 -1   0 0.8 12   0 1 0",
    'Camera "perspective" "float fov" [ 55 ]',
    'Film "rgb" "integer xresolution" [ 192 ] "integer yresolution" [ 128 ] "string filename" "many-lights.exr"',
    'Sampler "independent" "integer pixelsamples" [ 16 ]',
    'Integrator "path" "integer maxdepth" [ 5 ]',
    "WorldBegin",
    'Material "diffuse" "rgb reflectance" [ 0.6 0.6 0.6 ]',
    '# Floor, ceiling and walls of a hall 8 wide, 3 high and 60 long.',
    'Shape "bilinearmesh" "point3 P" [ -4 0 -2  4 0 -2  -4 0 60  4 0 60 ] "integer indices" [ 0 1 2 3 ]',
    'Shape "bilinearmesh" "point3 P" [ -4 3 -2  -4 3 60  4 3 -2  4 3 60 ] "integer indices" [ 0 1 2 3 ]',
    'Shape "bilinearmesh" "point3 P" [ -4 0 -2  -4 0 60  -4 3 -2  -4 3 60 ] "integer indices" [ 0 1 2 3 ]',
    'Shape "bilinearmesh" "point3 P" [ 4 0 -2  4 3 -2  4 0 60  4 3 60 ] "integer indices" [ 0 1 2 3 ]',
    'Material "diffuse" "rgb reflectance" [ 0.3 0.4 0.7 ]',
]
for i in range(12):
    x, z = -2.5 + 5 * rand(), 2 + 50 * rand()
    lines.append(f'AttributeBegin Translate {x:.3f} 0.4 {z:.3f} Shape "sphere" "float radius" [ 0.4 ] AttributeEnd')
for i in range(200):
    x, y, z = -3.6 + 7.2 * rand(), 0.3 + 2.5 * rand(), 50 * rand()
    # A random facing: a unit normal, and two edges of a 0.15 x 0.15 square across it.
    theta, phi = math.acos(1 - 2 * rand()), 2 * math.pi * rand()
    n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
    a = (1, 0, 0) if abs(n[0]) < 0.9 else (0, 1, 0)
    t = (a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0])
    tl = math.sqrt(sum(c * c for c in t))
    t = tuple(c / tl for c in t)
    b = (n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0])
    h = 0.075
    pts = []
    for s, u in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        pts.append(tuple([x, y, z][k] + h * (s * t[k] + u * b[k]) for k in range(3)))
    # One-sided: it emits to the side its winding gives (t x b = n up to pbrt-v4's rule).
    colour = [0.3 + 0.7 * rand() for _ in range(3)]
    power = 20 + 60 * rand()
    lines.append("AttributeBegin")
    lines.append(f'  AreaLightSource "diffuse" "rgb L" [ {colour[0]*power:.2f} {colour[1]*power:.2f} {colour[2]*power:.2f} ]')
    lines.append('  Shape "trianglemesh" "integer indices" [ 0 1 2  0 2 3 ]')
    lines.append('    "point3 P" [ ' + "  ".join(f"{p[0]:.4f} {p[1]:.4f} {p[2]:.4f}" for p in pts) + " ]")
    lines.append("AttributeEnd")
print("\n".join(lines))
