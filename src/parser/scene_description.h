// What a pbrt-v4 scene file says, before any scene object is built: the parser's output and
// the scene builder's input. Mirrors pbrt-v4's BasicScene entities.
//
// Transforms: pbrt applies each transform directive on the right of the current transformation
// matrix (CTM), so `Translate` then `Scale` scales first. "render" space is world space here:
// render_from_object is the CTM when the entity was declared (after WorldBegin the CTM is
// world-from-object); the builder may re-base everything into a camera-centred render space.
// Shapes inside ObjectBegin/ObjectEnd keep their full CTM too; an instance use places them with
// render_from_instance * shape.render_from_object (as pbrt-v4 does).
#pragma once

#include "core/animated_transform.h"
#include "core/error.h"
#include "core/transform.h"
#include "params/parameters.h"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace caustica {

class RGBColorSpace;

struct SceneEntity {
    std::string type;  // e.g. "perspective", "sphere", "diffuse"
    ParameterDictionary params;
    SourceLocation loc;  // of the directive
};

struct TransformedEntity : SceneEntity {
    Transform render_from_object;
};

struct CameraEntity : SceneEntity {
    Transform world_from_camera;  // inverse of the CTM at the Camera directive
    std::optional<Transform> world_from_camera_end; // the same at the end time, when it moves
    std::string medium;           // the outside medium of the MediumInterface in effect
};

struct ShapeEntity : SceneEntity {
    Transform render_from_object;  // at the start of the TransformTimes
    // Where the shape is at the end of the TransformTimes, when it moves (motion blur).
    std::optional<Transform> render_from_object_end;
    bool reverse_orientation = false;
    int material_index = -1;    // into SceneDescription::materials, or
    std::string material_name;  // a NamedMaterial (when non-empty); neither: pbrt's default "diffuse"
    int area_light_index = -1;  // into SceneDescription::area_lights
    std::string inside_medium, outside_medium;
};

struct LightEntity : TransformedEntity {
    std::string medium;  // the outside medium in effect
};

struct TextureEntity : TransformedEntity {
    std::string name;
    std::string texture_class;  // "float" or "spectrum"; `type` holds e.g. "imagemap"
};

struct MediumEntity : TransformedEntity {
    std::string name;  // `type` comes from the medium's "string type" parameter
};

struct InstanceDefinition {
    std::string name;
    std::vector<ShapeEntity> shapes;
    SourceLocation loc;
};

struct InstanceUse {
    std::string name;
    AnimatedTransform render_from_instance;
    SourceLocation loc;
};

struct SceneDescription {
    SceneEntity film, sampler, integrator, filter, accelerator;  // type empty if not given (pbrt defaults apply later)
    CameraEntity camera;
    bool has_camera = false;
    // The film's colour space: the ColorSpace in effect at the Film directive, or at WorldBegin
    // when there is no Film directive. sRGB unless a ColorSpace directive says otherwise.
    const RGBColorSpace *color_space = nullptr;
    std::vector<SceneEntity> materials;                                // anonymous Material directives
    std::vector<std::pair<std::string, SceneEntity>> named_materials;  // declaration order; type from "string type"
    std::vector<TextureEntity> textures;                               // declaration order
    std::vector<LightEntity> lights;
    std::vector<SceneEntity> area_lights;
    std::vector<ShapeEntity> shapes;
    std::vector<MediumEntity> media;
    std::vector<InstanceDefinition> instances;
    std::vector<InstanceUse> instance_uses;
    TransformTimes transform_times; // when moving shapes and instances are at their start and end
    // Option directives that were recognised, as typed parameters under pbrt's normalised names
    // (lower case, no '-' or '_'): "bool disablepixeljitter", "bool disabletexturefiltering",
    // "bool disablewavelengthjitter", "bool forcediffuse", "bool pixelstats", "bool wavefront",
    // "integer seed", "float displacementedgescale", "string msereferenceimage",
    // "string msereferenceout", "string rendercoordsys". A later Option replaces an earlier one
    // of the same name.
    ParameterDictionary options;
    std::vector<std::string> warnings;  // also printed through caustica::warning
};

// How parsing may reach files beyond the text it is given.
struct ParseOptions {
    // When false, nothing is read from disk: Include and Import find their files only in
    // `files`, and every parameter that names a file to read (spectrum files, "plymesh",
    // image "filename"s) is an InputError when used (ParameterDictionary::file_path). For text
    // from untrusted sources, such as the fuzzer's.
    bool file_access = true;
    // In-memory files for Include/Import when file access is off, by path: a relative name in
    // an Include resolves against the including file's name, as on disk ("a/b.pbrt" including
    // "c.pbrt" reads "a/c.pbrt"), and paths are compared after lexical normalisation.
    std::map<std::string, std::string> files;
};

// Parse a scene file and everything it includes. Throws InputError at the offending token's
// file:line:column for malformed input.
SceneDescription parse_scene_file(const std::string &path);
// Parse scene text; relative Include and parameter file names resolve against the current
// directory. `name` appears as the file in locations.
SceneDescription parse_scene_string(const std::string &text, const std::string &name = "<string>");
SceneDescription parse_scene_string(const std::string &text, const std::string &name,
                                    const ParseOptions &options);

} // namespace caustica
