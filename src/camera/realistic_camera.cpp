#include "camera/realistic_camera.h"

#include "core/sampling.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// Rays traced per ring of film radii when bounding the exit pupil. pbrt-v4 traces 2^20; the
// bounds only need to contain the pupil (a looser one costs rejected rays, not bias), and the
// margin of twice the sample spacing covers what 2^16 points miss.
constexpr int PupilSamplesPerRing = 1 << 16;

} // namespace

RealisticCamera::RealisticCamera(const Transform &world_from_camera, const FilmExtent &film, LensSystem lens,
                                 std::optional<ApertureMask> mask)
    : world_from_camera_(world_from_camera), film_(film), lens_(std::move(lens)), mask_(std::move(mask)) {
    // The film's physical size: the diagonal split in the image's aspect ratio.
    const double aspect = double(film_.full_resolution.y) / double(film_.full_resolution.x);
    const double width = std::sqrt(double(film_.diagonal) * film_.diagonal / (1 + aspect * aspect));
    half_width_ = width / 2;
    half_height_ = aspect * width / 2;
    const double max_radius = double(film_.diagonal) / 2;
    tbb::parallel_for(0, PupilRings, [&](int i) {
        pupil_bounds_[i] = bound_exit_pupil(max_radius * i / PupilRings, max_radius * (i + 1) / PupilRings);
    });
}

PupilBounds RealisticCamera::bound_exit_pupil(double r0, double r1) const {
    const double extent = 1.5 * lens_.rear_radius();
    PupilBounds bounds;
    bool found = false;
    for (int i = 0; i < PupilSamplesPerRing; ++i) {
        const double r = r0 + (r1 - r0) * (i + 0.5) / PupilSamplesPerRing;
        const double x = -extent + 2 * extent * radical_inverse(2, i);
        const double y = -extent + 2 * extent * radical_inverse(3, i);
        if (found && x >= bounds.x0 && x <= bounds.x1 && y >= bounds.y0 && y <= bounds.y1) continue;
        const Vec3d p_film{r, 0, 0}, p_rear{x, y, lens_.rear_z()};
        if (!lens_.trace_from_film({p_film, p_rear - p_film})) continue;
        if (!found) bounds = {x, y, x, y};
        bounds = {std::min(bounds.x0, x), std::min(bounds.y0, y), std::max(bounds.x1, x), std::max(bounds.y1, y)};
        found = true;
    }
    if (!found) return {};
    const double margin = 2 * (2 * extent * std::sqrt(2.0)) / std::sqrt(double(PupilSamplesPerRing));
    return {bounds.x0 - margin, bounds.y0 - margin, bounds.x1 + margin, bounds.y1 + margin};
}

bool RealisticCamera::transmits() const {
    return std::any_of(pupil_bounds_.begin(), pupil_bounds_.end(), [](const PupilBounds &b) { return !b.empty(); });
}

std::optional<CameraRay> RealisticCamera::ray_at_rest(const CameraSample &sample, const SampledWavelengths &) const {
    // The film point: raster x runs against camera x, because the lens turns the image over.
    const double sx = double(sample.p_film.x) / film_.full_resolution.x;
    const double sy = double(sample.p_film.y) / film_.full_resolution.y;
    const Vec3d p_film{-(-half_width_ + 2 * half_width_ * sx), -half_height_ + 2 * half_height_ * sy, 0};

    // A point of the pupil bounds of the film point's ring, rotated from the +x axis, where the
    // bounds were found, to the film point's azimuth.
    const double r_film = std::sqrt(p_film.x * p_film.x + p_film.y * p_film.y);
    const int ring = std::min(PupilRings - 1, int(r_film / (double(film_.diagonal) / 2) * PupilRings));
    const PupilBounds &bounds = pupil_bounds_[ring];
    if (bounds.empty()) return std::nullopt;
    const double lx = bounds.x0 + (bounds.x1 - bounds.x0) * sample.p_lens.x;
    const double ly = bounds.y0 + (bounds.y1 - bounds.y0) * sample.p_lens.y;
    const double cos_phi = r_film > 0 ? p_film.x / r_film : 1, sin_phi = r_film > 0 ? p_film.y / r_film : 0;
    const Vec3d p_pupil{cos_phi * lx - sin_phi * ly, sin_phi * lx + cos_phi * ly, lens_.rear_z()};

    const LensRay from_film{p_film, p_pupil - p_film};
    float mask_weight = 1;
    std::optional<LensRay> out = lens_.trace_from_film(from_film, mask_ ? &*mask_ : nullptr, &mask_weight);
    if (!out) return std::nullopt;

    // Irradiance at the film point from the pupil: L cos^4(theta) / d^2 over the pupil's area,
    // sampled uniformly over the bounds' area A (pbrt-v4 5.4.6).
    const double cos_theta = normalize(from_film.d).z;
    const double cos2 = cos_theta * cos_theta;
    const double weight = mask_weight * cos2 * cos2 * bounds.area() / (lens_.rear_z() * lens_.rear_z());

    CameraRay cr;
    cr.ray.o = world_from_camera_.apply_point(out->o.to_float());
    cr.ray.d = normalize(world_from_camera_.apply_vector(normalize(out->d).to_float()));
    cr.weight = SampledSpectrum(float(weight));
    return cr;
}

} // namespace caustica
