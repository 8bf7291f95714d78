#include "film/film.h"

#include "spectral/camera_sensor_data.h"
#include "spectral/cie.h"
#include "spectral/named_spectra.h"

#include <cassert>
#include <cmath>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace caustica {

Film::Film(Vec2i full_resolution, PixelBounds pixel_bounds, std::unique_ptr<Filter> filter,
           const RGBColorSpace &output, const PixelSensor &sensor, float max_component_value,
           std::string filename, bool save_fp16)
    : full_resolution_(full_resolution), pixel_bounds_(pixel_bounds), filter_(std::move(filter)),
      filter_integral_(filter_->integral()), output_(&output), sensor_(sensor),
      output_from_sensor_(output.rgb_from_xyz_matrix() * sensor.xyz_from_sensor_rgb()),
      max_component_value_(max_component_value), filename_(std::move(filename)),
      save_fp16_(save_fp16), splats_(pixel_bounds.min, pixel_bounds.max, *filter_) {
    if (pixel_bounds_.empty()) throw std::invalid_argument("film: empty pixel bounds");
}

// Allocated once; a store restored from a checkpoint is already there.
Film::Pixel *Film::camera_pixels() {
    std::call_once(pixels_allocated_, [this] {
        if (pixels_.empty()) pixels_.resize(pixel_count());
        if (spectral_ && bucket_sums_.empty()) bucket_sums_.resize(pixel_count() * spectral_->count());
    });
    return pixels_.data();
}

FilmExtent Film::extent() const {
    Vec2f r = filter_->radius();
    return {full_resolution_,
            {pixel_bounds_.min.x - r.x + 0.5f, pixel_bounds_.min.y - r.y + 0.5f},
            {pixel_bounds_.max.x + r.x - 0.5f, pixel_bounds_.max.y + r.y - 0.5f},
            r,
            diagonal_};
}

void Film::set_spectral(const SpectralBuckets &buckets) {
    spectral_ = buckets;
    bucket_splats_ = std::make_unique<SplatBuffer>(pixel_bounds_.min, pixel_bounds_.max, *filter_, buckets.count());
}

void Film::set_gbuffer(bool camera_space) {
    gbuffer_ = true;
    gbuffer_camera_space_ = camera_space;
    if (moments_.empty()) moments_.assign(pixel_count(), Moments{});
}

void Film::set_achromatic(const Spectrum &colour, float lambda) {
    achromatic_rgb_ = sensor_.to_sensor_rgb(colour) / colour(lambda);
    if (spectral_) {
        // Each bucket's mean of the colour, at every integer wavelength in it (the resolution of
        // tabulated spectra) or its centre if it holds none.
        achromatic_buckets_.assign(spectral_->count(), 0);
        std::vector<int> counts(spectral_->count(), 0);
        for (int l = int(std::ceil(spectral_->lambda_min())); l <= int(std::floor(spectral_->lambda_max())); ++l) {
            const int b = spectral_->bucket_of(float(l));
            achromatic_buckets_[b] += colour(float(l));
            ++counts[b];
        }
        for (int b = 0; b < spectral_->count(); ++b)
            achromatic_buckets_[b] = (counts[b] > 0 ? achromatic_buckets_[b] / counts[b] : colour(spectral_->centre(b))) /
                                     colour(lambda);
    }
}

template <typename Add>
void Film::for_each_bucket_value(const SampledSpectrum &L_in, const SampledWavelengths &lambda, ValueKind kind,
                                 Add &&add) const {
    // pbrt-v4 clamps the spectral value by its largest wavelength.
    SampledSpectrum L = L_in;
    const float lm = L.max_value();
    if (kind == ValueKind::Sample && lm > max_component_value_) L *= max_component_value_ / lm;
    if (monochromatic_) {
        // One wavelength only: its radiance goes to its bucket.
        if (spectral_->contains(lambda[0])) add(spectral_->bucket_of(lambda[0]), double(safe_div(L, lambda.pdf()).average()));
    } else if (achromatic_rgb_) {
        const double per_unit = L.average();
        if (per_unit != 0)
            for (int b = 0; b < spectral_->count(); ++b) add(b, per_unit * achromatic_buckets_[b]);
    } else {
        const SampledSpectrum estimate = safe_div(L, lambda.pdf()) / (float(NumWavelengths) * spectral_->width());
        for (int i = 0; i < NumWavelengths; ++i)
            if (estimate[i] != 0 && spectral_->contains(lambda[i])) add(spectral_->bucket_of(lambda[i]), double(estimate[i]));
    }
}

