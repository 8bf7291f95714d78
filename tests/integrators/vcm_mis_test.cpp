// vcm's multiple-importance weights (vcm_mis.h) against the power heuristic computed from the
// explicit densities of every strategy along the whole path.
//
// A path x_0 .. x_k runs from a point on an area light (x_0) to the lens (x_k); its scattering
// vertices lie on surfaces (some specular) or in media. Each vertex has two solid-angle
// densities: fwd, of sampling the next vertex when arriving from the previous one (the light
// subpath's direction), and rev, the converse (the camera subpath's); a medium vertex's phase
// function is symmetric, so there the two are equal, and a specular vertex's are equal deltas.
// In the area measure, x_i is generated from the light side with density
//   p_fwd(i) = fwd(i-1) |cos_i| / d^2(i-1, i)  (p_fwd(0) = light choice x position density, and
//   the light's emission density stands for fwd(0)),
// and from the camera side with
//   p_rev(i) = rev(i+1) |cos_i| / d^2(i, i+1)  (the camera's directional density, times the
//   pixels of the frame, stands for rev(k) at x_{k-1}).
// The strategies (Georgiev et al. 2012) and their densities:
//   - the camera path hits the light: prod_{i<k} p_rev(i);
//   - a connection between x_{s-1} and x_s (s = 1 is light sampling): prod_{i<s} p_fwd(i) prod_{i>=s} p_rev(i),
//     for non-specular x_{s-1} and x_s; s = k is light tracing, whose N light paths multiply it by N;
//   - a merge at non-specular x_j: prod_{i<=j} p_fwd(i) prod_{i>=j} p_rev(i) times eta_j, the kernel's
//     region times N (pi r^2 N on a surface, 4/3 pi r^3 N in a medium).
// Specular deltas appear once in every remaining strategy's density and cancel. The power
// heuristic weight of strategy j is p_j^2 / sum_i p_i^2.
// A light path may also start inside an emissive medium (integrators/common/medium_emission.h):
// x_0 then has no surface, its emission is uniform over the sphere, s = 1 joins x_1 to it, and
// the camera side's density of x_0 has the free flight's sigma e^(-sigma d) where a light's
// has its cosine. The recursion of vcm_mis.h must give
// the same weights, and so weights that sum to one, for vcm and, without connections, for bpm.
// Wrong recursions fail (the negative controls at the end).
#include "integrators/common/medium_emission.h"
#include "integrators/vcm/vcm_mis.h"

#include "core/vecmath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace caustica {
namespace {

struct Vertex {
    Vec3f p, n;            // n zero: a medium vertex (and the lens)
    bool specular = false;
    float fwd = 0, rev = 0;
    bool in_medium() const { return n == Vec3f{}; }
};

struct SyntheticPath {
    std::vector<Vertex> x; // x[0] on the light, x[k] the lens
    float light_choice_pdf_pos = 0; // pmf * pdf_pos
    float emission_pdf_dir = 0;     // the light's directional density towards x_1
    float camera_pdf = 0;           // the camera's directional density times the frame's pixels
    float light_paths = 0;          // N
    float radius = 0;
    float start_sigma = 0;          // > 0: x_0 lies in an emissive medium of this extinction
    bool light_side_drops_free_flight = false; // a negative control (see the end)

