// Geometry of a round brilliant-cut diamond (57 facets: table, 8 stars, 8 bezels, 16 upper
// girdle facets on the crown; 8 pavilion mains and 16 lower girdle facets on the pavilion),
// with Tolkowsky's (1919) ideal proportions by default. Each facet is a plane; the stone is the
// intersection of their half-spaces with a faceted girdle, computed exactly, so any consistent
// set of angles yields a closed convex mesh.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace caustica::diamond {

struct Proportions {
    double table = 0.53;            // table width / girdle diameter
    double crown_angle = 34.5;      // degrees, bezel facets against the girdle plane
    double pavilion_angle = 40.75;  // degrees, pavilion mains against the girdle plane
    double star_angle = 23.1;       // degrees: stars reach half-way to the girdle
    double upper_girdle_angle = 41.0;
    double lower_girdle_angle = 42.0;
    double girdle_thickness = 0.02; // / diameter
    int girdle_segments = 64;       // vertical planes approximating the round girdle
};

struct Vec {
    double x = 0, y = 0, z = 0;
    Vec operator+(Vec o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec operator-(Vec o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec operator*(double s) const { return {x * s, y * s, z * s}; }
};
inline double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

enum class FacetKind { Table, Star, Bezel, UpperGirdle, PavilionMain, LowerGirdle, Girdle };

struct Plane {
    Vec n;          // outward unit normal
    double d;       // points x inside satisfy dot(n, x) <= d
    FacetKind kind;
};

struct Face {
    FacetKind kind;
    std::vector<Vec> vertices; // counter-clockwise seen from outside
};

inline constexpr double kPi = 3.14159265358979323846;

// Outward normal of a facet tilted by `tilt` degrees from the girdle plane, facing azimuth phi,
// on the crown (up = +1) or pavilion (up = -1).
inline Vec tilted_normal(double phi, double tilt_deg, double up) {
    double t = tilt_deg * kPi / 180;
    return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), up * std::cos(t)};
}

// The facet planes for a stone of girdle radius 1, girdle centred on z = 0.
inline std::vector<Plane> facet_planes(const Proportions &p) {
    std::vector<Plane> planes;
    const double half_girdle = p.girdle_thickness; // thickness relative to the diameter 2
    // The table is an octagon with corners at radius `table` (relative to the girdle radius);
    // the bezels run from its corners down to the girdle at the crown angle, and the stars
    // share its edges.
    const double table_corner = p.table;
    const double table_z = half_girdle + (1 - table_corner) * std::tan(p.crown_angle * kPi / 180);
    planes.push_back({{0, 0, 1}, table_z, FacetKind::Table});
    auto through = [](Vec n, Vec point, FacetKind kind) { return Plane{n, dot(n, point), kind}; };
    for (int k = 0; k < 8; ++k) {
        double phi = k * kPi / 4, phi_star = phi + kPi / 8;
        // Bezels touch the girdle at their azimuth; stars share an edge with the table.
        planes.push_back(through(tilted_normal(phi, p.crown_angle, 1),
                                 {std::cos(phi), std::sin(phi), half_girdle}, FacetKind::Bezel));
        const double edge = p.table * std::cos(kPi / 8);
        Vec table_edge{edge * std::cos(phi_star), edge * std::sin(phi_star), table_z};
        planes.push_back(through(tilted_normal(phi_star, p.star_angle, 1), table_edge, FacetKind::Star));
        planes.push_back(through(tilted_normal(phi, p.pavilion_angle, -1),
                                 {std::cos(phi), std::sin(phi), -half_girdle}, FacetKind::PavilionMain));
        for (double side : {-1.0, 1.0}) {
            // Upper and lower girdle facets come in pairs straddling the azimuth between two
            // mains, where the girdle is reached.
            double phi_half = phi + kPi / 8 + side * kPi / 16;
            planes.push_back(through(tilted_normal(phi_half, p.upper_girdle_angle, 1),
                                     {std::cos(phi_half), std::sin(phi_half), half_girdle},
                                     FacetKind::UpperGirdle));
            planes.push_back(through(tilted_normal(phi_half, p.lower_girdle_angle, -1),
                                     {std::cos(phi_half), std::sin(phi_half), -half_girdle},
                                     FacetKind::LowerGirdle));
        }
    }
    for (int i = 0; i < p.girdle_segments; ++i) {
        double phi = (i + 0.5) * 2 * kPi / p.girdle_segments;
        planes.push_back({{std::cos(phi), std::sin(phi), 0}, 1.0, FacetKind::Girdle});
    }
    return planes;
}

// Intersection of the half-spaces: every vertex is a triple of planes meeting at a point that
// violates no other plane; each plane's vertices, sorted by angle, form its face.
inline std::vector<Face> build_faces(const std::vector<Plane> &planes) {
    const double eps = 1e-9;
    std::vector<std::vector<Vec>> on_plane(planes.size());
    const size_t n = planes.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                Vec a = planes[i].n, b = planes[j].n, c = planes[k].n;
                double det = dot(a, cross(b, c));
                if (std::abs(det) < 1e-12) continue;
                Vec x = (cross(b, c) * planes[i].d + cross(c, a) * planes[j].d + cross(a, b) * planes[k].d) * (1 / det);
                bool inside = true;
                for (size_t m = 0; m < n && inside; ++m) inside = dot(planes[m].n, x) <= planes[m].d + eps;
                if (!inside) continue;
                for (size_t m = 0; m < n; ++m)
                    if (std::abs(dot(planes[m].n, x) - planes[m].d) < 1e-7) {
                        bool duplicate = false;
                        for (const Vec &v : on_plane[m]) duplicate |= dot(v - x, v - x) < 1e-14;
                        if (!duplicate) on_plane[m].push_back(x);
                    }
            }
    std::vector<Face> faces;
    for (size_t m = 0; m < n; ++m) {
        auto &verts = on_plane[m];
        if (verts.size() < 3) continue;
        Vec centre;
        for (const Vec &v : verts) centre = centre + v;
        centre = centre * (1.0 / verts.size());
        Vec nrm = planes[m].n;
        Vec u = std::abs(nrm.z) < 0.9 ? cross(nrm, Vec{0, 0, 1}) : cross(nrm, Vec{1, 0, 0});
        u = u * (1 / std::sqrt(dot(u, u)));
        Vec w = cross(nrm, u);
        std::sort(verts.begin(), verts.end(), [&](const Vec &a, const Vec &b) {
            return std::atan2(dot(a - centre, w), dot(a - centre, u)) <
                   std::atan2(dot(b - centre, w), dot(b - centre, u));
        });
        faces.push_back({planes[m].kind, verts});
    }
    return faces;
}

} // namespace caustica::diamond