void Film::add_bucket_values(const SampledSpectrum &L, const SampledWavelengths &lambda, double *out,
                             ValueKind kind) const {
    for_each_bucket_value(L, lambda, kind, [out](int b, double v) { out[b] += v; });
}

RGB Film::sensor_value(const SampledSpectrum &L, const SampledWavelengths &lambda, ValueKind kind) const {
    RGB v;
    if (monochromatic_) {
        float grey = safe_div(L, lambda.pdf()).average() * sensor_.imaging_ratio();
        v = {grey, grey, grey};
    } else if (achromatic_rgb_) {
        v = *achromatic_rgb_ * L.average();
    } else {
        v = sensor_.to_sensor_rgb(L, lambda);
    }
    // pbrt-v4's clamp: scale the value down so its largest component is the maximum, which
    // keeps its chromaticity.
    float m = v.max_component();
    if (kind == ValueKind::Sample && m > max_component_value_) v *= max_component_value_ / m;
    return v;
}

void Film::add_sample(Vec2i pixel, const SampledSpectrum &L, const SampledWavelengths &lambda,
                      float filter_weight) {
    assert(!L.has_non_finite());
    add_sensor_value(pixel, sensor_value(L, lambda), filter_weight);
    if (spectral_ && pixel_bounds_.contains(pixel)) {
        int64_t *sums = &bucket_sums_[index(pixel) * spectral_->count()];
        bool ok = true;
        for_each_bucket_value(L, lambda, ValueKind::Sample,
                              [&](int b, double v) { ok &= fixed_point::add(sums[b], double(filter_weight) * v); });
        if (!ok) camera_overflow_ = true;
    }
}

void Film::add_sensor_value(Vec2i pixel, RGB v, float filter_weight, const double *bucket_values) {
    assert(std::isfinite(filter_weight));
    assert(pixel_bounds_.contains(pixel));
    // Outside a crop window there is no storage: dropping the sample keeps a caller that
    // iterates the full frame from corrupting memory in release builds.
    if (!pixel_bounds_.contains(pixel)) return;
    Pixel &p = camera_pixels()[index(pixel)];
    bool ok = true;
    for (int c = 0; c < 3; ++c) ok &= fixed_point::add(p.rgb_sum[c], double(filter_weight) * v[c]);
    ok &= fixed_point::add(p.weight_sum, filter_weight);
    if (spectral_ && bucket_values) {
        int64_t *sums = &bucket_sums_[index(pixel) * spectral_->count()];
        for (int b = 0; b < spectral_->count(); ++b) ok &= fixed_point::add(sums[b], double(filter_weight) * bucket_values[b]);
    }
    if (!moments_.empty()) {
        RGB out = monochromatic_ ? v : output_from_sensor_ * v;
        Moments &m = moments_[index(pixel)];
        for (int c = 0; c < 3; ++c) {
            ok &= fixed_point::add(m.sum[c], out[c]);
            ok &= fixed_point::add(m.sum_sq[c], double(out[c]) * out[c]);
        }
        ++m.count;
    }
    if (!ok) camera_overflow_ = true;
}

