// The film: accumulates radiance samples into pixels and produces the image (pbrt-v4's RGBFilm).
//
// Camera samples (add_sample) go to the pixel they were taken for, weighted by their filter
// weight (see filter.h); a pixel's value is the weighted average. Tiles of pixels are rendered
// by different threads, so add_sample needs no locking: each pixel is only ever written by the
// thread rendering its tile.
//
// Light-tracing contributions (add_splat) can land anywhere, from any thread: SplatBuffer
// (splat_buffer.h) sums them, in memory that does not grow with the number of threads.
//
// Every store sums in fixed point (fixed_point.h), so a pixel's sums do not depend on the order
// its samples were added in: the image is the same whatever the threads, and the stores of
// processes that shared a render's samples add up exactly to one process's (sums()).
//
// Each store is allocated when it is first written (a checkpoint restores it as it was): a
// light tracer never adds camera samples, and a path tracer never splats, so each needs only
// its own.
//
// Values are kept in the sensor's space (XYZ for the CIE 1931 sensor) as pbrt-v4 does, and
// converted to the output colour space's linear RGB when the image is made.
//
// pbrt-v4's "spectral" film (set_spectral) also keeps the spectrum in wavelength buckets
// (spectral_buckets.h). Each sample adds to bucket b its estimate of the radiance averaged over
// the bucket, (1/n) sum over the lanes i in b of L_i / (p_i width_b), which is unbiased for any
// wavelength density, as the RGB value is; the image holds the weighted average times
// CIE_Y_integral, pbrt-v4's scale (it undoes the photometric normalisation of lights' spectra),
// without the sensor's imaging ratio, as in pbrt-v4. Light-tracing splats fill the buckets the
// same way. (pbrt-v4 averages its camera samples per bucket instead, which needs its uniform
// wavelength density, and leaves buckets empty in its light tracer.)
//
// pbrt-v4's "gbuffer" film (set_gbuffer) keeps what the RGB film keeps, plus the camera
// samples' moments; its geometric layers come from the first visible surfaces, which the
// renderer traces for the image (see integrators/common/visible_surfaces.h).
#pragma once

#include "camera/camera.h"
#include "core/error.h"
#include "film/filter.h"
#include "film/fixed_point.h"
#include "film/image.h"
#include "film/image_io.h"
#include "film/pixel_sensor.h"
#include "film/spectral_buckets.h"
#include "film/splat_buffer.h"
#include "params/parameters.h"
#include "sampler/sampler.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iosfwd>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace caustica {

// A rectangle of pixels [min, max) in full-resolution raster coordinates.
struct PixelBounds {
    Vec2i min, max;
    int width() const { return max.x - min.x; }
    int height() const { return max.y - min.y; }
    bool empty() const { return width() <= 0 || height() <= 0; }
    bool contains(Vec2i p) const { return p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y; }
    bool operator==(const PixelBounds &) const = default;
};

class Film {
  public:
    // pixel_bounds: the pixels rendered (the crop window), within [0, full_resolution).
    // max_component_value clamps each sample's largest sensor component (pbrt's firefly
    // control); infinity disables it.
    Film(Vec2i full_resolution, PixelBounds pixel_bounds, std::unique_ptr<Filter> filter,
         const RGBColorSpace &output, const PixelSensor &sensor, float max_component_value,
         std::string filename, bool save_fp16);

    // The full frame; pixel_bounds() are the pixels actually rendered.
    Vec2i resolution() const { return full_resolution_; }
    const PixelBounds &pixel_bounds() const { return pixel_bounds_; }
    // What the camera needs to know about the film (pass it to create_camera).
    FilmExtent extent() const;
    const Filter &filter() const { return *filter_; }
    const RGBColorSpace &color_space() const { return *output_; }
    const std::string &filename() const { return filename_; }
    // True if the scene asked for half-float EXR output ("savefp16").
    bool save_fp16() const { return save_fp16_; }
    // The film's physical diagonal in metres ("diagonal", in millimetres in the scene file), which
    // only the realistic camera uses; 35 mm unless set.
    void set_diagonal(float metres) { diagonal_ = metres; }

    // pbrt-v4's "spectral" film: also keep the spectrum in `buckets` (see above). Call it before
    // any sample is added.
    void set_spectral(const SpectralBuckets &buckets);
    const SpectralBuckets *spectral() const { return spectral_ ? &*spectral_ : nullptr; }
    // pbrt-v4's "gbuffer" film: also keep the moments of the camera samples for the "Variance"
    // and "RelativeVariance" layers. camera_space: positions and normals in camera space (pbrt-v4's
    // "coordinatesystem" "camera") rather than world space.
    void set_gbuffer(bool camera_space);
    bool gbuffer() const { return gbuffer_; }
    bool gbuffer_camera_space() const { return gbuffer_camera_space_; }

