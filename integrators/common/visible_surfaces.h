// The first surface each pixel sees, for the geometric layers of pbrt-v4's "gbuffer" film
// (pbrt-v4's VisibleSurface): what denoisers and compositors read beside the image.
//
// The layers do not depend on the integrator, so they are traced here, once, for every
// integrator alike (pbrt-v4 fills them only in its path tracers, from their first vertex). Each
// pixel takes `samples` camera rays through the render's sampler, with the film's filter; a ray
// walks the scene as a camera path does (the shared SubpathWalk), crossing surfaces that only
// bound media, and the first surface with a BSDF is the pixel's visible surface. A ray that
// scatters in a medium first, or leaves the scene, has none, as in pbrt-v4.
//
// The layers, pbrt-v4's names and meanings:
//   Albedo.R/G/B  the BSDF's directional albedo rho(wo) (16 samples of its own sampling, drawn
//                 afresh for each camera sample),
//                 lit by the colour space's white, as output RGB; averaged over all samples;
//   P.X/Y/Z       the position;
//   N.X/Y/Z       the geometric normal, facing the camera, normalised after averaging;
//   Ns.X/Y/Z      the shading normal, likewise;
//   dzdx, dzdy    |dp/dx| and |dp/dy| along the depth axis: the change of the position's z
//                 from the camera rays offset on the film met on the surface's tangent plane
//                 (pbrt-v4's ray differentials), offset as pbrt-v4 scales them: by the spacing
//                 of the render's samples, max(1/8, 1/sqrt(spp)) of a pixel;
//   u, v          the surface parameterisation.
// Positions, normals and dz are in camera space (pbrt-v4's default "coordinatesystem") or world
// space; all but Albedo are averaged over the samples that saw a surface.
#pragma once

#include "film/image.h"

namespace caustica {

class Scene;

// samples: camera rays per pixel; render_samples: the render's samples per pixel.
void add_visible_surface_layers(const Scene &scene, int samples, int render_samples, Image &image);

} // namespace caustica
