#include "params/parameters.h"

#include "params/constant_textures.h"
#include "params/spectrum_file.h"
#include "spectral/color_space.h"
#include "spectral/named_spectra.h"
#include "spectral/rgb_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <span>

namespace caustica {

namespace {

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Values per item of the numeric types (0: any count is fine).
int values_per_item(const std::string &type) {
    if (type == "point3" || type == "vector3" || type == "normal3" || type == "rgb") return 3;
    if (type == "point2" || type == "vector2") return 2;
    return 1;
}

bool is_numeric_type(const std::string &type) {
    return type == "float" || type == "integer" || type == "point3" || type == "vector3" ||
           type == "normal3" || type == "point2" || type == "vector2" || type == "rgb" ||
           type == "blackbody";
}

// Types that describe a material or light property and may be probed one after the other
// (see the ParameterDictionary class comment).
bool is_property_type(const std::string &type) {
    return type == "float" || type == "texture" || type == "rgb" || type == "spectrum" ||
           type == "blackbody";
}

[[noreturn]] void fail(const ParsedParameter &p, const std::string &message) {
    throw InputError(p.loc, "parameter \"" + p.declaration() + "\": " + message);
}

// A reflectance above one would create energy. pbrt-v4 stops with an error; we clamp, since
// such values are mostly rounding in exported scenes, and say so at the parameter. Spectrum
// textures are built for every use they might have, so the wording allows that the parameter
// may never be used as a reflectance.
void warn_reflectance_clamped(const ParsedParameter &p) {
    warning(p.loc, "parameter \"" + p.declaration() +
                       "\": values above 1 are clamped to 1 where it is used as a reflectance");
}

float albedo_value(const ParsedParameter &p, float value) {
    if (value < 0) fail(p, "a reflectance must not be negative (" + format_number(value) + ")");
    if (value > 1) {
        warn_reflectance_clamped(p);
        return 1;
    }
    return value;
}

// Interleaved (wavelength, value) pairs as a spectrum of the given type.
SpectrumPtr piecewise_spectrum(const ParsedParameter &p, std::vector<float> pairs,
                               SpectrumType type) {
    if (type == SpectrumType::Albedo) {
        bool clamped = false;
        for (size_t i = 1; i < pairs.size(); i += 2) {
            if (pairs[i] < 0)
                fail(p, "a reflectance must not be negative (" + format_number(pairs[i]) + " at " +
                            format_number(pairs[i - 1]) + " nm)");
            clamped |= pairs[i] > 1;
            pairs[i] = std::min(pairs[i], 1.f);
        }
        if (clamped) warn_reflectance_clamped(p);
    }
    return PiecewiseLinearSpectrum::from_interleaved(pairs, false);
}

void expect_single(const ParsedParameter &p, size_t count, int per_item) {
    if (count != size_t(per_item))
        fail(p, per_item == 1 ? "expected a single value, found " + std::to_string(count)
                              : "expected one item of " + std::to_string(per_item) +
                                    " values, found " + std::to_string(count) + " values");
}

} // namespace

std::string canonical_parameter_type(const std::string &written) {
    static const char *const canonical[] = {"float",   "integer", "bool",     "string",
                                            "texture", "rgb",     "spectrum", "blackbody",
                                            "point3",  "normal3", "vector3",  "point2",
                                            "vector2"};
    for (const char *t : canonical)
        if (written == t) return written;
    // pbrt-v4 writes the 3D types both with and without the "3".
    if (written == "point") return "point3";
    if (written == "normal") return "normal3";
    if (written == "vector") return "vector3";
    return {};
}

void validate_parameter(const ParsedParameter &p) {
    const std::string &t = p.type;
    if (canonical_parameter_type(t) != t) fail(p, "unknown parameter type \"" + t + "\"");
    size_t kinds = !p.numbers.empty() + !p.strings.empty() + !p.bools.empty();
    if (kinds == 0) fail(p, "no values given");
    if (kinds > 1) fail(p, "values of different kinds (numbers, strings, booleans) mixed");
    if (is_numeric_type(t) && p.numbers.empty()) fail(p, "expected numeric values");
    if ((t == "string" || t == "texture") && p.strings.empty())
        fail(p, "expected quoted string values");
    if (t == "bool" && p.bools.empty()) fail(p, "expected true or false");
    for (double v : p.numbers) {
        if (!std::isfinite(v)) fail(p, "non-finite value");
        // Values are used as floats: beyond this they would become infinite.
        if (std::abs(v) > std::numeric_limits<float>::max())
            fail(p, format_number(v) + " is too large for single precision");
    }
    if (is_numeric_type(t)) {
        int n = values_per_item(t);
        if (p.numbers.size() % n != 0)
            fail(p, "expected a multiple of " + std::to_string(n) + " values, found " +
                        std::to_string(p.numbers.size()));
    }
    if (t == "integer")
        for (double v : p.numbers)
            if (v != std::floor(v) || std::abs(v) > 2147483647.0)
                fail(p, format_number(v) + " is not a 32-bit integer");
    if (t == "blackbody" && p.numbers.size() != 1)
        fail(p, "expected one temperature in kelvin, found " + std::to_string(p.numbers.size()) +
                    " values (pbrt-v3's second, scale, value is no longer accepted)");
    if (t == "spectrum" && p.numbers.size() > 1 && p.numbers.size() % 2 != 0)
        fail(p, "expected one constant value or wavelength-value pairs, found " +
                    std::to_string(p.numbers.size()) + " values");
}

ParameterDictionary::ParameterDictionary() = default;

ParameterDictionary::ParameterDictionary(std::vector<ParsedParameter> params,
                                         SourceLocation directive_loc,
                                         const RGBColorSpace *color_space,
                                         std::string base_directory)
    : params_(std::move(params)), directive_loc_(std::move(directive_loc)),
      color_space_(color_space), base_directory_(std::move(base_directory)) {
    for (const ParsedParameter &p : params_) validate_parameter(p);
}

void ParameterDictionary::add_defaults(const std::vector<ParsedParameter> &defaults) {
    for (const ParsedParameter &d : defaults) {
        validate_parameter(d);
        params_.push_back(d);
        params_.back().is_attribute_default = true;
    }
}

const RGBColorSpace &ParameterDictionary::color_space() const {
    return color_space_ ? *color_space_ : RGBColorSpace::srgb();
}

const ParsedParameter *ParameterDictionary::find(const std::string &name) const {
    for (const ParsedParameter &p : params_)
        if (p.name == name) return &p;
    return nullptr;
}

const ParsedParameter *
ParameterDictionary::find_typed(const std::string &name,
                                std::initializer_list<const char *> types) const {
    const ParsedParameter *p = find(name);
    if (!p) return nullptr;
    std::string wanted;
    bool wants_property = false;
    for (const char *t : types) {
        if (p->type == t) {
            p->looked_up = true;
            return p;
        }
        wants_property |= is_property_type(t);
        wanted += (wanted.empty() ? "\"" : ", \"") + std::string(t) + "\"";
    }
    if (wants_property && is_property_type(p->type)) return nullptr;
    throw InputError(p->loc, "parameter \"" + p->declaration() + "\" has the wrong type; " +
                                 (types.size() == 1 ? "expected " : "expected one of ") + wanted);
}

bool ParameterDictionary::has(const std::string &name) const { return find(name) != nullptr; }

SourceLocation ParameterDictionary::location(const std::string &name) const {
    const ParsedParameter *p = find(name);
    return p ? p->loc : directive_loc_;
}

float ParameterDictionary::get_one_float(const std::string &name, float def) const {
    const ParsedParameter *p = find_typed(name, {"float", "integer"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 1);
    return float(p->numbers[0]);
}

int ParameterDictionary::get_one_int(const std::string &name, int def) const {
    const ParsedParameter *p = find_typed(name, {"integer"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 1);
    return int(p->numbers[0]);
}

bool ParameterDictionary::get_one_bool(const std::string &name, bool def) const {
    const ParsedParameter *p = find_typed(name, {"bool"});
    if (!p) return def;
    expect_single(*p, p->bools.size(), 1);
    return p->bools[0];
}

std::string ParameterDictionary::get_one_string(const std::string &name,
                                                const std::string &def) const {
    const ParsedParameter *p = find_typed(name, {"string"});
    if (!p) return def;
    expect_single(*p, p->strings.size(), 1);
    return p->strings[0];
}

namespace {
Vec3f vec3_at(const std::vector<double> &v, size_t i) {
    return {float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2])};
}
Vec2f vec2_at(const std::vector<double> &v, size_t i) {
    return {float(v[2 * i]), float(v[2 * i + 1])};
}
} // namespace

Vec3f ParameterDictionary::get_one_point3(const std::string &name, Vec3f def) const {
    const ParsedParameter *p = find_typed(name, {"point3"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 3);
    return vec3_at(p->numbers, 0);
}

Vec3f ParameterDictionary::get_one_vector3(const std::string &name, Vec3f def) const {
    const ParsedParameter *p = find_typed(name, {"vector3"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 3);
    return vec3_at(p->numbers, 0);
}

Vec3f ParameterDictionary::get_one_normal(const std::string &name, Vec3f def) const {
    const ParsedParameter *p = find_typed(name, {"normal3"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 3);
    return vec3_at(p->numbers, 0);
}

Vec2f ParameterDictionary::get_one_point2(const std::string &name, Vec2f def) const {
    const ParsedParameter *p = find_typed(name, {"point2"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 2);
    return vec2_at(p->numbers, 0);
}

std::vector<float> ParameterDictionary::get_float_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"float", "integer"});
    if (!p) return {};
    return std::vector<float>(p->numbers.begin(), p->numbers.end());
}

std::vector<int> ParameterDictionary::get_int_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"integer"});
    if (!p) return {};
    std::vector<int> r;
    r.reserve(p->numbers.size());
    for (double v : p->numbers) r.push_back(int(v));
    return r;
}

