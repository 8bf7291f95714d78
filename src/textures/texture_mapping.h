// Texture coordinates from a surface point (pbrt-v4's TextureMapping2D / TextureMapping3D).
// The 2D mappings: "uv" (scaled and offset surface parameterisation), "spherical" and
// "cylindrical" (angles of the point in texture space), "planar" (projection onto two vectors).
// Each also carries the point's screen-space derivatives through the mapping (the chain rule on
// the context's du/dx ... or dp/dx, dp/dy), for filtering.
#pragma once

#include "core/transform.h"
#include "textures/texture.h"

namespace caustica {

// Texture coordinates and how they change from pixel to pixel.
struct TexCoord2D {
    Vec2f st;
    float dsdx = 0, dsdy = 0, dtdx = 0, dtdy = 0;
};

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

    // The (s, t) texture coordinates of the point and their derivatives.
    TexCoord2D map(const TextureEvalContext &ctx) const {
        TexCoord2D c;
        switch (kind_) {
        case Kind::UV:
            c.st = {scale_.x * ctx.uv.x + offset_.x, scale_.y * ctx.uv.y + offset_.y};
            c.dsdx = scale_.x * ctx.dudx;
            c.dsdy = scale_.x * ctx.dudy;
            c.dtdx = scale_.y * ctx.dvdx;
            c.dtdy = scale_.y * ctx.dvdy;
            return c;
        case Kind::Spherical: {
            const Vec3f p = texture_from_render_.apply_point(ctx.p);
            const Vec3f v = normalize(p);
            float phi = std::atan2(v.y, v.x);
            if (phi < 0) phi += 2 * Pi;
            c.st = {safe_acos(v.z) * InvPi, phi * Inv2Pi};
            // The gradients of s and t in texture space (pbrt-v4's, which pair s's gradient
            // with the azimuth and t's with the polar angle).
            const float x2y2 = sqr(p.x) + sqr(p.y), r_xy = std::sqrt(x2y2);
            const Vec3f dsdp = Vec3f{-p.y, p.x, 0} / (2 * Pi * x2y2);
            const Vec3f dtdp = Vec3f{p.x * p.z / r_xy, p.y * p.z / r_xy, -r_xy} / (Pi * (x2y2 + sqr(p.z)));
            return with_gradients(c, dsdp, dtdp, ctx);
        }
        case Kind::Cylindrical: {
            const Vec3f p = texture_from_render_.apply_point(ctx.p);
            c.st = {(Pi + std::atan2(p.y, p.x)) * Inv2Pi, p.z};
            const float x2y2 = sqr(p.x) + sqr(p.y);
            return with_gradients(c, Vec3f{-p.y, p.x, 0} / (2 * Pi * x2y2), Vec3f{0, 0, 1}, ctx);
        }
        case Kind::Planar: {
            const Vec3f v = texture_from_render_.apply_point(ctx.p);
            c.st = {offset_.x + dot(v, vs_), offset_.y + dot(v, vt_)};
            return with_gradients(c, vs_, vt_, ctx);
        }
        }
        return c;
    }

  private:
    // c with the derivatives of s and t whose texture-space gradients are dsdp and dtdp.
    TexCoord2D with_gradients(TexCoord2D c, Vec3f dsdp, Vec3f dtdp, const TextureEvalContext &ctx) const {
        const Vec3f dpdx = texture_from_render_.apply_vector(ctx.dpdx), dpdy = texture_from_render_.apply_vector(ctx.dpdy);
        c.dsdx = dot(dsdp, dpdx);
        c.dsdy = dot(dsdp, dpdy);
        c.dtdx = dot(dtdp, dpdx);
        c.dtdy = dot(dtdp, dpdy);
        // On the mapping's axis the gradients are undefined: no filtering there.
        if (!std::isfinite(c.dsdx + c.dsdy + c.dtdx + c.dtdy)) c.dsdx = c.dsdy = c.dtdx = c.dtdy = 0;
        return c;
    }

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
    // A render-space derivative (dp/dx, dp/dy) in texture space.
    Vec3f map_vector(Vec3f v) const { return texture_from_render_.apply_vector(v); }

  private:
    Transform texture_from_render_;
};

} // namespace caustica