void Film::add_splat(Vec2f p_raster, const SampledSpectrum &L, const SampledWavelengths &lambda) {
    assert(!L.has_non_finite());
    splats_.add(p_raster, sensor_value(L, lambda));
    if (!spectral_) return;
    // Four buckets per record; an achromatic sample fills every bucket.
    SplatValues values;
    for_each_bucket_value(L, lambda, ValueKind::Sample, [&](int b, double v) {
        values.add(b, float(v));
        if (values.count == int(values.value.size())) {
            bucket_splats_->add(p_raster, values);
            values = SplatValues{};
        }
    });
    if (values.count > 0) bucket_splats_->add(p_raster, values);
}

Image Film::get_image(double splat_scale, std::map<std::string, std::string> *metadata) const {
    splats_.flush();
    const std::vector<int64_t> &splats = splats_.sums();
    Image image(pixel_bounds_.width(), pixel_bounds_.height());
    image.origin = pixel_bounds_.min;
    image.full_resolution = full_resolution_;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            size_t i = size_t(y) * image.width + x;
            double sensor[3] = {0, 0, 0};
            if (!pixels_.empty()) {
                const Pixel &p = pixels_[i];
                for (int c = 0; c < 3; ++c)
                    sensor[c] = p.weight_sum != 0 ? fixed_point::value(p.rgb_sum[c]) / fixed_point::value(p.weight_sum) : 0;
            }
            if (!splats.empty())
                for (int c = 0; c < 3; ++c) {
                    double splat = fixed_point::value(splats[i * 3 + c]);
                    sensor[c] += splat_scale * splat / filter_integral_;
                }
            RGB v{float(sensor[0]), float(sensor[1]), float(sensor[2])};
            if (!monochromatic_) v = output_from_sensor_ * v;
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = v[c];
        }
    if (variance_layer_) {
        Image::Layer variance{"variance", std::vector<float>(image.rgb.size(), 0.f)};
        for (size_t i = 0; i < moments_.size(); ++i) {
            const Moments &m = moments_[i];
            if (m.count < 2) continue;
            for (int c = 0; c < 3; ++c) variance.rgb[i * 3 + c] = float(m.sample_variance(c) / m.count);
        }
        image.layers.push_back(std::move(variance));
    }
    if (gbuffer_) add_sample_variance_layers(image);
    if (spectral_) add_bucket_channels(image, splat_scale, metadata);
    if (splats_.take_overflow())
        warning("light-tracing contributions exceeded the film's fixed-point range; the image "
                "is wrong where they landed");
    if (camera_overflow_.exchange(false))
        warning("camera samples exceeded the film's fixed-point range; the image is wrong where they were taken");
    return image;
}

// pbrt-v4's G-buffer variance layers: each pixel's sample variance s^2 of its camera samples
// (not of their mean), and s^2 over the mean.
void Film::add_sample_variance_layers(Image &image) const {
    Image::Layer variance{"Variance", std::vector<float>(image.rgb.size(), 0.f)};
    Image::Layer relative{"RelativeVariance", std::vector<float>(image.rgb.size(), 0.f)};
    for (size_t i = 0; i < moments_.size(); ++i) {
        const Moments &m = moments_[i];
        if (m.count < 2) continue;
        for (int c = 0; c < 3; ++c) {
            const double s2 = m.sample_variance(c), mean = m.mean(c);
            variance.rgb[i * 3 + c] = float(s2);
            relative.rgb[i * 3 + c] = mean != 0 ? float(s2 / mean) : 0.f;
        }
    }
    image.layers.push_back(std::move(variance));
    image.layers.push_back(std::move(relative));
}

