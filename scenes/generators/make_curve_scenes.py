"""Writes the witness scenes of pbrt-v4's "curve" shape and "hair" material:

    python3 scenes/generators/make_curve_scenes.py scenes/shapes

- curves.pbrt: curves of every kind on diffuse materials, on a grey floor before a grey
  wall, lit by the sun (a distant light) and a dim sky: flat cubic Bezier blades that narrow from width0 to width1, "cylinder" arcs, twisted
  "ribbon"s (normals a quarter turn apart), and uniform B-splines of degree 3 and 2 with
  quadratic Beziers, a pixel or so wide and a few widths apart, all in the plane z = 0, which
  the sun's rays leave at once: no curve shades another from the sun. Embree's and pbrt-v4's curves
  differ by a small fraction of a pixel in where they put the centre line, which matters more in
  thinner curves; pbrt-v4 moves the points where it samples lights, and the rays that leave a
  curve, up to 1.7 of its widths off the curve (its error bound), which shifts the shadows that
  curves cast on each other and the light of near emitters (the sun and the sky are infinitely
  far).
- hair.pbrt: three hanging tufts of "hair" on flat curves, coloured by melanin (pbrt-v4's
  default eumelanin 1.3), by "color" (a blonde reflectance) and by "sigma_a", and two wide
  strands in front of them, lit by the sun and the sky.
- wide-fibres.pbrt: a hair fibre and a "cylinder" curve many pixels wide.

The curves are drawn from a fixed random stream, so the files are reproduced exactly.
"""
import math
import random
import sys

ROOM = """WorldBegin
LightSource "infinite" "rgb L" [{sky} {sky} {sky}]
LightSource "distant" "point3 from" [0.6 2 -1.2] "point3 to" [0 0 0] "rgb L" [2.5 2.4 2.2]
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-3 -1 -4  3 -1 -4  3 -1 2  -3 -1 2] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-3 -1 1.5  3 -1 1.5  3 2 1.5  -3 2 1.5] "integer indices" [0 1 2 0 2 3]
"""


def header(comment, name, spp):
    return comment + """LookAt 0 0.2 -3.2  0 0.1 0  0 1 0
Camera "perspective" "float fov" 42
Film "rgb" "integer xresolution" 64 "integer yresolution" 64 "string filename" "{name}.exr"
Sampler "independent" "integer pixelsamples" {spp}
Integrator "path" "integer maxdepth" 8

""".format(name=name, spp=spp)


def points(ps):
    return " ".join("%.4f %.4f %.4f" % p for p in ps)


def curves_scene(rng):
    out = [header("# pbrt-v4's \"curve\" shape in all its kinds (see scenes/generators/make_curve_scenes.py).\n"
                  "# Reference: tests/data/pbrt-v4/shapes/curves.exr (pbrt-v4's path tracer).\n", "curves", 64),
           ROOM.format(sky=0.1)]
    # Flat blades rising from below, bending sideways, narrowing to their tips.
    out.append('AttributeBegin\n  Material "diffuse" "rgb reflectance" [0.8 0.25 0.15]\n')
    for i in range(10):
        x, z = -1.35 + 0.09 * i, 0.0
        bend = rng.uniform(-0.25, 0.25)
        ps = [(x, -0.8, z), (x, -0.3, z), (x + bend * 0.5, 0.1, z), (x + bend, rng.uniform(0.2, 0.6), z)]
        out.append('  Shape "curve" "point3 P" [%s] "float width0" 0.05 "float width1" 0.015\n' % points(ps))
    out.append('AttributeEnd\n')
    # Cylinder arcs, one behind the other.
    out.append('AttributeBegin\n  Material "diffuse" "rgb reflectance" [0.2 0.6 0.8]\n')
    for i in range(6):
        x, z, h = -0.45 + 0.08 * i, 0.0, rng.uniform(0.6, 1.1)
        span = rng.uniform(0.3, 0.5)
        ps = [(x, -0.8, z), (x, -0.8 + h, z), (x + span, -0.8 + h, z), (x + span, -0.8, z)]
        out.append('  Shape "curve" "string type" "cylinder" "point3 P" [%s] "float width" 0.04\n' % points(ps))
    out.append('AttributeEnd\n')
    # Twisted ribbons: wide facing the camera at the foot, edge-on at the top.
    out.append('AttributeBegin\n  Material "diffuse" "rgb reflectance" [0.85 0.75 0.2]\n')
    for i in range(7):
        x, z = 0.45 + 0.12 * i, 0.0
        lean = rng.uniform(-0.2, 0.2)
        ps = [(x, -0.8, z), (x, -0.4, z), (x + lean, 0.0, z), (x + lean, rng.uniform(0.2, 0.5), z)]
        out.append('  Shape "curve" "string type" "ribbon" "point3 P" [%s] "normal N" [0 0 -1  -1 0 -0.3]\n'
                   '    "float width" 0.07\n' % points(ps))
    # A wide one above them, whose normal's turn across the width shows (pixels average a thin
    # curve's across its width).
    out.append('  Shape "curve" "string type" "cylinder" "point3 P" [-0.3 0.42 0  -0.1 0.7 0  0.2 0.7 0  0.4 0.42 0]\n'
               '    "float width" 0.12\n')
    out.append('AttributeEnd\n')
    # Gently waving horizontal B-splines of degree 3 and 2, and quadratic Beziers, above.
    out.append('AttributeBegin\n  Material "diffuse" "rgb reflectance" [0.3 0.75 0.3]\n')
    for i in range(9):
        y, z = 0.75 + 0.075 * i, 0.0
        ps = [(-1.4 + 0.4 * k, y + rng.uniform(-0.04, 0.04), z) for k in range(8)]
        if i % 3 == 0:
            out.append('  Shape "curve" "string basis" "bspline" "point3 P" [%s] "float width" 0.04\n' % points(ps))
        elif i % 3 == 1:
            out.append('  Shape "curve" "string basis" "bspline" "integer degree" 2 "point3 P" [%s]\n'
                       '    "float width" 0.04\n' % points(ps))
        else:
            out.append('  Shape "curve" "integer degree" 2 "point3 P" [%s] "float width" 0.04\n' % points(ps[:7]))
    out.append('AttributeEnd\n')
    return "".join(out)


