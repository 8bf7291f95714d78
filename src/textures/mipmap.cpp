#include "textures/mipmap.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

namespace caustica {

namespace {

float length_squared(Vec2f v) { return v.x * v.x + v.y * v.y; }

bool is_power_of_2(int v) { return v > 0 && (v & (v - 1)) == 0; }

int round_up_power_of_2(int v) {
    int p = 1;
    while (p < v) p *= 2;
    return p;
}

// The weights of pbrt-v4's upsampling (Image::ResampleWeights): for each new texel, four old
// ones around its centre, weighted by a Lanczos-windowed sinc of radius 2 and normalised.
struct ResampleWeight {
    int first;
    float w[4];
};

float sinc(float x) { return std::abs(x) < 1e-5f ? 1.f : std::sin(Pi * x) / (Pi * x); }

std::vector<ResampleWeight> resample_weights(int old_res, int new_res) {
    constexpr float radius = 2, tau = 2;
    std::vector<ResampleWeight> weights(new_res);
    for (int i = 0; i < new_res; ++i) {
        const float centre = (i + 0.5f) * old_res / new_res;
        ResampleWeight &r = weights[i];
        r.first = int(std::floor(centre - radius + 0.5f));
        float sum = 0;
        for (int j = 0; j < 4; ++j) {
            const float x = r.first + j + 0.5f - centre;
            r.w[j] = std::abs(x) > radius ? 0.f : sinc(x) * sinc(x / tau);
            sum += r.w[j];
        }
        for (float &w : r.w) w /= sum;
    }
    return weights;
}

// Channel c of texel (x, y): read directly inside the image, by the wrap mode outside it.
float texel_or_wrapped(const TexelImage &image, const float *texels, int x, int y, int c, ImageWrap wrap) {
    if (x >= 0 && x < image.width() && y >= 0 && y < image.height())
        return texels[(size_t(y) * image.width() + x) * image.channels() + c];
    return image.texel(x, y, c, wrap);
}

// The image resampled up to (width, height), reading past its edges by the wrap mode: rows
// first, then columns, clamped at zero (the sinc's lobes can go negative). Rows in parallel.
std::shared_ptr<const TexelImage> resize_up(const TexelImage &image, int width, int height, ImageWrap wrap) {
    const int nc = image.channels();
    const float *source = image.data();
    const std::vector<ResampleWeight> wx = resample_weights(image.width(), width);
    const std::vector<ResampleWeight> wy = resample_weights(image.height(), height);
    // Rows resampled in x, for every source row a column filter can reach (y0 .. y1).
    const int y0 = wy.front().first, y1 = wy.back().first + 4;
    std::vector<float> rows(size_t(y1 - y0) * width * nc);
    tbb::parallel_for(y0, y1, [&](int y) {
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < nc; ++c) {
                float v = 0;
                for (int j = 0; j < 4; ++j) v += wx[x].w[j] * texel_or_wrapped(image, source, wx[x].first + j, y, c, wrap);
                rows[(size_t(y - y0) * width + x) * nc + c] = v;
            }
    });
    std::vector<float> texels(size_t(width) * height * nc);
    tbb::parallel_for(0, height, [&](int y) {
        const float *r = &rows[size_t(wy[y].first - y0) * width * nc];
        const size_t stride = size_t(width) * nc;
        for (size_t i = 0; i < stride; ++i) {
            const float v = wy[y].w[0] * r[i] + wy[y].w[1] * r[i + stride] + wy[y].w[2] * r[i + 2 * stride] +
                            wy[y].w[3] * r[i + 3 * stride];
            texels[size_t(y) * stride + i] = std::max(0.f, v);
        }
    });
    return std::make_shared<TexelImage>(width, height, nc, std::move(texels));
}

// The next level: each texel the mean of the 2x2 below it (a side of 1 stays 1).
std::shared_ptr<const TexelImage> downsample(const TexelImage &image) {
    const int nc = image.channels(), w = image.width();
    const float *source = image.data();
    const int width = std::max(1, w / 2), height = std::max(1, image.height() / 2);
    const int dx = w > 1 ? 1 : 0, dy = image.height() > 1 ? 1 : 0;
    std::vector<float> texels(size_t(width) * height * nc);
    tbb::parallel_for(0, height, [&](int y) {
        const float *row0 = source + size_t(2 * y) * w * nc, *row1 = source + size_t(2 * y + dy) * w * nc;
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < nc; ++c) {
                const size_t a = size_t(2 * x) * nc + c, b = size_t(2 * x + dx) * nc + c;
                texels[(size_t(y) * width + x) * nc + c] = (row0[a] + row0[b] + row1[a] + row1[b]) / 4;
            }
    });
    return std::make_shared<TexelImage>(width, height, nc, std::move(texels));
}

