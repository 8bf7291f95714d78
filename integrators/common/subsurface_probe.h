// Where light that entered a subsurface-scattering surface leaves it: probe-ray sampling of the
// exit point of a separable BSSRDF with a radial profile R(r) (subsurface_profile.h), the
// technique of King et al. 2013 ("BSSRDF Importance Sampling") as structured by pbrt-v3
// (SeparableBSSRDF::Sample_Sp and Pdf_Sp, "Physically Based Rendering", 3rd ed., section 15.4).
//
// A strategy is a projection axis of the entry point's frame (tangent x, tangent y or the
// geometric normal, with probabilities 1/4, 1/4, 1/2) and a wavelength channel (uniform over the
// channels with energy). It draws a radius r from that channel's profile and a uniform angle in
// the plane perpendicular to the axis, then probes the segment of length 2 sqrt(r_max^2 - r^2)
// along the axis through that planar point, centred on the entry's plane: exactly the points
// within r_max of the entry, the profile's reach. Every hit on the segment with the entry's
// material is a candidate and one is chosen uniformly.
//
// The estimate of int_surface R(|x - entry|) dA(x) is R(|x - entry|) n / sum_s P(s) q_s(x), with
// n the number of candidates and q_s(x) = pdf_area_c(r_axis(x)) |n_x . axis| [|x - entry| <
// r_max,c] the density with which strategy s = (axis, c) reaches x by projection, before the
// choice among hits. This is one-sample multiple importance sampling with weights proportional
// to P(s) q_s, which sum to one over the strategies; the weight of the strategy that was used
// cancels its own density q_s / n (n counted on its own segment), so the estimator is unbiased
// without the hit counts the other strategies would see through x. (pbrt-v3 uses the same
// estimator, without the reach condition in q_s, which loses the little energy that only a
// channel with a longer reach can find.)
#pragma once

#include "geometry/interaction.h"
#include "materials/subsurface_profile.h"

#include <functional>
#include <optional>
#include <vector>

namespace caustica {

class Scene;

// Appends to `hits` every surface crossed by segment.o + t segment.d for 0 < t <= segment.t_max,
// in any order, whatever its material.
using ProbeHitGatherer =
    std::function<void(const Ray &segment, std::vector<SurfaceInteraction> &hits)>;

// The probe's choice of axis: 0 and 1 the entry frame's tangents, 2 its geometric normal.
inline constexpr float ProbeAxisProbability[3] = {0.25f, 0.25f, 0.5f};

struct SubsurfaceExit {
    // The exit point, as the gatherer reported it (its wo faces back along the probe, which is
    // not a direction light leaves in: the integrator chooses that).
    SurfaceInteraction si;
    // R(|exit - entry|) / pdf for every channel: its expectation is the profile's integral over
    // the surface within reach (the albedo, on a plane).
    SampledSpectrum weight;
    // Density of this exit per unit surface area, all strategies combined and divided by the
    // number of candidates.
    float pdf = 0;
    int axis = 0, channel = 0; // the strategy used
    int candidates = 0;        // hits with the entry's material on the probe segment
};

// sum_s P(s) q_s(p): the combined density, per unit surface area, with which the strategies
// project onto a surface point p with geometric normal n, before the choice among candidates.
float subsurface_projected_pdf(const SurfaceInteraction &entry, const SubsurfaceProfile &profile,
                               Vec3f p, Vec3f n);

// All hits along the segment by repeated closest-hit queries, each continuing from the previous
// hit towards the segment's end.
void gather_scene_hits(const Scene &scene, const Ray &segment,
                       std::vector<SurfaceInteraction> &hits);

// One per thread: keeps its hit buffer between calls.
class SubsurfaceProbeSampler {
  public:
    // u_strategy picks the axis, the channel and then the candidate (each remapping the rest of
    // it, as pbrt-v3 does); u is (radius, angle). Empty when the sampled radius is beyond reach
    // or the probe finds no candidate: a zero-valued sample, not a failure to retry.
    std::optional<SubsurfaceExit> sample(const SurfaceInteraction &entry,
                                         const SubsurfaceProfile &profile, float u_strategy,
                                         Vec2f u, const ProbeHitGatherer &gather);
    std::optional<SubsurfaceExit> sample(const SurfaceInteraction &entry,
                                         const SubsurfaceProfile &profile, float u_strategy,
                                         Vec2f u, const Scene &scene);

  private:
    std::vector<SurfaceInteraction> hits_;
};

} // namespace caustica
