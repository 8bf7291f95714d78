// Multiple-importance weight of one BDPT connection strategy (Veach 1997, section 10.2.1).
#pragma once

#include "integrators/common/path_vertex.h"

namespace caustica {

// The power-heuristic weight of the path made of light_vertices[0, s) and camera_vertices[0, t)
// against every other (s', t') strategy that could have produced the same path. `sampled` is the
// vertex that the strategy sampled afresh (the lens point when t = 1, the light point when
// s = 1) and replaces the subpath's own endpoint while the weight is computed; the vertices'
// densities are modified temporarily and restored before returning.
float bdpt_mis_weight(const Scene &scene, PathVertex *light_vertices, PathVertex *camera_vertices,
                      const PathVertex &sampled, int s, int t);

} // namespace caustica