void Film::add_bucket_channels(Image &image, double splat_scale, std::map<std::string, std::string> *metadata) const {
    bucket_splats_->flush();
    const std::vector<int64_t> &splats = bucket_splats_->sums();
    const int n = spectral_->count();
    const size_t pixels = size_t(image.width) * image.height;
    for (int b = 0; b < n; ++b) {
        Image::Channel channel{spectral_->channel_name(b), std::vector<float>(pixels, 0.f)};
        for (size_t i = 0; i < pixels; ++i) {
            double value = 0;
            if (!pixels_.empty() && pixels_[i].weight_sum != 0)
                value = fixed_point::value(bucket_sums_[i * n + b]) / fixed_point::value(pixels_[i].weight_sum);
            if (!splats.empty()) value += splat_scale * fixed_point::value(splats[i * n + b]) / filter_integral_;
            channel.values[i] = float(value * CIE_Y_integral);
        }
        image.channels.push_back(std::move(channel));
    }
    if (bucket_splats_->take_overflow())
        warning("light-tracing contributions exceeded the spectral film's fixed-point range; its buckets are "
                "wrong where they landed");
    if (metadata) {
        (*metadata)["spectralLayoutVersion"] = "1.0";
        (*metadata)["emissiveUnits"] = "W.m^-2.sr^-1";
    }
}

namespace {

void write_u64(std::ostream &out, uint64_t value) { out.write(reinterpret_cast<const char *>(&value), sizeof value); }

uint64_t read_u64(std::istream &in) {
    uint64_t value = 0;
    in.read(reinterpret_cast<char *>(&value), sizeof value);
    return value;
}

template <typename T> void write_array(std::ostream &out, const std::vector<T> &values) {
    write_u64(out, values.size());
    out.write(reinterpret_cast<const char *>(values.data()), std::streamsize(values.size() * sizeof(T)));
}

// Reads an array that must hold `count` elements, or none if `may_be_empty` (a store that was
// never written).
template <typename T>
void read_array(std::istream &in, std::vector<T> &values, size_t count, bool may_be_empty = false) {
    const uint64_t stored = read_u64(in);
    if ((stored != count && !(may_be_empty && stored == 0)) || !in) throw std::runtime_error("film state: wrong pixel count");
    values.resize(stored);
    in.read(reinterpret_cast<char *>(values.data()), std::streamsize(stored * sizeof(T)));
    if (!in) throw std::runtime_error("film state: truncated");
}

} // namespace

void Film::save_state(std::ostream &out) const {
    write_array(out, pixels_);
    write_array(out, moments_);
    splats_.flush();
    write_array(out, splats_.sums());
    write_u64(out, splats_.overflowed() ? 1 : 0);
    if (spectral_) {
        write_array(out, bucket_sums_);
        bucket_splats_->flush();
        write_array(out, bucket_splats_->sums());
        write_u64(out, bucket_splats_->overflowed() ? 1 : 0);
    }
}

void Film::restore_state(std::istream &in) {
    std::vector<Pixel> pixels;
    read_array(in, pixels, pixel_count(), true);
    std::vector<Moments> moments;
    read_array(in, moments, moments_.size());
    std::vector<int64_t> splats;
    read_array(in, splats, pixel_count() * 3, true);
    const uint64_t overflow = read_u64(in);
    if (!in || overflow > 1) throw std::runtime_error("film state: truncated");
    std::vector<int64_t> bucket_sums;
    std::vector<int64_t> bucket_splats;
    uint64_t bucket_overflow = 0;
    if (spectral_) {
        read_array(in, bucket_sums, pixel_count() * spectral_->count(), true);
        read_array(in, bucket_splats, pixel_count() * spectral_->count(), true);
        bucket_overflow = read_u64(in);
        if (!in || bucket_overflow > 1 || bucket_sums.empty() != pixels.empty())
            throw std::runtime_error("film state: truncated");
    }
    // A store the film has allocated keeps its size: camera_pixels() hands out its address.
    if (pixels.empty() && !pixels_.empty()) pixels.assign(pixels_.size(), Pixel{});
    pixels_ = std::move(pixels);
    moments_ = std::move(moments);
    splats_.restore(std::move(splats));
    splats_.set_overflow(overflow != 0);
    if (spectral_) {
        if (bucket_sums.empty() && !bucket_sums_.empty()) bucket_sums.assign(bucket_sums_.size(), 0);
        bucket_sums_ = std::move(bucket_sums);
        bucket_splats_->restore(std::move(bucket_splats));
        bucket_splats_->set_overflow(bucket_overflow != 0);
    }
}

