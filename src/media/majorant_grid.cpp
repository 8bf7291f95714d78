#include "media/majorant_grid.h"

namespace caustica {

MajorantGrid::MajorantGrid(int nx, int ny, int nz)
    : nx_(nx), ny_(ny), nz_(nz), bounds_(size_t(nx) * ny * nz, 0.f) {}

float MajorantGrid::max_bound() const {
    float m = 0;
    for (float b : bounds_) m = std::max(m, b);
    return m;
}

Bounds3f MajorantGrid::cell_bounds(int x, int y, int z) const {
    return {{float(x) / nx_, float(y) / ny_, float(z) / nz_},
            {float(x + 1) / nx_, float(y + 1) / ny_, float(z + 1) / nz_}};
}

bool clip_to_unit_cube(Vec3f o, Vec3f d, float t_min, float t_max, float *t0, float *t1) {
    const float origin[3] = {o.x, o.y, o.z}, dir[3] = {d.x, d.y, d.z};
    float lo = t_min, hi = t_max;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0) {
            if (origin[a] < 0 || origin[a] > 1) return false;
            continue;
        }
        float near = (0 - origin[a]) / dir[a], far = (1 - origin[a]) / dir[a];
        if (near > far) std::swap(near, far);
        lo = std::max(lo, near);
        hi = std::min(hi, far);
        if (lo > hi) return false;
    }
    *t0 = lo;
    *t1 = hi;
    return lo < hi;
}

} // namespace caustica
