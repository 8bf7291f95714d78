// pbrt-v4's MIP map (Williams 1983, "Pyramidal parametrics"; pbrt-v4 10.4.3): an image and its
// successively halved versions, and lookups that average the image over a footprint.
//
// As in pbrt-v4, so that imagemap textures filter as pbrt-v4 filters them:
//   - an image whose sides are not powers of two is first resampled up to the next powers of two
//     with a windowed sinc (radius 2, tau 2); each level then averages 2x2 texels of the one
//     below, down to a single texel;
//   - a footprint is two vectors in (s, t) (how s and t change per pixel in x and in y);
//   - "point", "bilinear" and "trilinear" choose the level whose texels are as wide as the
//     footprint's widest extent; "point" takes the nearest texel there, "bilinear" interpolates
//     there, "trilinear" also interpolates between that level and the next. With no footprint
//     all three use the full-resolution image;
//   - "ewa" (Greene and Heckbert 1986; Heckbert 1989) weights the texels inside the footprint's
//     ellipse with a truncated Gaussian, on the two levels that bracket the ellipse's minor
//     axis, after clamping its eccentricity to `maxanisotropy`.
// Differs from pbrt-v4 in that levels are kept in float; pbrt-v4 stores the levels of an 8-bit
// image back in 8 bits.
#pragma once

#include "core/vecmath.h"
#include "textures/image_texture.h"

#include <memory>
#include <vector>

namespace caustica {

enum class MIPFilter { Point, Bilinear, Trilinear, EWA };

class MIPMap {
  public:
    MIPMap(std::shared_ptr<const TexelImage> image, ImageWrap wrap, MIPFilter filter, float max_anisotropy);

    // The filtered channels at st (t = 0 at the top row, as the image is stored) for the
    // footprint dst0 = (ds/dx, dt/dx), dst1 = (ds/dy, dt/dy); written to out[0 .. channels()).
    void filter(Vec2f st, Vec2f dst0, Vec2f dst1, float *out) const;

    int channels() const { return pyramid_[0]->channels(); }
    int levels() const { return int(pyramid_.size()); }
    const TexelImage &level(int i) const { return *pyramid_[i]; }

  private:
    void bilerp(int level, Vec2f st, float *out) const;
    void texel(int level, int x, int y, float *out) const;
    void ewa(int level, Vec2f st, Vec2f dst0, Vec2f dst1, float *out) const;

    std::vector<std::shared_ptr<const TexelImage>> pyramid_;
    ImageWrap wrap_;
    MIPFilter filter_;
    float max_anisotropy_;
};

} // namespace caustica
