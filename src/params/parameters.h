// Typed parameter lists of scene directives ("float radius" 2, "rgb reflectance" [.5 .5 .5])
// and the dictionary that scene-object constructors read them through. Semantics follow
// pbrt-v4's ParameterDictionary; see the notes on ParameterDictionary for where we differ.
#pragma once

#include "core/error.h"
#include "core/vecmath.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

#include <string>
#include <vector>

namespace caustica {

class RGBColorSpace;

// One "type name" declaration with its values, as written in the scene file. Numeric types
// (float, integer, point*, vector*, normal3, rgb, blackbody and numeric spectra) keep their
// values in `numbers`; string, texture and named/file spectra in `strings`; bool in `bools`.
struct ParsedParameter {
    std::string type;  // canonical type name: "point" is stored as "point3", etc.
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    std::vector<bool> bools;
    SourceLocation loc;
    // Set for defaults from an `Attribute` directive: the colour space in effect there (RGB values
    // are interpreted in it), and a default that an object does not use is not worth a warning.
    const RGBColorSpace *color_space = nullptr;
    bool is_attribute_default = false;
    // Set when some create_* function read the parameter (for report_unused()).
    mutable bool looked_up = false;

    // "float radius" etc., for messages.
    std::string declaration() const { return type + " " + name; }
};

// Maps a type as written ("point", "normal", ...) to its canonical name; empty if unknown.
std::string canonical_parameter_type(const std::string &written);
// Checks that the values suit the declared type (kind and count); throws InputError at the
// parameter. The parser calls this for every parameter it reads.
void validate_parameter(const ParsedParameter &p);

// Read access to one directive's parameters.
//
// Lookups find the first parameter with the requested name. Entity parameters come before
// `Attribute` defaults, so an object's own value wins. A parameter of a type the lookup cannot
// use is an InputError at the parameter, with one exception that keeps pbrt's probing idiom
// working: the "material property" types float, texture, rgb, spectrum and blackbody are
// interchangeable enough that a lookup of one of them that meets another of them reports the
// parameter as absent (a dielectric reads "eta" first as floats, then as a spectrum). Two
// extensions over pbrt-v4: spectrum lookups accept a "float" (a constant spectrum), and float
// lookups accept an "integer".
class ParameterDictionary {
  public:
    ParameterDictionary();
    ParameterDictionary(std::vector<ParsedParameter> params, SourceLocation directive_loc,
                        const RGBColorSpace *color_space, std::string base_directory);
    // Appends `Attribute` defaults after the entity's own parameters.
    void add_defaults(const std::vector<ParsedParameter> &defaults);

    float get_one_float(const std::string &name, float def) const;
    int get_one_int(const std::string &name, int def) const;
    bool get_one_bool(const std::string &name, bool def) const;
    std::string get_one_string(const std::string &name, const std::string &def) const;
    Vec3f get_one_point3(const std::string &name, Vec3f def) const;
    Vec3f get_one_vector3(const std::string &name, Vec3f def) const;
    Vec3f get_one_normal(const std::string &name, Vec3f def) const;
    Vec2f get_one_point2(const std::string &name, Vec2f def) const;
    std::vector<float> get_float_array(const std::string &name) const;
    std::vector<int> get_int_array(const std::string &name) const;
    std::vector<Vec3f> get_point3_array(const std::string &name) const;
    std::vector<Vec3f> get_normal_array(const std::string &name) const;
    std::vector<Vec3f> get_vector3_array(const std::string &name) const;
    std::vector<Vec2f> get_point2_array(const std::string &name) const;
    std::vector<std::string> get_string_array(const std::string &name) const;
    // An "rgb" parameter's values, three at a time, as written (not checked for sign).
    std::vector<Vec3f> get_rgb_array(const std::string &name) const;
    // "rgb", "spectrum" (constant value, named e.g. "glass-BK7"/"metal-Cu-eta", inline
    // lambda-value pairs, or a file name), "blackbody" -> a Spectrum of the given type.
    SpectrumPtr get_one_spectrum(const std::string &name, SpectrumPtr def, SpectrumType type) const;
    // "texture name" reference, or a constant value of any of the forms above.
    FloatTexturePtr get_float_texture(const std::string &name, float def,
                                      const NamedTextures &textures) const;
    FloatTexturePtr get_float_texture_or_null(const std::string &name,
                                              const NamedTextures &textures) const;
    SpectrumTexturePtr get_spectrum_texture(const std::string &name, SpectrumPtr def,
                                            SpectrumType type, const NamedTextures &textures) const;
    SpectrumTexturePtr get_spectrum_texture_or_null(const std::string &name, SpectrumType type,
                                                    const NamedTextures &textures) const;
    bool has(const std::string &name) const;
    // Location of a parameter (for error messages); the directive's location if absent.
    SourceLocation location(const std::string &name) const;
    const SourceLocation &directive_location() const { return directive_loc_; }
    // Throws InputError at the parameter if value is outside [lo, hi].
    float get_one_float_checked(const std::string &name, float def, float lo, float hi) const;
    // Warn about parameters no create_* function looked at (pbrt would error; we warn, naming it).
    void report_unused() const;
    // Counts as read what `copy` (a copy of this dictionary, read by someone else) read.
    void add_lookups_of(const ParameterDictionary &copy) const;
    const std::string &base_directory() const { return base_directory_; }
    // The file that parameter `name` names (`file`, as written), resolved against the scene
    // file's directory when relative. Throws InputError at the parameter when file access is
    // disabled.
    std::string file_path(const std::string &name, const std::string &file) const;
    // Scenes parsed from untrusted text in memory (ParseOptions::file_access, the fuzzer) must
    // not make the renderer read files: every file a parameter names is then an InputError.
    void disable_file_access() { file_access_ = false; }

    // Colour space for RGB values (pbrt's `ColorSpace` directive in effect at the directive).
    const RGBColorSpace &color_space() const;
    const std::vector<ParsedParameter> &parameters() const { return params_; }

  private:
    // The first parameter called `name`, or null.
    const ParsedParameter *find(const std::string &name) const;
    // Like find(), but only a parameter whose type is in `types`; see the class comment for
    // which mismatches are errors and which read as "absent".
    const ParsedParameter *find_typed(const std::string &name,
                                      std::initializer_list<const char *> types) const;
    SpectrumPtr spectrum_from(const ParsedParameter &p, SpectrumType type) const;

    std::vector<ParsedParameter> params_;
    SourceLocation directive_loc_;
    const RGBColorSpace *color_space_ = nullptr;
    std::string base_directory_;
    bool file_access_ = true;
};

} // namespace caustica
