#!/usr/bin/env python3
"""Writes two small BSDF files in the RGL format of Dupuy and Jakob 2018 ("An Adaptive
Parameterization for Efficient Material Acquisition and Rendering"), the format of pbrt-v4's
"measured" material, for scenes/materials/measured.pbrt and the tests:

  scenes/materials/measured-isotropic.bsdf    a rough gold-coloured metal (GGX, alpha 0.25)
  scenes/materials/measured-anisotropic.bsdf  a brushed blue-grey metal (GGX, alpha 0.1 x 0.4)

Real RGL files are measurements and are not ours to copy; these tabulate an analytic microfacet
model on the format's grids instead, so that pbrt-v4 and Caustica read the same tables.

The format is Mitsuba's "tensor file": the 12 bytes "tensor_file\\0", version 1.0, the number of
fields, then for each field its name, rank, type, data offset and shape, and the data. The
fields (all float32 unless said otherwise), in the coordinates u = (sqrt(2 theta / pi),
phi / (2 pi) + 1/2) of a direction's spherical angles:
  theta_i, phi_i   the incident directions measured (radians);
  ndf [y, x]       the microfacet distribution D(wm) at u_wm = (x, y);
  sigma [y, x]     the projected area of the microsurface seen from u_wo;
  vndf [phi_i, theta_i, y, x]   the distribution of visible normals in u_wm (relative azimuth
                   phi_m - phi_i for isotropic files, which have at most 2 phi_i);
  luminance [phi_i, theta_i, y, x]   a density over the sample space of the vndf warp, by which
                   directions are importance sampled;
  spectra [phi_i, theta_i, wavelength, y, x]   the reflectance factor at each wavelength, over
                   the sample space: f(wo, wi) = spectra * D(wm) / (4 sigma(wo) cos theta_i);
  wavelengths      nm; description (uint8 text); jacobian (uint8 [1]).

Here spectra = R(lambda) t(theta_i) s(x, y) with a smooth s that varies over the sample space
(so that reading it back needs the exact inverse of the vndf warp), and luminance = s.
Pure Python: no numpy needed. Usage: scenes/generators/make_measured_bsdfs.py [OUTDIR]
"""
import math
import os
import struct
import sys

FLOAT32, UINT8 = 10, 1


def theta_of(u):
    return u * u * math.pi / 2


def phi_of(u):
    return (2 * u - 1) * math.pi


def direction(theta, phi):
    s = math.sin(theta)
    return (s * math.cos(phi), s * math.sin(phi), math.cos(theta))


def ggx_d(m, ax, ay):
    cos2 = m[2] * m[2]
    if cos2 <= 0:
        return 0.0
    e = (m[0] * m[0] / (ax * ax) + m[1] * m[1] / (ay * ay)) / cos2
    return 1 / (math.pi * ax * ay * cos2 * cos2 * (1 + e) ** 2)


def ggx_sigma(w, ax, ay):
    # Projected area of the GGX microsurface seen from w: cos theta (1 + Lambda(w)), written so
    # that it stays finite at grazing angles.
    sin2 = w[0] * w[0] + w[1] * w[1]
    if sin2 <= 0:
        return w[2]
    a2 = (w[0] * w[0] * ax * ax + w[1] * w[1] * ay * ay) / sin2
    return 0.5 * (w[2] + math.sqrt(w[2] * w[2] + a2 * sin2))


def grid(n):
    return [i / (n - 1) for i in range(n)]


def write_tensor_file(path, fields):
    """fields: list of (name, dtype, shape, bytes)."""
    header = b"tensor_file\0" + bytes([1, 0]) + struct.pack("<I", len(fields))
    size = len(header)
    for name, _, shape, _ in fields:
        size += 2 + len(name) + 2 + 1 + 8 + 8 * len(shape)
    out, data, offset = [header], [], size
    for name, dtype, shape, blob in fields:
        out.append(struct.pack("<H", len(name)) + name.encode() + struct.pack("<HBQ", len(shape), dtype, offset))
        out.append(b"".join(struct.pack("<Q", s) for s in shape))
        data.append(blob)
        offset += len(blob)
    with open(path, "wb") as f:
        f.write(b"".join(out) + b"".join(data))


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def make(path, description, ax, ay, n_phi_i, n_theta_i, n_u, wavelengths, reflectance):
    isotropic = n_phi_i <= 2
    theta_i = [theta_of(u) for u in grid(n_theta_i)]
    phi_i = [0.0] if n_phi_i == 1 else [phi_of(u) for u in grid(n_phi_i)]
    us = grid(n_u)

    ndf, sigma = [], []
    for y in us:
        for x in us:
            w = direction(theta_of(x), phi_of(y))
            ndf.append(ggx_d(w, ax, ay))
            sigma.append(ggx_sigma(w, ax, ay))

    vndf, luminance, spectra = [], [], []
    for p in phi_i:
        for t in theta_i:
            wo = direction(t, p)
            for y in us:
                for x in us:
                    theta_m, phi_m = theta_of(x), phi_of(y)
                    wm = direction(theta_m, phi_m + (p if isotropic else 0))
                    visible = max(0.0, sum(a * b for a, b in zip(wo, wm)))
                    jacobian = 2 * math.pi ** 2 * x * math.sin(theta_m)
                    vndf.append(visible * ggx_d(wm, ax, ay) / ggx_sigma(wo, ax, ay) * jacobian)
            # The sample-space shape s, and the angular factor t of the reflectance.
            shape = [(0.7 + 0.3 * x) * (0.85 + 0.15 * math.cos(2 * math.pi * y)) for y in us for x in us]
            luminance += shape
            t_factor = 1 - 0.5 * math.sin(t) ** 2
            for lam in wavelengths:
                r = reflectance(lam) * t_factor
                spectra += [r * s for s in shape]

    n_l = len(wavelengths)
    fields = [
        ("description", UINT8, [len(description)], description.encode()),
        ("jacobian", UINT8, [1], bytes([1])),
        ("theta_i", FLOAT32, [n_theta_i], floats(theta_i)),
        ("phi_i", FLOAT32, [len(phi_i)], floats(phi_i)),
        ("wavelengths", FLOAT32, [n_l], floats(wavelengths)),
        ("ndf", FLOAT32, [n_u, n_u], floats(ndf)),
        ("sigma", FLOAT32, [n_u, n_u], floats(sigma)),
        ("vndf", FLOAT32, [len(phi_i), n_theta_i, n_u, n_u], floats(vndf)),
        ("luminance", FLOAT32, [len(phi_i), n_theta_i, n_u, n_u], floats(luminance)),
        ("spectra", FLOAT32, [len(phi_i), n_theta_i, n_l, n_u, n_u], floats(spectra)),
    ]
    write_tensor_file(path, fields)


def gold(lam):
    return 0.25 + 0.7 / (1 + math.exp(-(lam - 520) / 25))


def steel_blue(lam):
    return 0.75 - 0.35 * (lam - 360) / 470


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "materials")
    os.makedirs(out, exist_ok=True)
    wavelengths = [360 + 67 * i for i in range(8)]
    make(os.path.join(out, "measured-isotropic.bsdf"),
         "Synthetic isotropic GGX metal (alpha 0.25), Caustica test data", 0.25, 0.25,
         1, 8, 16, wavelengths, gold)
    make(os.path.join(out, "measured-anisotropic.bsdf"),
         "Synthetic anisotropic GGX metal (alpha 0.1 x 0.4), Caustica test data", 0.1, 0.4,
         5, 6, 12, wavelengths, steel_blue)


if __name__ == "__main__":
    main()