namespace {

constexpr uint32_t CameraSamples = 1, Splats = 2, BucketSplats = 4; // Film::stores()

} // namespace

uint32_t Film::stores() const {
    splats_.flush();
    if (bucket_splats_) bucket_splats_->flush();
    return (pixels_.empty() ? 0 : CameraSamples) | (splats_.sums().empty() ? 0 : Splats) |
           (bucket_splats_ && !bucket_splats_->sums().empty() ? BucketSplats : 0);
}

Film::Sums Film::sums(uint32_t stores) {
    Sums sums;
    auto add = [&](int64_t *data, size_t count) { sums.narrow.emplace_back(data, count); };
    if (stores & CameraSamples) {
        camera_pixels();
        add(reinterpret_cast<int64_t *>(pixels_.data()), pixels_.size() * sizeof(Pixel) / sizeof(int64_t));
        if (spectral_) add(bucket_sums_.data(), bucket_sums_.size());
    }
    splats_.flush();
    if (stores & Splats) {
        std::vector<int64_t> &splats = splats_.sums(true);
        add(splats.data(), splats.size());
    }
    if (bucket_splats_ && (stores & BucketSplats)) {
        bucket_splats_->flush();
        std::vector<int64_t> &splats = bucket_splats_->sums(true);
        add(splats.data(), splats.size());
    }
    sums.wide = {reinterpret_cast<fixed_point::Wide *>(moments_.data()),
                 moments_.size() * sizeof(Moments) / sizeof(fixed_point::Wide)};
    sums.overflow = (camera_overflow_ ? CameraSamples : 0) | (splats_.overflowed() ? Splats : 0) |
                    (bucket_splats_ && bucket_splats_->overflowed() ? BucketSplats : 0);
    return sums;
}

void Film::set_overflow(uint32_t flags) {
    camera_overflow_ = (flags & CameraSamples) != 0;
    splats_.set_overflow((flags & Splats) != 0);
    if (bucket_splats_) bucket_splats_->set_overflow((flags & BucketSplats) != 0);
}

CameraSample get_camera_sample(Sampler &sampler, Vec2i pixel, const Filter &filter, const Shutter *shutter) {
    FilterSample fs = filter.sample(sampler.get_pixel_2d());
    CameraSample cs;
    cs.p_film = {pixel.x + 0.5f + fs.p.x, pixel.y + 0.5f + fs.p.y};
    cs.p_lens = sampler.get_2d();
    if (shutter) cs.time = shutter->time(sampler.get_1d());
    cs.filter_weight = fs.weight;
    return cs;
}

// ---- Factory ----

