// Texture coordinates from a surface point (pbrt-v4's TextureMapping2D / TextureMapping3D).
// The 2D mappings: "uv" (scaled and offset surface parameterisation), "spherical" and
// "cylindrical" (angles of the point in texture space), "planar" (projection onto two vectors).
#pragma once

#include "core/transform.h"
#include "textures/texture.h"

namespace caustica {

class TextureMapping2D {
  public:
    enum class Kind { UV, Spherical, Cylindrical, Planar };

    static TextureMapping2D uv(float su, float sv, float du, float dv) {
        TextureMapping2D m;
        m.kind_ = Kind::UV;
        m.scale_ = {su, sv};
        m.offset_ = {du, dv};
        return m;
    }
    static TextureMapping2D spherical(const Transform &texture_from_render) {
        TextureMapping2D m;
        m.kind_ = Kind::Spherical;
        m.texture_from_render_ = texture_from_render;
        return m;
    }
    static TextureMapping2D cylindrical(const Transform &texture_from_render) {
        TextureMapping2D m;
        m.kind_ = Kind::Cylindrical;
        m.texture_from_render_ = texture_from_render;
        return m;
    }
    static TextureMapping2D planar(const Transform &texture_from_render, Vec3f vs, Vec3f vt,
                                   float ds, float dt) {
        TextureMapping2D m;
        m.kind_ = Kind::Planar;
        m.texture_from_render_ = texture_from_render;
        m.vs_ = vs;
        m.vt_ = vt;
        m.offset_ = {ds, dt};
        return m;
    }

    // The (s, t) texture coordinates of the point.
    Vec2f map(const TextureEvalContext &ctx) const {
        switch (kind_) {
        case Kind::UV:
            return {scale_.x * ctx.uv.x + offset_.x, scale_.y * ctx.uv.y + offset_.y};
        case Kind::Spherical: {
            Vec3f v = normalize(texture_from_render_.apply_point(ctx.p));
            float phi = std::atan2(v.y, v.x);
            if (phi < 0) phi += 2 * Pi;
            return {safe_acos(v.z) * InvPi, phi * Inv2Pi};
        }
        case Kind::Cylindrical: {
            Vec3f p = texture_from_render_.apply_point(ctx.p);
            return {(Pi + std::atan2(p.y, p.x)) * Inv2Pi, p.z};
        }
        case Kind::Planar: {
            Vec3f v = texture_from_render_.apply_point(ctx.p);
            return {offset_.x + dot(v, vs_), offset_.y + dot(v, vt_)};
        }
        }
        return {};
    }

  private:
    Kind kind_ = Kind::UV;
    Vec2f scale_{1, 1}, offset_{0, 0};
    Vec3f vs_{1, 0, 0}, vt_{0, 1, 0};
    Transform texture_from_render_;
};

// Solid textures: the point in texture space.
class TextureMapping3D {
  public:
    explicit TextureMapping3D(const Transform &texture_from_render)
        : texture_from_render_(texture_from_render) {}
    Vec3f map(const TextureEvalContext &ctx) const { return texture_from_render_.apply_point(ctx.p); }

  private:
    Transform texture_from_render_;
};

} // namespace caustica