def tuft(rng, x0, count):
    """Strands hanging from a bar at height 1.1 around x0, falling in arcs."""
    lines = []
    for _ in range(count):
        x, z = x0 + rng.uniform(-0.25, 0.25), rng.uniform(-0.2, 0.2)
        sway, length = rng.uniform(-0.3, 0.3), rng.uniform(1.2, 1.7)
        ps = [(x, 1.1, z), (x + 0.3 * sway, 1.1 - 0.35 * length, z - 0.1),
              (x + sway, 1.1 - 0.7 * length, z + 0.1), (x + 0.8 * sway, 1.1 - length, z)]
        lines.append('  Shape "curve" "point3 P" [%s] "float width0" 0.012 "float width1" 0.006\n' % points(ps))
    return "".join(lines)


def hair_scene(rng):
    out = [header("# pbrt-v4's \"hair\" material on flat curves (see scenes/generators/make_curve_scenes.py).\n"
                  "# Reference: tests/data/pbrt-v4/shapes/hair.exr (pbrt-v4's path tracer).\n", "hair", 64),
           ROOM.format(sky=0.3)]
    out.append('AttributeBegin\n  Material "hair"\n' + tuft(rng, -0.7, 150) + 'AttributeEnd\n')
    out.append('AttributeBegin\n  Material "hair" "rgb color" [0.75 0.55 0.3] "float beta_m" 0.2\n'
               + tuft(rng, 0.0, 150) + 'AttributeEnd\n')
    out.append('AttributeBegin\n  Material "hair" "rgb sigma_a" [0.1 0.6 1.4] "float beta_n" 0.5 "float alpha" 3\n'
               + tuft(rng, 0.7, 150) + 'AttributeEnd\n')
    # Two wide strands in front of the tufts, lit from one side by the sun, where the offset h
    # across the fibre shows (pixels average it out in thin ones).
    out.append('AttributeBegin\n  Material "hair"\n'
               '  Shape "curve" "point3 P" [-0.35 1.1 -0.8  -0.3 0.6 -0.8  -0.4 0 -0.8  -0.35 -0.5 -0.8] "float width" 0.08\n'
               '  Material "hair" "rgb sigma_a" [0.1 0.6 1.4]\n'
               '  Shape "curve" "point3 P" [0.35 1.1 -0.8  0.4 0.6 -0.8  0.3 0 -0.8  0.35 -0.5 -0.8] "float width" 0.08\n'
               'AttributeEnd\n')
    return "".join(out)


def wide_fibres_scene():
    """Straight curves many pixels wide, so that what changes across a fibre (a cylinder's
    normal, the hair's offset h) shows in blocks of pixels, not only within a pixel. (pbrt-v4
    subdivides a curve more coarsely the wider it is: straight ones it places exactly.) Nothing but the sun and
    the sky lights them, so pbrt-v4's offsets of rays that leave them meet nothing."""
    return header("# A wide hair fibre and a wide \"cylinder\" curve under the sun and the sky (see\n"
                  "# scenes/generators/make_curve_scenes.py). Reference: tests/data/pbrt-v4/shapes/wide-fibres.exr.\n",
                  "wide-fibres", 64) + """WorldBegin
LightSource "infinite" "rgb L" [0.2 0.25 0.3]
LightSource "distant" "point3 from" [2 1 -1] "point3 to" [0 0 0] "rgb L" [3 2.9 2.7]
AttributeBegin
  Material "hair" "float eumelanin" 0.3 "float beta_m" 0.25
  Shape "curve" "point3 P" [-0.65 1.2 0  -0.6 0.4 0  -0.55 -0.3 0  -0.5 -1 0] "float width" 0.55
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [0.7 0.7 0.7]
  Shape "curve" "string type" "cylinder" "point3 P" [0.5 1.2 0  0.55 0.4 0  0.6 -0.3 0  0.65 -1 0]
    "float width" 0.55
AttributeEnd
"""


def main():
    folder = sys.argv[1]
    rng = random.Random(2026)
    with open(folder + "/curves.pbrt", "w") as f:
        f.write(curves_scene(rng))
    with open(folder + "/hair.pbrt", "w") as f:
        f.write(hair_scene(rng))
    with open(folder + "/wide-fibres.pbrt", "w") as f:
        f.write(wide_fibres_scene())


if __name__ == "__main__":
    main()