    // Monochromatic rendering (`--wavelength`): a sample's value is the grey level
    // (1/n) sum_j L_j / pdf_j (times the imaging ratio) in every channel, with no colour
    // conversion.
    void set_monochromatic(bool on) { monochromatic_ = on; }
    // Achromatic rendering (SceneFeatures::achromatic): every path is traced at the one
    // wavelength `lambda` and carries colour(lambda) times a factor that does not depend on
    // wavelength, so a sample's value is its average over the lanes (all alike) divided by
    // colour(lambda), times the sensor's exact value for colour. No colour noise.
    void set_achromatic(const Spectrum &colour, float lambda);
    // Also keep per-pixel first and second moments of the camera samples' output RGB, so that
    // get_image() adds a "variance" layer: the estimated variance of each pixel's mean
    // (s^2 / n). It assumes equal sample weights, which pbrt's filter importance sampling gives
    // for non-negative filters; light-tracing splats are not included.
    void enable_variance() {
        variance_layer_ = true;
        moments_.assign(pixel_count(), Moments{});
    }
    bool monochromatic() const { return monochromatic_; }
    // Whether "maxcomponentvalue" clamps samples at all.
    bool clamps_samples() const { return std::isfinite(max_component_value_); }

    // A camera sample for `pixel`, which must lie inside pixel_bounds() (iterate those, not the
    // full resolution, when a crop window is set; samples outside are dropped). L must be
    // finite: integrators count and drop non-finite estimates before they reach the film.
    void add_sample(Vec2i pixel, const SampledSpectrum &L, const SampledWavelengths &lambda,
                    float filter_weight);
    // A sample already converted with sensor_value() and, for a spectral film, bucket_values()
    // (else null): for estimators that combine values of several wavelength sets per pixel before
    // adding them (progressive photon mapping).
    void add_sensor_value(Vec2i pixel, RGB value, float filter_weight, const double *bucket_values = nullptr);
    // What a value passed to the film is. "maxcomponentvalue" clamps one sample's value (pbrt-v4
    // clamps each camera sample and each splat); a density estimate gathered from many photons
    // has no such outliers to cut and is left alone, as pbrt-v4's sppm leaves its own.
    enum class ValueKind { Sample, PhotonEstimate };
    // A spectral value in the sensor's space (a sample's clamped to "maxcomponentvalue").
    RGB sensor_value(const SampledSpectrum &L, const SampledWavelengths &lambda,
                     ValueKind kind = ValueKind::Sample) const;
    // A spectral film's per-bucket estimates of L (see above), added to out[0, buckets).
    void add_bucket_values(const SampledSpectrum &L, const SampledWavelengths &lambda, double *out,
                           ValueKind kind = ValueKind::Sample) const;
    // A light-tracing contribution at a raster position; reaches every pixel within the
    // filter's radius, weighted by the filter. Thread-safe and order-independent.
    void add_splat(Vec2f p_raster, const SampledSpectrum &L, const SampledWavelengths &lambda);

    // The image over pixel_bounds(), in the output colour space's linear RGB: the weighted
    // average of the samples plus splat_scale times the splats divided by the filter's integral
    // (pbrt-v4; for light tracing, splat_scale is 1 / samples per pixel). A spectral film adds
    // its buckets' channels, a G-buffer film its variance layers (the rest is the renderer's).
    // The metadata of pbrt-v4's layout are added to `metadata` when given.
    Image get_image(double splat_scale, std::map<std::string, std::string> *metadata = nullptr) const;

    // Checkpoints: the accumulated samples (pixel sums, moments and splats) in this machine's
    // binary representation, so that a restored film continues bit-identically. restore_state
    // reads what save_state wrote for a film of the same pixel bounds with variance on or off
    // as then, and throws std::runtime_error if the data does not fit. Not thread-safe: call
    // them while nothing is being added.
    void save_state(std::ostream &out) const;
    void restore_state(std::istream &in);

    // The film's sums as arrays of integers that add element by element, for the reduction of
    // a distributed render (ProcessGroup::reduce). Stores are allocated when first written, so
    // films that took different samples may hold different ones: stores() names those this film
    // holds (a bit each), and sums(stores) gives the named ones, in a fixed order, allocating
    // those it lacks. With them, the flags of sums that left the range (a bit per store).
    struct Sums {
        std::vector<std::span<int64_t>> narrow;
        std::span<fixed_point::Wide> wide;
        uint32_t overflow = 0;
    };
    uint32_t stores() const;
    Sums sums(uint32_t stores);
    void set_overflow(uint32_t flags);

  private:
    size_t index(Vec2i pixel) const {
        return size_t(pixel.y - pixel_bounds_.min.y) * pixel_bounds_.width() + (pixel.x - pixel_bounds_.min.x);
    }

