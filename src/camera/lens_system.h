// A camera lens as a stack of spherical glass interfaces and a planar aperture stop, traced
// exactly rather than idealised as a thin lens (Kolb, Mitchell and Hanrahan 1995, "A realistic
// camera model for computer graphics"; pbrt-v4's RealisticCamera, section 5.4 of Physically
// Based Rendering, 4th edition). Its parameters are those of a lens description file.
//
// Coordinates are the camera's (metres): the optical axis is +z, looking into the scene; the
// film lies in the plane z = 0 and the lens in front of it, its rear interface at z = rear_z()
// and its front one at z = front_z(). Interface 0 faces the scene.
#pragma once

#include "camera/aperture_mask.h"
#include "geometry/vec3d.h"

#include <optional>
#include <string>
#include <vector>

namespace caustica {

struct LensInterface {
    // Signed radius of curvature: positive when the centre lies behind the vertex (towards the
    // film); 0 for the aperture stop, a plane.
    double curvature_radius = 0;
    double thickness = 0;  // along the axis, to the next interface (the film after the last)
    double eta = 1;        // of the glass behind the interface (0 or 1 for air)
    double aperture_radius = 0;
    bool is_stop() const { return curvature_radius == 0; }
};

struct LensRay {
    Vec3d o, d;
};

class LensSystem {
  public:
    // Interfaces from a lens description: rows of curvature radius, thickness, index of
    // refraction and aperture diameter in millimetres, front to rear, as pbrt-v4 reads them.
    // `stop_diameter_mm` replaces the stop's diameter when it is smaller; *clamped is set when it
    // was larger (the stop's own diameter is kept, as in pbrt-v4). Throws InputError (without a
    // location) for a row count that is not a multiple of four or a non-physical value.
    static LensSystem from_description(const std::vector<float> &values_mm, double stop_diameter_mm,
                                       bool *clamped);

    double rear_z() const { return interfaces_.back().thickness; }
    double front_z() const;
    double rear_radius() const { return interfaces_.back().aperture_radius; }
    const std::vector<LensInterface> &interfaces() const { return interfaces_; }

    // Traces a ray leaving the film (towards +z) through every interface; empty when an aperture
    // blocks it or it is totally reflected. *weight (if given) receives the aperture mask's value
    // where the ray crosses the stop (1 without a mask).
    std::optional<LensRay> trace_from_film(LensRay ray, const ApertureMask *mask = nullptr,
                                           float *weight = nullptr) const;
    // Traces a ray arriving from the scene (towards -z) through every interface to the film's
    // side, ignoring any aperture mask.
    std::optional<LensRay> trace_from_scene(LensRay ray) const;

    // Moves the film so that the plane at distance `focus_distance` from it is in focus, by the
    // thick-lens approximation found from two paraxial rays (pbrt-v4's FocusThickLens). Throws
    // InputError (without a location) when the lens cannot focus there or passes no paraxial ray.
    // `film_diagonal` sets the paraxial rays' height.
    void focus(double focus_distance, double film_diagonal);

  private:
    std::optional<LensRay> trace(LensRay ray, bool from_film, const ApertureMask *mask, float *weight) const;
    std::vector<LensInterface> interfaces_;
};

} // namespace caustica
