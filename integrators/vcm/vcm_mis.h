// The recursive multiple-importance quantities of vertex connection and merging (Georgiev,
// Krivanek, Davidovic and Slusallek 2012, "Light transport simulation with vertex connection and
// merging"; the recursion is derived in Georgiev's tech. report "Implementing vertex connection
// and merging", 2012, section 5, whose names d^VCM, d^VC, d^VM are kept here).
//
// A subpath carries, at its last vertex, three partial sums over the strategies that could have
// produced more of it from the other end:
//   d_vcm  1 / (density of the last vertex), for the connection that ends at the vertex before;
//   d_vc   the sums used when the path is completed by a connection (or by hitting a light);
//   d_vm   the same, used when it is completed by a merge.
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
// The strategy families can be switched off (bpm has no connections; vcm has both): a disabled
// family's terms are removed from every sum, so the remaining weights still sum to one.
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
// d_vm is kept relative to a merge on a SURFACE (its terms are divided by eta_surface rather than
// by the eta of whatever vertex it ends up merged at, which is unknown while the subpath is being
// extended). With eta the same at every vertex this is Georgiev's recursion unchanged; a medium
// vertex contributes merge_ratio = mis(eta_medium / eta_surface) where a surface vertex
// contributes 1, and a merge at a medium vertex rescales d_vm by d_vm_scale, the inverse. (Every
// term of d_vm is a strategy's density over the merge's, whose eta is the merge vertex's; no
// other strategy's density contains that eta, so the rescaling is exact.)
struct MergeWeights {
    float vm_weight = 0;   // mis(eta) when merging is on: a merge at this vertex relative to a connection
    float vc_weight = 0;   // mis(1 / eta) when connecting is on: the converse, for a merge here
    float merge_ratio = 1; // mis(eta / eta_surface), see above
    float d_vm_scale = 1;  // mis(eta_surface / eta)
};

// The weights of a vertex that cannot be merged at (see above): vm_weight and merge_ratio zero.
inline constexpr MergeWeights NoMerge{0, 0, 0, 1};

// Per-iteration constants.
struct VcmWeights {
    MergeWeights surface, medium;
    float vc_enabled = 0;     // 1 when connecting is on (it weighs the connection terms of d_vc)
    // mis(1 / eta_surface): a camera path hitting the light, relative to a surface merge (d_vm's
    // reference). That strategy exists whatever the families, so unlike the vc_weights it is
    // not switched off with them.
    float light_hit_weight = 0;

    const MergeWeights &at(bool in_medium) const { return in_medium ? medium : surface; }

    static VcmWeights make(bool use_vc, bool use_vm, float eta_surface, float eta_medium) {
        VcmWeights w;
        w.surface.vm_weight = use_vm ? mis(eta_surface) : 0.f;
        w.surface.vc_weight = use_vc ? mis(1 / eta_surface) : 0.f;
        w.medium.vm_weight = use_vm ? mis(eta_medium) : 0.f;
        w.medium.vc_weight = use_vc ? mis(1 / eta_medium) : 0.f;
        w.medium.merge_ratio = mis(eta_medium / eta_surface);
        w.medium.d_vm_scale = mis(eta_surface / eta_medium);
        w.vc_enabled = use_vc ? 1.f : 0.f;
        w.light_hit_weight = use_vm ? mis(1 / eta_surface) : 0.f;
        return w;
    }
};

struct SubpathMis {
    float d_vcm = 0, d_vc = 0, d_vm = 0;

    // A new vertex was reached at distance^2 dist2 (pass 1 where the previous vertex is at
    // infinity: no distance conversion) and its geometric normal makes cosine cos_in with the
    // incoming segment.
    void arrive(float dist2, float cos_in) {
        d_vcm *= mis(dist2);
        d_vcm /= mis(cos_in);
        d_vc /= mis(cos_in);
        d_vm /= mis(cos_in);
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
            d_vm *= mis(cos_out);
            return;
        }
        const float g = mis(cos_out / pdf_dir);
        d_vc = g * (d_vc * mis(pdf_rev) + w.vc_enabled * d_vcm + here.vm_weight);
        d_vm = g * (d_vm * mis(pdf_rev) + d_vcm * w.surface.vc_weight + here.merge_ratio);
        d_vcm = mis(1 / pdf_dir);
    }

    // The subpath jumps through a profile solid from its entry to its exit (see above): scatter
    // and arrive with densities and conversions of 1, and no connection between the two.
    // pdf_rev_exit is the density with which the exit lobe at the entry samples the direction
    // back along this subpath (profile_exit_density). here: the entry's merge weights, NoMerge
    // when this is a camera subpath (the light's exit is there).
    void jump(const VcmWeights &w, const MergeWeights &here, float pdf_rev_exit) {
        d_vc = d_vc * mis(pdf_rev_exit) + w.vc_enabled * d_vcm + here.vm_weight;
        d_vm = d_vm * mis(pdf_rev_exit) + d_vcm * w.surface.vc_weight + here.merge_ratio;
        d_vcm = 0;
    }
};

} // namespace caustica
