#include "integrators/common/subsurface_probe.h"

#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {

// The entry's frame and the channels strategies may use, shared by sampling and the pdf so that
// both describe the same set of strategies.
struct ProbeStrategies {
    Vec3f origin;
    Vec3f axes[3]; // tangent x, tangent y, geometric normal
    int channels[NumWavelengths];
    int channel_count = 0;
    float max_radius[NumWavelengths] = {};

    ProbeStrategies(const SurfaceInteraction &entry, const SubsurfaceProfile &profile)
        : origin(entry.p) {
        Frame frame = Frame::from_xz(entry.dpdu, entry.n);
        axes[0] = frame.x;
        axes[1] = frame.y;
        axes[2] = frame.z;
        SampledSpectrum albedo = profile.albedo();
        for (int c = 0; c < NumWavelengths; ++c) {
            max_radius[c] = profile.max_radius(c);
            if (max_radius[c] > 0 && albedo[c] > 0) channels[channel_count++] = c;
        }
    }

    float projected_pdf(const SubsurfaceProfile &profile, Vec3f p, Vec3f n) const {
        Vec3f offset = p - origin;
        Vec3f local{dot(offset, axes[0]), dot(offset, axes[1]), dot(offset, axes[2])};
        float distance2 = length_squared(local);
        float pdf = 0;
        for (int axis = 0; axis < 3; ++axis) {
            // Distance from the entry in the plane perpendicular to the axis, from the other two
            // coordinates (not distance^2 - along^2, which cancels near the axis, where the
            // profile's density is largest).
            float r = std::sqrt(sqr(local[(axis + 1) % 3]) + sqr(local[(axis + 2) % 3]));
            float cosine = abs_dot(n, axes[axis]);
            if (cosine == 0) continue;
            SampledSpectrum pdf_area = profile.pdf_area(r);
            for (int k = 0; k < channel_count; ++k) {
                int c = channels[k];
                if (distance2 < sqr(max_radius[c]))
                    pdf += ProbeAxisProbability[axis] * pdf_area[c] * cosine;
            }
        }
        return pdf / float(channel_count);
    }
};

// Uniform choice among n options from u in [0, 1); u is rescaled to [0, 1) within the choice.
int choose(int n, float *u) {
    int i = std::min(int(*u * n), n - 1);
    *u = std::min(*u * n - i, OneMinusEpsilon);
    return i;
}

// A probe crossing more surfaces than this runs through coincident or degenerate geometry; the
// cap bounds its cost.
constexpr int MaxProbeHits = 64;

} // namespace

float subsurface_projected_pdf(const SurfaceInteraction &entry, const SubsurfaceProfile &profile,
                               Vec3f p, Vec3f n) {
    ProbeStrategies strategies(entry, profile);
    if (strategies.channel_count == 0) return 0;
    return strategies.projected_pdf(profile, p, n);
}

void gather_scene_hits(const Scene &scene, const Ray &segment,
                       std::vector<SurfaceInteraction> &hits) {
    Vec3f end = segment.at(segment.t_max);
    Ray ray = segment;
    SurfaceInteraction si;
    for (int i = 0; i < MaxProbeHits && scene.intersect(ray, &si); ++i) {
        hits.push_back(si);
        ray = si.spawn_ray_to(end);
    }
}

std::optional<SubsurfaceExit> SubsurfaceProbeSampler::sample(const SurfaceInteraction &entry,
                                                             const SubsurfaceProfile &profile,
                                                             float u_strategy, Vec2f u,
                                                             const ProbeHitGatherer &gather) {
    ProbeStrategies strategies(entry, profile);
    if (strategies.channel_count == 0) return {};

    // Strategy: the axis (probabilities 1/4, 1/4, 1/2), then the channel.
    int axis;
    if (u_strategy < 0.5f) {
        axis = 2;
        u_strategy = u_strategy * 2;
    } else if (u_strategy < 0.75f) {
        axis = 0;
        u_strategy = (u_strategy - 0.5f) * 4;
    } else {
        axis = 1;
        u_strategy = (u_strategy - 0.75f) * 4;
    }
    u_strategy = std::min(u_strategy, OneMinusEpsilon);
    int channel = strategies.channels[choose(strategies.channel_count, &u_strategy)];

    // A point of the plane perpendicular to the axis, and the probe through it.
    float r = profile.sample_radius(channel, u.x);
    float r_max = strategies.max_radius[channel];
    if (!(r < r_max)) return {};
    float phi = 2 * Pi * u.y;
    const Vec3f &a = strategies.axes[axis];
    const Vec3f &b1 = strategies.axes[(axis + 1) % 3];
    const Vec3f &b2 = strategies.axes[(axis + 2) % 3];
    float half_length = std::sqrt(sqr(r_max) - sqr(r));
    Vec3f start = entry.p + (b1 * std::cos(phi) + b2 * std::sin(phi)) * r - a * half_length;

    hits_.clear();
    gather(Ray{start, a, 2 * half_length, entry.time}, hits_);
    std::erase_if(hits_,
                  [&](const SurfaceInteraction &hit) { return hit.material != entry.material; });
    if (hits_.empty()) return {};

    SubsurfaceExit exit;
    exit.si = hits_[choose(int(hits_.size()), &u_strategy)];
    exit.axis = axis;
    exit.channel = channel;
    exit.candidates = int(hits_.size());
    float projected = strategies.projected_pdf(profile, exit.si.p, exit.si.n);
    if (!(projected > 0)) return {};
    exit.pdf = projected / float(exit.candidates);
    exit.weight = profile.evaluate(distance(exit.si.p, entry.p)) / exit.pdf;
    return exit;
}

std::optional<SubsurfaceExit> SubsurfaceProbeSampler::sample(const SurfaceInteraction &entry,
                                                             const SubsurfaceProfile &profile,
                                                             float u_strategy, Vec2f u,
                                                             const Scene &scene) {
    return sample(entry, profile, u_strategy, u,
                  [&scene](const Ray &segment, std::vector<SurfaceInteraction> &hits) {
                      gather_scene_hits(scene, segment, hits);
                  });
}

} // namespace caustica