    int k() const { return int(x.size()) - 1; }
    float dist2(int i, int j) const { return length_squared(x[i].p - x[j].p); }
    // |cos| at x_i towards x_j; 1 where there is no surface.
    float cosine(int i, int j) const {
        return x[i].in_medium() ? 1.f : abs_dot(x[i].n, normalize(x[j].p - x[i].p));
    }
    bool medium_start() const { return start_sigma > 0; }
    // What converts the camera side's density of x_0 to its measure: the cosine at a light, the
    // free flight's density in a medium.
    float start_factor() const {
        return medium_start() ? collision_density(start_sigma, std::sqrt(dist2(0, 1))) : cosine(0, 1);
    }
    float eta(int j) const {
        return light_paths * (x[j].in_medium() ? 4.f / 3.f * Pi * radius * radius * radius : Pi * radius * radius);
    }
};

SyntheticPath random_path(std::mt19937 &rng, int k, bool medium_start = false) {
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    auto random_direction = [&] {
        const float z = 1 - 2 * unit(rng), phi = 2 * Pi * unit(rng), r = std::sqrt(std::max(0.f, 1 - z * z));
        return Vec3f{r * std::cos(phi), r * std::sin(phi), z};
    };
    SyntheticPath path;
    path.x.resize(k + 1);
    for (int i = 0; i <= k; ++i) {
        Vertex &v = path.x[i];
        v.p = Vec3f{unit(rng), unit(rng), unit(rng)} * 2.f + Vec3f{float(i), 0, 0} * 0.7f;
        const bool scattering = i > 0 && i < k;
        const bool medium = scattering && unit(rng) < 0.3f;
        v.n = (i == k || medium) ? Vec3f{} : random_direction();
        v.specular = scattering && !medium && unit(rng) < 0.25f;
        v.fwd = 0.05f + 5 * unit(rng);
        v.rev = (medium || v.specular) ? v.fwd : 0.05f + 5 * unit(rng);
    }
    path.light_choice_pdf_pos = 0.1f + unit(rng);
    path.emission_pdf_dir = 0.1f + unit(rng);
    path.camera_pdf = 100 + 1000 * unit(rng);
    path.light_paths = 1000 + 5000 * unit(rng);
    path.radius = 0.005f + 0.05f * unit(rng);
    if (medium_start) {
        path.x[0].n = Vec3f{};
        path.emission_pdf_dir = Inv4Pi;
        path.start_sigma = 0.05f + 3 * unit(rng);
    }
    return path;
}

struct Strategy {
    const char *kind;
    int at;              // s for hits and connections, j for merges
    double explicit_density = 0;
    double weight = 0;   // from the recursion
};

// Every strategy that can produce the path, with its explicit density and its weight from the
// recursion of vcm_mis.h (as vcm.cpp evaluates it at each kind of join).
std::vector<Strategy> strategies(const SyntheticPath &path, const VcmWeights &w, bool use_vc) {
    const int k = path.k();
    const auto &x = path.x;
    // Area densities of generating x_i from either side.
    std::vector<double> p_fwd(k + 1), p_rev(k + 1);
    p_fwd[0] = path.light_choice_pdf_pos;
    if (k >= 1) p_fwd[1] = path.emission_pdf_dir * path.cosine(1, 0) / path.dist2(0, 1);
    for (int i = 2; i <= k; ++i) p_fwd[i] = x[i - 1].fwd * path.cosine(i, i - 1) / path.dist2(i - 1, i);
    p_rev[k] = 1;
    if (k >= 1) p_rev[k - 1] = path.camera_pdf * path.cosine(k - 1, k) / path.dist2(k - 1, k);
    for (int i = k - 2; i >= 0; --i)
        p_rev[i] = x[i + 1].rev * (i == 0 ? path.start_factor() : path.cosine(i, i + 1)) / path.dist2(i, i + 1);
    auto product = [&](int light_end, int camera_start) { // prod_{i<=light_end} p_fwd prod_{i>=camera_start}^{k-1} p_rev
        double p = 1;
        for (int i = 0; i <= light_end; ++i) p *= p_fwd[i];
        for (int i = camera_start; i < k; ++i) p *= p_rev[i];
        return p;
    };

    // The recursion along both subpaths, as trace_light_path and trace_camera_path run it.
    const float emission_pdf = path.light_choice_pdf_pos * path.emission_pdf_dir;
    std::vector<SubpathMis> light(k + 1), camera(k + 1);
    SubpathMis m = SubpathMis::light_start(emission_pdf, path.light_choice_pdf_pos,
                                           path.medium_start() ? 1.f : path.cosine(0, 1), true);
    for (int i = 1; i < k; ++i) {
        m.arrive(path.dist2(i - 1, i), path.cosine(i, i - 1));
        if (i == 1 && path.medium_start() && !path.light_side_drops_free_flight) {
            m.d_vc *= mis(path.start_factor());
        }
        light[i] = m;
        m.scatter(w, w.at(x[i].in_medium()), path.cosine(i, i + 1), x[i].fwd, x[i].rev, x[i].specular);
    }
    m = SubpathMis::camera_start(path.light_paths, path.camera_pdf);
    for (int i = k - 1; i >= 0; --i) {
        m.arrive(path.dist2(i + 1, i), i == 0 ? path.start_factor() : path.cosine(i, i + 1));
        camera[i] = m;
        if (i > 0) m.scatter(w, w.at(x[i].in_medium()), path.cosine(i, i - 1), x[i].rev, x[i].fwd, x[i].specular);
    }

    std::vector<Strategy> out;
    // The camera path hits the light (directly from the lens when k = 1).
    out.push_back({"hit", 0, product(-1, 0),
                   1 / (1 + camera[0].hit_emitter(w, path.light_choice_pdf_pos, emission_pdf))});
    for (int s = 1; s <= k && use_vc; ++s) {
        const int y = s - 1, z = s; // the light subpath's end and the camera subpath's
        if (x[y].specular || (z < k && x[z].specular)) continue;
        if (k == 1) {
            // The light subpath's start joined to the lens (connect_start_to_camera).
            const float camera_pdf_a = path.camera_pdf * path.cosine(0, 1) / path.dist2(0, 1);
            const float w_light = SubpathMis::light_point(path.light_choice_pdf_pos)
                                      .connected(camera_pdf_a / path.light_paths, 0, NoMerge);
            out.push_back({"start traced", s, product(0, 1) * path.light_paths, 1 / (1 + w_light)});
        } else if (s == 1 && path.medium_start()) {
            // x_1 joined to the start in the medium (connect_to_medium_start).
            const float camera_pdf = x[1].rev * path.start_factor() / path.dist2(0, 1);
            const float w_light = mis(camera_pdf / path.light_choice_pdf_pos);
            const float w_camera = camera[1].connected(path.emission_pdf_dir * path.cosine(1, 0) / path.dist2(0, 1),
                                                       x[1].fwd, w.at(x[1].in_medium()));
            out.push_back({"medium start", s, product(0, 1), 1 / (w_light + 1 + w_camera)});
        } else if (s == 1) {
            // Light sampling from x_1, with the light's density as a solid angle there.
            const float direct = path.light_choice_pdf_pos * path.dist2(0, 1) / path.cosine(0, 1);
            const float w_light = mis(x[1].rev / direct);
            const float w_camera = camera[1].connected(emission_pdf * path.cosine(1, 0) / (direct * path.cosine(0, 1)),
                                                       x[1].fwd, w.at(x[1].in_medium()));
            out.push_back({"light sample", s, product(0, 1), 1 / (w_light + 1 + w_camera)});
        } else if (s == k) {
            // Light tracing: x_{k-1} joined to the lens.
            const float camera_pdf_a = path.camera_pdf * path.cosine(y, k) / path.dist2(y, k);
            const float w_light = light[y].connected(camera_pdf_a / path.light_paths, x[y].rev, w.at(x[y].in_medium()));
            out.push_back({"light trace", s, product(k - 1, k) * path.light_paths, 1 / (1 + w_light)});
        } else {
            const float camera_pdf_a = x[z].rev * path.cosine(y, z) / path.dist2(y, z);
            const float light_pdf_a = x[y].fwd * path.cosine(z, y) / path.dist2(y, z);
            const float w_light = light[y].connected(camera_pdf_a, x[y].rev, w.at(x[y].in_medium()));
            const float w_camera = camera[z].connected(light_pdf_a, x[z].fwd, w.at(x[z].in_medium()));
            out.push_back({"connection", s, product(s - 1, s), 1 / (w_light + 1 + w_camera)});
        }
    }
    for (int j = 1; j < k; ++j) {
        if (x[j].specular) continue;
        const MergeWeights &here = w.at(x[j].in_medium());
        const float w_light = light[j].merged(x[j].rev, here);
        const float w_camera = camera[j].merged(x[j].fwd, here);
        out.push_back({"merge", j, product(j, j) * path.eta(j), 1 / (w_light + 1 + w_camera)});
    }
    return out;
}

// The per-iteration constants, as VCM::render makes them (merging always on).
VcmWeights weights_for(const SyntheticPath &path, bool use_vc) {
    const float r = path.radius;
    return VcmWeights::make(use_vc, path.light_paths * Pi * r * r, path.light_paths * 4.f / 3.f * Pi * r * r * r);
}

// The largest relative difference between the recursion's weights and the explicit power
// heuristic over the path's strategies, and how far their sum is from one.
struct Discrepancy {
    double weight = 0, sum = 0;
};

Discrepancy check(const SyntheticPath &path, const VcmWeights &w, bool use_vc) {
    const std::vector<Strategy> all = strategies(path, w, use_vc);
    double squares = 0, sum = 0;
    for (const Strategy &s : all) {
        squares += s.explicit_density * s.explicit_density;
        sum += s.weight;
    }
    Discrepancy d;
    d.sum = std::abs(sum - 1);
    for (const Strategy &s : all) {
        const double expected = s.explicit_density * s.explicit_density / squares;
        d.weight = std::max(d.weight, std::abs(s.weight - expected) / std::max(expected, 1e-3));
    }
    return d;
}

void expect_weights_match(bool use_vc, bool medium_start = false) {
    std::mt19937 rng(use_vc ? 1234 : 4321);
    int paths = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        // A light seen directly (k = 1) has light tracing of its start against the camera's
        // hit; a start in a medium is not joined to the lens (the camera's collision estimate
        // is the one strategy there).
        const int k = medium_start ? 2 + trial % 6 : 1 + trial % 7;
        const SyntheticPath path = random_path(rng, k, medium_start);
        const Discrepancy d = check(path, weights_for(path, use_vc), use_vc);
        ASSERT_LT(d.sum, 1e-4) << "path length " << path.k() << ", trial " << trial;
        ASSERT_LT(d.weight, 1e-3) << "path length " << path.k() << ", trial " << trial;
        ++paths;
    }
    EXPECT_EQ(paths, 4000);
}