    // Fixed-point sums (fixed_point.h) of the weighted values and of the weights.
    struct Pixel {
        int64_t rgb_sum[3] = {0, 0, 0};
        int64_t weight_sum = 0;
    };
    static_assert(sizeof(Pixel) == 4 * sizeof(int64_t), "a pixel's sums add element by element");
    // All 128-bit integers, so that moments add element by element (sums()).
    struct Moments {
        fixed_point::Wide sum[3] = {0, 0, 0}, sum_sq[3] = {0, 0, 0};
        fixed_point::Wide count = 0;
        // Channel c's sample variance s^2 (count >= 2) and mean.
        double sample_variance(int c) const {
            const double m = mean(c);
            return std::max(0.0, (fixed_point::value(sum_sq[c]) - double(count) * m * m) / double(count - 1));
        }
        double mean(int c) const { return fixed_point::value(sum[c]) / double(count); }
    };

    Vec2i full_resolution_;
    PixelBounds pixel_bounds_;
    std::unique_ptr<Filter> filter_;
    float filter_integral_;
    const RGBColorSpace *output_;
    PixelSensor sensor_;
    Matrix3 output_from_sensor_;
    float max_component_value_;
    std::string filename_;
    bool save_fp16_;
    float diagonal_ = 0.035f;
    bool monochromatic_ = false;
    std::optional<RGB> achromatic_rgb_; // per unit of a sample's average, when achromatic
    // A spectral film's buckets; when achromatic, each bucket's average of the colour over the
    // colour at the traced wavelength.
    std::optional<SpectralBuckets> spectral_;
    std::vector<double> achromatic_buckets_;
    bool gbuffer_ = false, gbuffer_camera_space_ = true;
    bool variance_layer_ = false; // enable_variance() was called

    size_t pixel_count() const { return size_t(pixel_bounds_.width()) * pixel_bounds_.height(); }
    void add_sample_variance_layers(Image &image) const;
    void add_bucket_channels(Image &image, double splat_scale, std::map<std::string, std::string> *metadata) const;
    // Calls add(bucket, value) with a spectral film's estimates of L (see above).
    template <typename Add>
    void for_each_bucket_value(const SampledSpectrum &L, const SampledWavelengths &lambda, ValueKind kind,
                               Add &&add) const;
    // The camera samples' store, allocated on first use (thread-safe).
    Pixel *camera_pixels();

    std::vector<Pixel> pixels_;
    std::vector<int64_t> bucket_sums_; // a spectral film's, per pixel, with pixels_
    // Whether a camera sample's sum left the fixed-point range (reported with the image).
    mutable std::atomic<bool> camera_overflow_{false};
    std::once_flag pixels_allocated_;
    static_assert(sizeof(Moments) == 7 * sizeof(fixed_point::Wide), "moments add element by element");
    std::vector<Moments> moments_; // empty unless enable_variance()
    // Mutable: making an image or a checkpoint first adds the queued splats to the sums, which
    // changes no value the film stands for.
    mutable SplatBuffer splats_;
    mutable std::unique_ptr<SplatBuffer> bucket_splats_; // a spectral film's
};

// The camera sample for a pixel: the position within the pixel (pixel + 0.5 + a filter offset
// drawn from get_pixel_2d()), the lens position (get_2d()) and the filter weight. Consumes the
// sampler dimensions documented in sampler.h; with a shutter (Scene::motion_shutter()), also the
// time (one get_1d(), dimension 5), and without one the time is 0.
CameraSample get_camera_sample(Sampler &sampler, Vec2i pixel, const Filter &filter, const Shutter *shutter = nullptr);

// pbrt-v4's films: "rgb", "spectral" (also "nbuckets" (16), "lambdamin" (360) and "lambdamax"
// (830)) and "gbuffer" (also "coordinatesystem": "camera" (the default) or "world"); the last two
// write only OpenEXR. Their common parameters: "xresolution" (1280), "yresolution" (720), "filename" ("pbrt.exr"), "cropwindow",
// "pixelbounds", "iso" (100), "whitebalance" (0: none; 6500 for camera sensors), "sensor"
// ("cie1931", or a camera's: pixel_sensor.h), "maxcomponentvalue" (infinity), "savefp16" (false
// here: Caustica writes full floats unless asked). exposure_time is the camera's shutter
// interval.
// What the command line sets in place of the Film's parameters: resolution components > 0, and
// a crop window (x0 x1 y0 y1 in [0, 1]) or pixel bounds (x0 x1 y0 y1 in pixels) when not empty,
// as pbrt-v4's --cropwindow and --pixelbounds.
struct FilmOverrides {
    Vec2i resolution{0, 0};
    std::vector<float> crop_window;
    std::vector<int> pixel_bounds;
};

// A null color_space means sRGB.
std::unique_ptr<Film> create_film(const std::string &type, const ParameterDictionary &params,
                                  const RGBColorSpace *color_space, std::unique_ptr<Filter> filter,
                                  const SourceLocation &loc, const FilmOverrides &overrides = {},
                                  float exposure_time = 1);

} // namespace caustica
