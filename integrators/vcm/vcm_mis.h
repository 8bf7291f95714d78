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
// is reached and the cosines as each is known.
//
// The strategy families can be switched off (bpm has no connections; vcm has both): a disabled
// family's terms are removed from every sum, so the remaining weights still sum to one.
#pragma once

namespace caustica {

inline float mis(float density_ratio) { return density_ratio * density_ratio; }

// Per-iteration constants. eta_vcm = pi r^2 N_group is the ratio of the merging density to the
// connection density (a camera vertex gathers the N_group light paths of its wavelength group
// within radius r, but connects to one).
struct VcmWeights {
    float vm_weight = 0;      // mis(eta_vcm) when merging is on: a merge relative to a connection
    float vc_weight = 0;      // mis(1 / eta_vcm) when connecting is on: the converse
    float vc_enabled = 0;     // 1 when connecting is on (it weighs the connection terms of d_vc)
    // mis(1 / eta_vcm): a camera path hitting the light, relative to a merge. That strategy
    // exists whatever the families, so unlike vc_weight it is not switched off with them.
    float light_hit_weight = 0;

    static VcmWeights make(bool use_vc, bool use_vm, float eta_vcm) {
        VcmWeights w;
        w.vm_weight = use_vm ? mis(eta_vcm) : 0.f;
        w.vc_weight = use_vc ? mis(1 / eta_vcm) : 0.f;
        w.vc_enabled = use_vc ? 1.f : 0.f;
        w.light_hit_weight = use_vm ? mis(1 / eta_vcm) : 0.f;
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
    // geometric normal. A specular sample has equal delta densities both ways, which cancel.
    void scatter(const VcmWeights &w, float cos_out, float pdf_dir, float pdf_rev, bool specular) {
        if (specular) {
            d_vcm = 0;
            d_vc *= mis(cos_out);
            d_vm *= mis(cos_out);
            return;
        }
        const float g = mis(cos_out / pdf_dir);
        d_vc = g * (d_vc * mis(pdf_rev) + w.vc_enabled * d_vcm + w.vm_weight);
        d_vm = g * (d_vm * mis(pdf_rev) + d_vcm * w.vc_weight + 1);
        d_vcm = mis(1 / pdf_dir);
    }
};

} // namespace caustica
