// The recursive multiple-importance quantities of vertex connection and merging (Georgiev,
// Krivanek, Davidovic and Slusallek 2012, "Light transport simulation with vertex connection and
// merging"; the recursion is derived in Georgiev's tech. report "Implementing vertex connection
// and merging", 2012, section 5, whose names d^VCM and d^VC are kept here).
//
// A subpath carries, at its last vertex, two partial sums over the strategies that could have
// produced more of it from the other end:
//   d_vcm  1 / (density of the last vertex), for the connection that ends at the vertex before;
//   d_vc   the sum used when the path is completed by a connection (or by hitting a light).
// The report's third sum, d_vm, used when the path is completed by a merge, is not carried:
// here it is always d_vc / eta^2 at the vertex merged at (MergeWeights::vc_to_vm says why), so a
// stored light vertex needs only the two.
// The weights are power-heuristic (mis(x) = x^2), and every density is in the area measure at
// its vertex; the conversion from solid angle happens lazily, the distance squared when a vertex
// is reached and the cosines as each is known. A vertex inside a participating medium has no
// normal: its density is per unit volume, every cosine of a conversion at it is 1, and its
// scattering function is the phase function. The densities of free-flight distance sampling are
// left out of every strategy's density, on both subpaths alike (as pbrt-v3/v4's BDPT do): the
// weights are then those of a consistent set of per-strategy densities and still sum to one.
//
// Profile subsurface (profile_subsurface.h). A path through a diffusion or dipole solid jumps
// from the entry x_j to the exit x_j+1 (light-side numbering) without a direction between them.
// As in BDPT (PathVertex::after_jump) the jump's densities are taken as 1 both ways, and the one
// strategy that would join x_j and x_j+1 is not one. Merging needs a photon that arrived at its
// vertex along a segment, so photons are not kept at light subpaths' exits: x_j (the light's
// entry, the camera's exit) can be merged at, x_j+1 cannot. Every other strategy counts.
//
// A light subpath that starts inside an emissive medium (integrators/common/medium_emission.h)
// starts as a light does, with cos_light 1: the camera side's density of the start has the free
// flight's density where a light has its cosine, a factor known once the first vertex is, which
// the caller then applies to d_vc.
//
// Connections can be switched off (bpm has none; vcm has both families): their terms are then
// removed from every sum, so the remaining weights still sum to one.
#pragma once

namespace caustica {

inline float mis(float density_ratio) { return density_ratio * density_ratio; }

// What merging weighs at one kind of vertex. A camera vertex gathers the N_group light paths of
// its wavelength group within the kernel's acceptance region, but connects to one, so a merge has
// eta = |region| N_group times the density of the connection that ends at the same vertex
// (Georgiev et al. 2012, eq. 11): |region| = pi r^2 on a surface, where the kernel is a disk and
// densities are per unit area, and 4/3 pi r^3 in a medium, where it is a sphere and densities are
// per unit volume (the volumetric photon map's sphere, Jensen and Christensen 1998; its place
// among VCM's strategies is the "point-point 3D" estimator of Krivanek et al. 2014, "Unifying
// points, beams, and paths in volumetric light transport simulation").
//
// The report's d_vm needs no recursion of its own. d_vc and d_vm sum over the same strategies
// (the connections among them only when connecting is on), each strategy's density over that of
// completing the path at the subpath's last vertex: by a connection for d_vc, by a merge for
// d_vm. A merge there has eta times the connection's density, with the eta of the vertex merged
// at, so d_vm = d_vc * mis(1 / eta) on surfaces and in media alike: one sum serves both.
struct MergeWeights {
    float vm_weight = 0; // mis(eta) when merging is on: a merge at this vertex relative to a connection
    float vc_weight = 0; // mis(1 / eta) when connecting is on: the converse, for a merge here
    float vc_to_vm = 0;  // mis(1 / eta): the report's d_vm at a merge here, from d_vc (see above)
};

// The weights of a vertex that cannot be merged at (see above).
inline constexpr MergeWeights NoMerge{0, 0, 0};

// Per-iteration constants.
struct VcmWeights {
    MergeWeights surface, medium;
    float vc_enabled = 0; // 1 when connecting is on (it weighs the connection terms of d_vc)

    const MergeWeights &at(bool in_medium) const { return in_medium ? medium : surface; }

    // Merging is always on (bpm and vcm both merge); use_vc: connections too (vcm).
    static VcmWeights make(bool use_vc, float eta_surface, float eta_medium) {
        VcmWeights w;
        w.surface = MergeWeights{mis(eta_surface), use_vc ? mis(1 / eta_surface) : 0.f, mis(1 / eta_surface)};
        w.medium = MergeWeights{mis(eta_medium), use_vc ? mis(1 / eta_medium) : 0.f, mis(1 / eta_medium)};
        w.vc_enabled = use_vc ? 1.f : 0.f;
        return w;
    }
};

struct SubpathMis {
    float d_vcm = 0, d_vc = 0;