std::vector<Vec3f> ParameterDictionary::get_point3_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"point3"});
    std::vector<Vec3f> r;
    if (p)
        for (size_t i = 0; i < p->numbers.size() / 3; ++i) r.push_back(vec3_at(p->numbers, i));
    return r;
}

std::vector<Vec3f> ParameterDictionary::get_normal_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"normal3"});
    std::vector<Vec3f> r;
    if (p)
        for (size_t i = 0; i < p->numbers.size() / 3; ++i) r.push_back(vec3_at(p->numbers, i));
    return r;
}

std::vector<Vec3f> ParameterDictionary::get_vector3_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"vector3"});
    std::vector<Vec3f> r;
    if (p)
        for (size_t i = 0; i < p->numbers.size() / 3; ++i) r.push_back(vec3_at(p->numbers, i));
    return r;
}

std::vector<Vec2f> ParameterDictionary::get_point2_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"point2"});
    std::vector<Vec2f> r;
    if (p)
        for (size_t i = 0; i < p->numbers.size() / 2; ++i) r.push_back(vec2_at(p->numbers, i));
    return r;
}

std::vector<std::string> ParameterDictionary::get_string_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"string"});
    return p ? p->strings : std::vector<std::string>{};
}

std::vector<Vec3f> ParameterDictionary::get_rgb_array(const std::string &name) const {
    const ParsedParameter *p = find_typed(name, {"rgb"});
    std::vector<Vec3f> r;
    if (p)
        for (size_t i = 0; i < p->numbers.size() / 3; ++i) r.push_back(vec3_at(p->numbers, i));
    return r;
}