TEST(VcmMis, RecursiveWeightsAreThePowerHeuristicOfTheExplicitDensities) { expect_weights_match(true); }

TEST(VcmMis, BpmWeightsWithoutConnectionsAreThePowerHeuristicToo) { expect_weights_match(false); }

TEST(VcmMis, WeightsOfLightPathsFromAnEmissiveMediumAreThePowerHeuristic) {
    expect_weights_match(true, true);
    expect_weights_match(false, true);
}

// Negative controls. Weighing merges in media as if they were on surfaces (the volume kernel's
// eta dropped) is still a partition of unity, but not the power heuristic of the true densities:
// the comparison with the explicit weights catches it. Reading d_vc as the report's d_vm at a
// merge, without the merge's eta (vc_to_vm one), breaks the partition itself.
// For a start in a medium, leaving the free flight's density out of the light subpath's sums
// (as if the start had a cosine of 1) breaks it too.
TEST(VcmMis, WrongWeightsFail) {
    std::mt19937 rng(99);
    int medium_as_surface = 0, eta_left_out = 0, with_medium = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const SyntheticPath path = random_path(rng, 4);
        bool has_medium = false;
        for (const Vertex &v : path.x) has_medium |= v.in_medium();
        VcmWeights wrong = weights_for(path, true);
        wrong.medium = wrong.surface;
        if (has_medium) {
            ++with_medium;
            medium_as_surface += check(path, wrong, true).weight > 1e-2;
        }
        wrong = weights_for(path, true);
        wrong.surface.vc_to_vm = wrong.medium.vc_to_vm = 1;
        eta_left_out += check(path, wrong, true).sum > 1e-3;
    }
    EXPECT_GT(with_medium, 100);
    EXPECT_GT(medium_as_surface, with_medium / 2);
    EXPECT_GT(eta_left_out, 100);

    int free_flight_left_out = 0;
    for (int trial = 0; trial < 500; ++trial) {
        SyntheticPath path = random_path(rng, 4, true);
        path.light_side_drops_free_flight = true;
        free_flight_left_out += check(path, weights_for(path, true), true).sum > 1e-3;
    }
    EXPECT_GT(free_flight_left_out, 250);
}

} // namespace
} // namespace caustica