    // A light subpath leaves its light (tech. report eqs. 31-33): emission_pdf, the density of the
    // emitted ray (light choice, position and direction); direct_pdf, the density with which
    // light sampling would pick the same point (as in SmallVCM and pbrt-v4's BDPT, light choice
    // times position density; for lights at infinity, the direction density); cos_light, the
    // cosine of the ray with the light's surface (1 at infinity); hittable, whether a camera path
    // can reach the light (not a delta light).
    static SubpathMis light_start(float emission_pdf, float direct_pdf, float cos_light, bool hittable) {
        SubpathMis m;
        m.d_vcm = mis(direct_pdf / emission_pdf);
        m.d_vc = hittable ? mis(cos_light / emission_pdf) : 0.f;
        return m;
    }

    // The light subpath at its start, before it leaves the light: start_pdf is the density with
    // which it chose the point (light choice times position density). The start joined to the
    // lens, light tracing of emission the camera sees directly, completes a path of two
    // vertices, whose one other strategy is the camera subpath hitting the light.
    static SubpathMis light_point(float start_pdf) {
        SubpathMis m;
        m.d_vcm = mis(1 / start_pdf);
        return m;
    }

    // A camera subpath leaves the lens with the directional density camera_pdf, one sample per
    // pixel of the full frame, while light tracing reaches the lens with light_paths paths (eq.
    // 31 for the camera).
    static SubpathMis camera_start(float light_paths, float camera_pdf) {
        SubpathMis m;
        m.d_vcm = mis(light_paths / camera_pdf);
        return m;
    }

    // A new vertex was reached at distance^2 dist2 (pass 1 where the previous vertex is at
    // infinity: no distance conversion) and its geometric normal makes cosine cos_in with the
    // incoming segment.
    void arrive(float dist2, float cos_in) {
        d_vcm *= mis(dist2);
        d_vcm /= mis(cos_in);
        d_vc /= mis(cos_in);
    }

    // The subpath continues from this vertex in a direction sampled with solid-angle density
    // pdf_dir (pdf_rev: the reverse direction's density), leaving at cosine cos_out with the
    // geometric normal (1 at a medium vertex). A specular sample has equal delta densities both
    // ways, which cancel. here: the merge weights of this vertex's kind.
    void scatter(const VcmWeights &w, const MergeWeights &here, float cos_out, float pdf_dir, float pdf_rev,
                 bool specular) {
        if (specular) {
            d_vcm = 0;
            d_vc *= mis(cos_out);
            return;
        }
        const float g = mis(cos_out / pdf_dir);
        d_vc = g * (d_vc * mis(pdf_rev) + w.vc_enabled * d_vcm + here.vm_weight);
        d_vcm = mis(1 / pdf_dir);
    }

    // The strategies that complete a path at this subpath's last vertex are weighed against each
    // other by three sums, each over the strategies that would have produced more of the path
    // from the other end; a strategy's weight is 1 / (1 + the light subpath's sum + the camera
    // subpath's sum) (tech. report eqs. 40-44). here: the merge weights of the last vertex.

    // A connection (or light sampling, or light tracing) joins this subpath's last vertex to the
    // other end: pdf_a, the density, in the area measure at this vertex, with which the other end
    // samples it; pdf_rev, the density with which this vertex samples its predecessor from the
    // direction of the other end (tech. report eq. 40).
    float connected(float pdf_a, float pdf_rev, const MergeWeights &here) const {
        return mis(pdf_a) * (here.vm_weight + d_vcm + d_vc * mis(pdf_rev));
    }

    // This vertex is merged with a vertex of the other subpath: pdf_rev, the density with which
    // the other subpath's scattering function there samples this subpath's predecessor (eqs.
    // 42-43, with the report's d_vm from d_vc, see MergeWeights).
    float merged(float pdf_rev, const MergeWeights &here) const {
        return d_vcm * here.vc_weight + d_vc * here.vc_to_vm * mis(pdf_rev);
    }

    // This camera subpath has reached an emitter: direct_pdf, the density with which light
    // sampling would have chosen the point (area measure, or solid angle at infinity; at the
    // camera subpath's first vertex, the light subpath's density of its start, which light
    // tracing joins to the lens); emission_pdf, the density of emitting the path's last segment
    // from it (eq. 44).
    float hit_emitter(const VcmWeights &w, float direct_pdf, float emission_pdf) const {
        return w.vc_enabled * mis(direct_pdf) * d_vcm + mis(emission_pdf) * d_vc;
    }

    // The subpath jumps through a profile solid from its entry to its exit (see above): scatter
    // and arrive with densities and conversions of 1, and no connection between the two.
    // pdf_rev_exit is the density with which the exit lobe at the entry samples the direction
    // back along this subpath (profile_exit_density). here: the entry's merge weights, NoMerge
    // when this is a camera subpath (the light's exit is there).
    void jump(const VcmWeights &w, const MergeWeights &here, float pdf_rev_exit) {
        d_vc = d_vc * mis(pdf_rev_exit) + w.vc_enabled * d_vcm + here.vm_weight;
        d_vcm = 0;
    }
};

} // namespace caustica
