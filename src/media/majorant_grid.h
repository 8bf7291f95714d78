// A coarse grid over a heterogeneous medium's bounds that holds, per cell, an upper bound of the
// medium's density anywhere in the cell (pbrt-v4's MajorantGrid, section 11.4.3). Delta and ratio
// tracking sample tentative collisions at the rate of the bound of the cell they are in, so a
// tight bound per cell makes sparse and empty regions cheap: an empty cell is crossed without a
// single collision. The cells along a ray are visited in order by a 3D digital differential
// analyzer (Amanatides and Woo 1987, "A Fast Voxel Traversal Algorithm for Ray Tracing").
#pragma once

#include "core/vecmath.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace caustica {

class MajorantGrid {
  public:
    // A grid of nx x ny x nz cells over the unit cube, every bound zero.
    MajorantGrid(int nx, int ny, int nz);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int nz() const { return nz_; }
    float at(int x, int y, int z) const { return bounds_[(size_t(z) * ny_ + y) * nx_ + x]; }
    void set(int x, int y, int z, float bound) { bounds_[(size_t(z) * ny_ + y) * nx_ + x] = bound; }
    // The largest bound of all cells.
    float max_bound() const;
    // The part of the unit cube that cell (x, y, z) covers.
    Bounds3f cell_bounds(int x, int y, int z) const;

    // One stretch of a ray inside one cell: parameters [t0, t1) and the cell's bound.
    struct Segment {
        float t0, t1, bound;
    };
    // Visits the cells that the ray o + t d (unit-cube coordinates, d need not be unit) crosses
    // for t in [t_min, t_max), in order along the ray, calling visit(Segment) for each; stops early
    // when visit returns false.
    template <typename Visit> void traverse(Vec3f o, Vec3f d, float t_min, float t_max, Visit visit) const;

  private:
    int nx_, ny_, nz_;
    std::vector<float> bounds_;
};

// Parameters [t0, t1] of the ray o + t d inside the unit cube, clipped to [t_min, t_max]; false
// when it misses.
bool clip_to_unit_cube(Vec3f o, Vec3f d, float t_min, float t_max, float *t0, float *t1);

template <typename Visit>
void MajorantGrid::traverse(Vec3f o, Vec3f d, float t_min, float t_max, Visit visit) const {
    float t_enter, t_exit;
    if (!clip_to_unit_cube(o, d, t_min, t_max, &t_enter, &t_exit)) return;
    const int res[3] = {nx_, ny_, nz_};
    const float origin[3] = {o.x, o.y, o.z}, dir[3] = {d.x, d.y, d.z};
    int cell[3], step[3], out[3];
    float next_t[3], delta_t[3];
    for (int a = 0; a < 3; ++a) {
        // The cell holding the entry point, from the entry point itself (not the origin, which may
        // lie far outside the grid).
        const float p = origin[a] + dir[a] * t_enter;
        cell[a] = std::clamp(int(p * float(res[a])), 0, res[a] - 1);
        if (dir[a] == 0) {
            next_t[a] = Infinity;
            delta_t[a] = Infinity;
            step[a] = 0;
            out[a] = -2;
            continue;
        }
        const float inv = 1 / dir[a];
        const int boundary = dir[a] > 0 ? cell[a] + 1 : cell[a];
        next_t[a] = (float(boundary) / float(res[a]) - origin[a]) * inv;
        delta_t[a] = std::abs(inv / float(res[a]));
        step[a] = dir[a] > 0 ? 1 : -1;
        out[a] = dir[a] > 0 ? res[a] : -1;
    }
    float t = t_enter;
    while (t < t_exit) {
        // The axis whose cell boundary comes first.
        int axis = next_t[0] < next_t[1] ? (next_t[0] < next_t[2] ? 0 : 2) : (next_t[1] < next_t[2] ? 1 : 2);
        const float t_next = std::min(std::max(next_t[axis], t), t_exit);
        if (t_next > t && !visit(Segment{t, t_next, at(cell[0], cell[1], cell[2])})) return;
        t = t_next;
        if (t >= t_exit) return;
        cell[axis] += step[axis];
        if (cell[axis] == out[axis]) return;
        next_t[axis] += delta_t[axis];
    }
}

} // namespace caustica