SpectrumPtr ParameterDictionary::spectrum_from(const ParsedParameter &p, SpectrumType type) const {
    if (p.type == "rgb") {
        expect_single(p, p.numbers.size(), 3);
        RGB rgb{float(p.numbers[0]), float(p.numbers[1]), float(p.numbers[2])};
        if (rgb.r < 0 || rgb.g < 0 || rgb.b < 0) fail(p, "RGB components must not be negative");
        const RGBColorSpace &cs = p.color_space ? *p.color_space : color_space();
        switch (type) {
        case SpectrumType::Albedo:
            if (rgb.r > 1 || rgb.g > 1 || rgb.b > 1) {
                warn_reflectance_clamped(p);
                rgb = {std::min(rgb.r, 1.f), std::min(rgb.g, 1.f), std::min(rgb.b, 1.f)};
            }
            return std::make_shared<RGBAlbedoSpectrum>(cs, rgb);
        case SpectrumType::Unbounded:
            return std::make_shared<RGBUnboundedSpectrum>(cs, rgb);
        case SpectrumType::Illuminant:
            return std::make_shared<RGBIlluminantSpectrum>(cs, rgb);
        }
    }
    if (p.type == "blackbody") {
        expect_single(p, p.numbers.size(), 1);
        if (!(p.numbers[0] > 0)) fail(p, "the temperature must be positive");
        return std::make_shared<BlackbodySpectrum>(float(p.numbers[0]));
    }
    if (p.type == "float" || (p.type == "spectrum" && p.numbers.size() == 1)) {
        expect_single(p, p.numbers.size(), 1);
        float value = float(p.numbers[0]);
        if (type == SpectrumType::Albedo) value = albedo_value(p, value);
        return std::make_shared<ConstantSpectrum>(value);
    }
    // "spectrum": wavelength-value pairs, a named spectrum or a file.
    if (!p.numbers.empty()) {
        std::vector<float> pairs(p.numbers.begin(), p.numbers.end());
        for (size_t i = 2; i < pairs.size(); i += 2)
            if (!(pairs[i] > pairs[i - 2]))
                fail(p, "wavelengths must increase (" + format_number(pairs[i - 2]) +
                            " is followed by " + format_number(pairs[i]) + ")");
        return piecewise_spectrum(p, std::move(pairs), type);
    }
    expect_single(p, p.strings.size(), 1);
    const std::string &name = p.strings[0];
    if (SpectrumPtr named = get_named_spectrum(name)) return named;
    if (!file_access_)
        fail(p, "\"" + name + "\" is not a named spectrum (and spectrum files are not read: file "
                "access is disabled)");
    std::vector<float> pairs;
    try {
        pairs = read_spectrum_file(file_path(p.name, name));
    } catch (const InputError &e) {
        fail(p, "\"" + name + "\" is not a named spectrum, and as a file: " + e.message());
    }
    return piecewise_spectrum(p, std::move(pairs), type);
}