// The EWA filter's truncated Gaussian, exp(-2 r^2) - exp(-2), tabulated over r^2 in [0, 1].
constexpr int EWATableSize = 128;
const std::array<float, EWATableSize> &ewa_weights() {
    static const std::array<float, EWATableSize> table = [] {
        std::array<float, EWATableSize> t{};
        for (int i = 0; i < EWATableSize; ++i) {
            const float r2 = float(i) / (EWATableSize - 1);
            t[i] = std::exp(-2 * r2) - std::exp(-2.f);
        }
        return t;
    }();
    return table;
}

} // namespace

MIPMap::MIPMap(std::shared_ptr<const TexelImage> image, ImageWrap wrap, MIPFilter filter, float max_anisotropy)
    : wrap_(wrap), filter_(filter), max_anisotropy_(max_anisotropy) {
    if (!is_power_of_2(image->width()) || !is_power_of_2(image->height()))
        image = resize_up(*image, round_up_power_of_2(image->width()), round_up_power_of_2(image->height()), wrap);
    pyramid_.push_back(std::move(image));
    while (pyramid_.back()->width() > 1 || pyramid_.back()->height() > 1)
        pyramid_.push_back(downsample(*pyramid_.back()));
}

void MIPMap::texel(int level, int x, int y, float *out) const {
    for (int c = 0; c < channels(); ++c) out[c] = pyramid_[level]->texel(x, y, c, wrap_);
}

void MIPMap::bilerp(int level, Vec2f st, float *out) const { pyramid_[level]->bilerp(st, wrap_, out); }

void MIPMap::filter(Vec2f st, Vec2f dst0, Vec2f dst1, float *out) const {
    const int nc = channels();
    if (!std::isfinite(st.x) || !std::isfinite(st.y)) {
        for (int c = 0; c < nc; ++c) out[c] = 0;
        return;
    }
    if (!std::isfinite(dst0.x + dst0.y + dst1.x + dst1.y)) dst0 = dst1 = Vec2f{0, 0};
    // Texel indices must stay within int: a repeating image is looked up the same a whole number
    // of repeats away (st - floor(st) is exact), any other is constant that far outside.
    if (wrap_ == ImageWrap::Repeat) st = {st.x - std::floor(st.x), st.y - std::floor(st.y)};
    else st = {std::clamp(st.x, -1e4f, 1e4f), std::clamp(st.y, -1e4f, 1e4f)};
    if (filter_ != MIPFilter::EWA) {
        // The level whose texels are as wide as the footprint's widest extent.
        const float width = 2 * std::max({std::abs(dst0.x), std::abs(dst0.y), std::abs(dst1.x), std::abs(dst1.y)});
        const float level = float(levels() - 1) + std::log2(std::max(width, 1e-8f));
        if (!(level < float(levels() - 1))) return texel(levels() - 1, 0, 0, out);
        const int i = std::max(0, int(std::floor(level)));
        if (filter_ == MIPFilter::Point) {
            const TexelImage &l = *pyramid_[i];
            return texel(i, int(std::round(st.x * l.width() - 0.5f)), int(std::round(st.y * l.height() - 0.5f)), out);
        }
        if (filter_ == MIPFilter::Bilinear || i == 0) return bilerp(i, st, out);
        float a[4], b[4];
        bilerp(i, st, a);
        bilerp(i + 1, st, b);
        const float t = level - float(i);
        for (int c = 0; c < nc; ++c) out[c] = lerp(t, a[c], b[c]);
        return;
    }
    // EWA: dst0 the major axis, its length at most max_anisotropy times the minor's.
    if (length_squared(dst0) < length_squared(dst1)) std::swap(dst0, dst1);
    const float major = std::sqrt(length_squared(dst0));
    float minor = std::sqrt(length_squared(dst1));
    if (minor * max_anisotropy_ < major && minor > 0) {
        const float scale = major / (minor * max_anisotropy_);
        dst1 = dst1 * scale;
        minor *= scale;
    }
    if (!(minor > 0)) return bilerp(0, st, out);
    const float lod = std::max(0.f, float(levels() - 1) + std::log2(minor));
    const int i = int(std::floor(lod));
    float a[4], b[4];
    ewa(i, st, dst0, dst1, a);
    ewa(i + 1, st, dst0, dst1, b);
    const float t = lod - float(i);
    for (int c = 0; c < nc; ++c) out[c] = lerp(t, a[c], b[c]);
}