namespace {

// pbrt-v4's crop window: each range is ordered and clamped to [0, 1]; the first pixel is the one
// whose left/top edge is at or after the window's start.
PixelBounds crop_window_bounds(const std::vector<float> &cw, Vec2i full) {
    float x0 = clamp(std::min(cw[0], cw[1]), 0.f, 1.f), x1 = clamp(std::max(cw[0], cw[1]), 0.f, 1.f);
    float y0 = clamp(std::min(cw[2], cw[3]), 0.f, 1.f), y1 = clamp(std::max(cw[2], cw[3]), 0.f, 1.f);
    return {{int(std::ceil(full.x * x0)), int(std::ceil(full.y * y0))},
            {int(std::ceil(full.x * x1)), int(std::ceil(full.y * y1))}};
}

PixelBounds clamp_to_image(PixelBounds b, Vec2i full) {
    return {{std::max(b.min.x, 0), std::max(b.min.y, 0)}, {std::min(b.max.x, full.x), std::min(b.max.y, full.y)}};
}

PixelBounds read_pixel_bounds(const ParameterDictionary &params, Vec2i full, const SourceLocation &loc,
                              const FilmOverrides &overrides) {
    PixelBounds bounds{{0, 0}, full};
    if (!overrides.crop_window.empty() || !overrides.pixel_bounds.empty()) {
        // The command line's choice replaces the file's.
        if (!overrides.crop_window.empty()) {
            if (overrides.crop_window.size() != 4)
                throw InputError("--cropwindow needs 4 values (x0 x1 y0 y1)");
            for (float v : overrides.crop_window)
                if (!std::isfinite(v)) throw InputError("--cropwindow values must be finite numbers");
            bounds = crop_window_bounds(overrides.crop_window, full);
        } else {
            const std::vector<int> &pb = overrides.pixel_bounds;
            if (pb.size() != 4) throw InputError("--pixelbounds needs 4 values (x0 x1 y0 y1)");
            PixelBounds given{{pb[0], pb[2]}, {pb[1], pb[3]}};
            bounds = clamp_to_image(given, full);
            if (!(bounds == given)) warning("--pixelbounds extends beyond the image; clamping it");
        }
        if (bounds.empty()) throw InputError("the pixel bounds given on the command line are empty");
        return bounds;
    }
    std::vector<int> pb = params.get_int_array("pixelbounds");
    std::vector<float> cw = params.get_float_array("cropwindow");
    if (!pb.empty()) {
        if (pb.size() != 4)
            throw InputError(params.location("pixelbounds"),
                             "\"pixelbounds\" needs 4 values (x0 x1 y0 y1), got " + std::to_string(pb.size()));
        PixelBounds given{{pb[0], pb[2]}, {pb[1], pb[3]}};
        bounds = clamp_to_image(given, full);
        if (!(bounds == given))
            warning(params.location("pixelbounds"), "\"pixelbounds\" extends beyond the image; clamping it");
    }
    if (!cw.empty()) {
        if (cw.size() != 4)
            throw InputError(params.location("cropwindow"),
                             "\"cropwindow\" needs 4 values (x0 x1 y0 y1), got " + std::to_string(cw.size()));
        for (float v : cw)
            if (!std::isfinite(v))
                throw InputError(params.location("cropwindow"), "\"cropwindow\" values must be finite numbers");
        if (!pb.empty())
            warning(params.location("cropwindow"), "both \"pixelbounds\" and \"cropwindow\" are given; "
                                                   "using the crop window");
        bounds = crop_window_bounds(cw, full);
    }
    if (bounds.empty()) throw InputError(loc, "the film's pixel bounds (crop window) are empty");
    return bounds;
}

// pbrt-v4's spectral film parameters; pbrt-v4 renders wavelengths in [360, 830] nm only.
SpectralBuckets read_spectral_buckets(const ParameterDictionary &params) {
    const int count = params.get_one_int("nbuckets", 16);
    if (count < 1 || count > 4096)
        throw InputError(params.location("nbuckets"), "\"nbuckets\" must be between 1 and 4096");
    const float lo = params.get_one_float("lambdamin", LambdaMin), hi = params.get_one_float("lambdamax", LambdaMax);
    if (!(lo >= LambdaMin && lo <= LambdaMax))
        throw InputError(params.location("lambdamin"), "\"lambdamin\" must lie in [360, 830] nm, the wavelengths rendered");
    if (!(hi >= LambdaMin && hi <= LambdaMax))
        throw InputError(params.location("lambdamax"), "\"lambdamax\" must lie in [360, 830] nm, the wavelengths rendered");
    if (!(lo < hi))
        throw InputError(params.location("lambdamax"), "\"lambdamax\" must be greater than \"lambdamin\"");
    return SpectralBuckets(count, lo, hi);
}

} // namespace