std::string ParameterDictionary::file_path(const std::string &name, const std::string &file) const {
    if (!file_access_)
        throw InputError(location(name), "\"" + file + "\" is not read: file access is disabled");
    std::filesystem::path path(file);
    if (path.is_relative() && !base_directory_.empty())
        path = std::filesystem::path(base_directory_) / path;
    return path.string();
}

SpectrumPtr ParameterDictionary::get_one_spectrum(const std::string &name, SpectrumPtr def,
                                                  SpectrumType type) const {
    const ParsedParameter *p = find_typed(name, {"rgb", "spectrum", "blackbody", "float"});
    return p ? spectrum_from(*p, type) : def;
}

FloatTexturePtr ParameterDictionary::get_float_texture(const std::string &name, float def,
                                                       const NamedTextures &textures) const {
    FloatTexturePtr t = get_float_texture_or_null(name, textures);
    return t ? t : std::make_shared<ConstantFloatTexture>(def);
}

FloatTexturePtr ParameterDictionary::get_float_texture_or_null(
    const std::string &name, const NamedTextures &textures) const {
    const ParsedParameter *p = find_typed(name, {"texture", "float", "integer"});
    if (!p) return nullptr;
    if (p->type != "texture") {
        expect_single(*p, p->numbers.size(), 1);
        return std::make_shared<ConstantFloatTexture>(float(p->numbers[0]));
    }
    expect_single(*p, p->strings.size(), 1);
    const std::string &tex = p->strings[0];
    if (auto it = textures.float_textures.find(tex); it != textures.float_textures.end())
        return it->second;
    bool is_spectrum = textures.albedo.count(tex) || textures.unbounded.count(tex) ||
                       textures.illuminant.count(tex);
    fail(*p, "no float texture named \"" + tex + "\"" +
                 (is_spectrum ? " (\"" + tex + "\" is a spectrum texture)" : ""));
}

SpectrumTexturePtr ParameterDictionary::get_spectrum_texture(const std::string &name,
                                                             SpectrumPtr def, SpectrumType type,
                                                             const NamedTextures &textures) const {
    SpectrumTexturePtr t = get_spectrum_texture_or_null(name, type, textures);
    if (t || !def) return t;
    return std::make_shared<ConstantSpectrumTexture>(std::move(def));
}

SpectrumTexturePtr ParameterDictionary::get_spectrum_texture_or_null(
    const std::string &name, SpectrumType type, const NamedTextures &textures) const {
    const ParsedParameter *p =
        find_typed(name, {"texture", "rgb", "spectrum", "blackbody", "float"});
    if (!p) return nullptr;
    if (p->type != "texture") return std::make_shared<ConstantSpectrumTexture>(spectrum_from(*p, type));
    expect_single(*p, p->strings.size(), 1);
    const std::string &tex = p->strings[0];
    const auto &map = textures.spectrum(type);
    if (auto it = map.find(tex); it != map.end()) return it->second;
    bool is_float = textures.float_textures.count(tex) != 0;
    fail(*p, "no spectrum texture named \"" + tex + "\"" +
                 (is_float ? " (\"" + tex + "\" is a float texture)" : ""));
}

float ParameterDictionary::get_one_float_checked(const std::string &name, float def, float lo,
                                                 float hi) const {
    const ParsedParameter *p = find_typed(name, {"float", "integer"});
    if (!p) return def;
    expect_single(*p, p->numbers.size(), 1);
    float v = float(p->numbers[0]);
    if (!(v >= lo && v <= hi))
        fail(*p, "value " + format_number(v) + " is outside the allowed range [" +
                     format_number(lo) + ", " + format_number(hi) + "]");
    return v;
}

void ParameterDictionary::add_lookups_of(const ParameterDictionary &copy) const {
    for (size_t i = 0; i < params_.size() && i < copy.params_.size(); ++i)
        if (copy.params_[i].looked_up && copy.params_[i].name == params_[i].name) params_[i].looked_up = true;
}

void ParameterDictionary::report_unused() const {
    for (size_t i = 0; i < params_.size(); ++i) {
        const ParsedParameter &p = params_[i];
        if (p.looked_up || p.is_attribute_default) continue;
        // An earlier parameter of the same name that was read shadows this one.
        bool shadowed = std::any_of(params_.begin(), params_.begin() + i,
                                    [&](const ParsedParameter &q) { return q.name == p.name; });
        if (!shadowed) warning(p.loc, "unused parameter \"" + p.declaration() + "\"");
    }
}

} // namespace caustica