void MIPMap::ewa(int level, Vec2f st, Vec2f dst0, Vec2f dst1, float *out) const {
    const int nc = channels();
    if (level >= levels()) return texel(levels() - 1, 0, 0, out);
    // In this level's texel units, texel centres at integers.
    const TexelImage &l = *pyramid_[level];
    const float w = float(l.width()), h = float(l.height());
    const float s = st.x * w - 0.5f, t = st.y * h - 0.5f;
    dst0 = {dst0.x * w, dst0.y * h};
    dst1 = {dst1.x * w, dst1.y * h};
    // The implicit ellipse A s^2 + B s t + C t^2 < 1 spanned by the axes, grown by a texel so
    // that it covers at least one (Heckbert 1989, 3.5.8).
    float A = sqr(dst0.y) + sqr(dst1.y) + 1;
    float B = -2 * (dst0.x * dst0.y + dst1.x * dst1.y);
    float C = sqr(dst0.x) + sqr(dst1.x) + 1;
    const float inv_f = 1 / (A * C - sqr(B) * 0.25f);
    A *= inv_f;
    B *= inv_f;
    C *= inv_f;
    // Its bounding box.
    const float det = -sqr(B) + 4 * A * C, inv_det = 1 / det;
    const float u_sqrt = safe_sqrt(det * C), v_sqrt = safe_sqrt(A * det);
    const int s0 = int(std::ceil(s - 2 * inv_det * u_sqrt)), s1 = int(std::floor(s + 2 * inv_det * u_sqrt));
    const int t0 = int(std::ceil(t - 2 * inv_det * v_sqrt)), t1 = int(std::floor(t + 2 * inv_det * v_sqrt));
    const std::array<float, EWATableSize> &table = ewa_weights();
    float sum[4] = {0, 0, 0, 0}, texel_value[4];
    float sum_weights = 0;
    for (int it = t0; it <= t1; ++it) {
        const float tt = float(it) - t;
        for (int is = s0; is <= s1; ++is) {
            const float ss = float(is) - s;
            const float r2 = A * ss * ss + B * ss * tt + C * tt * tt;
            if (!(r2 < 1)) continue;
            const float weight = table[std::min(int(r2 * EWATableSize), EWATableSize - 1)];
            texel(level, is, it, texel_value);
            for (int c = 0; c < nc; ++c) sum[c] += weight * texel_value[c];
            sum_weights += weight;
        }
    }
    for (int c = 0; c < nc; ++c) out[c] = sum_weights > 0 ? sum[c] / sum_weights : 0.f;
}

} // namespace caustica