std::unique_ptr<Film> create_film(const std::string &type, const ParameterDictionary &params,
                                  const RGBColorSpace *color_space, std::unique_ptr<Filter> filter,
                                  const SourceLocation &loc, const FilmOverrides &overrides,
                                  float exposure_time) {
    if (type != "rgb" && type != "gbuffer" && type != "spectral")
        throw InputError(loc, "\"" + type + "\": unknown film type");
    const RGBColorSpace &output = color_space ? *color_space : RGBColorSpace::srgb();

    Vec2i full{params.get_one_int("xresolution", 1280), params.get_one_int("yresolution", 720)};
    if (overrides.resolution.x > 0) full.x = overrides.resolution.x;
    if (overrides.resolution.y > 0) full.y = overrides.resolution.y;
    if (full.x < 1) throw InputError(params.location("xresolution"), "\"xresolution\" must be positive");
    if (full.y < 1) throw InputError(params.location("yresolution"), "\"yresolution\" must be positive");
    PixelBounds bounds = read_pixel_bounds(params, full, loc, overrides);

    std::string filename = params.get_one_string("filename", "");
    if (filename.empty()) filename = "pbrt.exr";
    const float diagonal_mm = params.get_one_float("diagonal", 35);  // the realistic camera's film size
    if (!(diagonal_mm > 0) || !std::isfinite(diagonal_mm))
        throw InputError(params.location("diagonal"), "\"diagonal\" must be a positive length in millimetres");

    float iso = params.get_one_float("iso", 100);
    if (!(iso > 0)) throw InputError(params.location("iso"), "\"iso\" must be positive");
    const std::string sensor_name = params.get_one_string("sensor", "cie1931");
    const CameraSensorCurves *camera_sensor = nullptr;
    for (const CameraSensorCurves &curves : camera_sensor_curves())
        if (curves.name == sensor_name) camera_sensor = &curves;
    if (sensor_name != "cie1931" && !camera_sensor) {
        std::string known = "\"cie1931\"";
        for (const CameraSensorCurves &curves : camera_sensor_curves()) known += ", \"" + curves.name + "\"";
        throw InputError(params.location("sensor"), "unknown sensor \"" + sensor_name + "\" (known: " + known + ")");
    }
    float white_balance = params.get_one_float("whitebalance", 0);
    // pbrt-v4 white-balances camera sensors to 6500 K unless told otherwise.
    if (camera_sensor && white_balance == 0) white_balance = 6500;
    if (!(white_balance >= 0))
        throw InputError(params.location("whitebalance"), "\"whitebalance\" must not be negative");
    float max_component = params.get_one_float("maxcomponentvalue", Infinity);
    if (!(max_component > 0))
        throw InputError(params.location("maxcomponentvalue"), "\"maxcomponentvalue\" must be positive");
    bool fp16 = params.get_one_bool("savefp16", false);

    std::optional<PixelSensor> sensor;
    try {
        const float imaging_ratio = exposure_time * iso / 100;
        if (camera_sensor)
            sensor.emplace(output, *get_named_spectrum(sensor_name + "_r"), *get_named_spectrum(sensor_name + "_g"),
                           *get_named_spectrum(sensor_name + "_b"), white_balance,
                           imaging_ratio);
        else
            sensor.emplace(output, white_balance, imaging_ratio);
    } catch (const std::domain_error &e) {
        throw InputError(params.location("whitebalance"), e.what());
    }
    auto film = std::make_unique<Film>(full, bounds, std::move(filter), output, *sensor, max_component,
                                       filename, fp16);
    film->set_diagonal(diagonal_mm / 1000);
    if (type != "rgb" && !filename.ends_with(".exr"))
        throw InputError(params.location("filename"),
                         "\"" + filename + "\": the \"" + type + "\" film writes only OpenEXR files (.exr)");
    if (type == "spectral") film->set_spectral(read_spectral_buckets(params));
    if (type == "gbuffer") {
        const std::string system = params.get_one_string("coordinatesystem", "camera");
        if (system != "camera" && system != "world")
            throw InputError(params.location("coordinatesystem"),
                             "\"coordinatesystem\" must be \"camera\" or \"world\", not \"" + system + "\"");
        film->set_gbuffer(system == "camera");
    }
    return film;
}

} // namespace caustica
