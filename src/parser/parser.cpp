// The pbrt-v4 scene format (https://pbrt.org/fileformat-v4): a sequence of directives, each a
// word followed by fixed arguments and, for most, a list of typed parameters. This parser keeps
// pbrt-v4's graphics-state semantics (BasicSceneBuilder) and reports every malformed input as an
// InputError at the token responsible.
#include "parser/scene_description.h"

#include "core/file_contents.h"
#include "params/number_text.h"
#include "parser/tokenizer.h"
#include "spectral/color_space.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace caustica {

namespace {

namespace fs = std::filesystem;

// Include/Import nesting beyond this is almost certainly a runaway; real scenes use a few levels.
constexpr int MaxIncludeDepth = 32;

bool is_finite(const Matrix4 &m) {
    for (const auto &row : m.m)
        for (float v : row)
            if (!std::isfinite(v)) return false;
    return true;
}

// The state that AttributeBegin saves and AttributeEnd restores (pbrt-v4's GraphicsState).
struct GraphicsState {
    // The current transformation at the start and at the end of the TransformTimes (motion
    // blur); ActiveTransform chooses which of the two the transform directives change.
    Transform ctm, ctm_end;
    bool start_transform_active = true, end_transform_active = true;
    bool reverse_orientation = false;
    int material_index = -1;
    std::string material_name;
    std::optional<SceneEntity> area_light;
    std::string inside_medium, outside_medium;
    const RGBColorSpace *color_space = nullptr;
    std::vector<ParsedParameter> shape_defaults, light_defaults, material_defaults,
        medium_defaults, texture_defaults;
};

struct PushedState {
    GraphicsState state;
    enum class Kind { Attribute, Transform, Object } kind;
    SourceLocation loc;
};

// A file being read. Import differs from Include in that the importing file's graphics state
// is restored when the imported file ends (pbrt-v4 parses imports with a copy of the state).
struct Source {
    std::unique_ptr<Tokenizer> tokenizer;
    // For cycle detection: the canonical path on disk, the normalised name of an in-memory
    // file, or empty for text given as a string that no Include can name.
    fs::path canonical_path;
    fs::path directory;       // relative Includes in this file resolve against it first
    std::optional<GraphicsState> state_after_import;
    size_t pushed_depth_at_import = 0;
};

struct FinishedImport {
    GraphicsState state;  // the importer's, to restore
    size_t pushed_depth;  // AttributeBegin depth at the Import
};

struct NameReference {
    std::string name;
    SourceLocation loc;
};

class SceneParser {
  public:
    SceneParser(SceneDescription &desc, std::string base_directory, const ParseOptions &options)
        : desc_(desc), base_directory_(std::move(base_directory)),
          file_access_(options.file_access) {
        state_.color_space = &RGBColorSpace::srgb();
        desc_.color_space = state_.color_space;
        for (const auto &[name, text] : options.files)
            memory_files_[fs::path(name).lexically_normal()] = &text;
    }

    void push_text(std::string text, const std::string &name, fs::path directory) {
        Source s;
        s.tokenizer = std::make_unique<Tokenizer>(std::move(text), intern(name));
        s.directory = std::move(directory);
        // Without file access, names are paths into the in-memory files: an Include of the
        // text's own name is a cycle.
        if (!file_access_) s.canonical_path = fs::path(name).lexically_normal();
        sources_.push_back(std::move(s));
    }

    void push_file(const fs::path &path, const SourceLocation &include_loc) {
        std::string why;
        std::optional<std::string> text = read_file_contents(path, &why);
        if (!text) {
            if (include_loc.file.empty())
                throw InputError("cannot read scene file \"" + path.string() + "\": " + why);
            throw InputError(include_loc, "cannot read \"" + path.string() + "\": " + why);
        }
        Source s;
        s.tokenizer = std::make_unique<Tokenizer>(std::move(*text), intern(path.string()));
        std::error_code ec;
        s.canonical_path = fs::weakly_canonical(path, ec);
        if (ec) s.canonical_path = fs::absolute(path);
        s.directory = path.parent_path();
        sources_.push_back(std::move(s));
    }

    void parse() {
        while (true) {
            Token tok = next();
            if (!finished_imports_.empty()) apply_finished_imports();
            if (tok.kind == Token::Kind::End) break;
            if (tok.kind != Token::Kind::Word) {
                if (tok.kind == Token::Kind::String)
                    error(tok, "unexpected string " + tok.describe() + " where a directive was expected");
                error(tok, "unexpected " + tok.describe() + " where a directive was expected");
            }
            auto it = handlers().find(tok.text);
            if (it == handlers().end()) {
                if (tok.text == "WorldEnd")
                    error(tok, "unknown directive 'WorldEnd' (pbrt-v4 has no WorldEnd: the world "
                               "block runs to the end of the input; delete it)");
                double v;
                if (parse_number_text(tok.text, &v) != NumberTextStatus::NotANumber)
                    error(tok, "unexpected number " + tok.describe() +
                                   " (too many arguments for the directive before it?)");
                error(tok, "unknown directive " + tok.describe());
            }
            (this->*(it->second))(tok);
        }
        finish();
    }

  private:
    using Handler = void (SceneParser::*)(const Token &);

    static const std::unordered_map<std::string, Handler> &handlers() {
        static const std::unordered_map<std::string, Handler> h = {
            {"Accelerator", &SceneParser::accelerator},
            {"ActiveTransform", &SceneParser::active_transform},
            {"AreaLightSource", &SceneParser::area_light_source},
            {"Attribute", &SceneParser::attribute},
            {"AttributeBegin", &SceneParser::attribute_begin},
            {"AttributeEnd", &SceneParser::attribute_end},
            {"Camera", &SceneParser::camera},
            {"ColorSpace", &SceneParser::color_space},
            {"ConcatTransform", &SceneParser::concat_transform},
            {"CoordinateSystem", &SceneParser::coordinate_system},
            {"CoordSysTransform", &SceneParser::coord_sys_transform},
            {"Film", &SceneParser::film},
            {"Identity", &SceneParser::identity},
            {"Import", &SceneParser::import},
            {"Include", &SceneParser::include},
            {"Integrator", &SceneParser::integrator},
            {"LightSource", &SceneParser::light_source},
            {"LookAt", &SceneParser::look_at},
            {"MakeNamedMaterial", &SceneParser::make_named_material},
            {"MakeNamedMedium", &SceneParser::make_named_medium},
            {"Material", &SceneParser::material},
            {"MediumInterface", &SceneParser::medium_interface},
            {"NamedMaterial", &SceneParser::named_material},
            {"ObjectBegin", &SceneParser::object_begin},
            {"ObjectEnd", &SceneParser::object_end},
            {"ObjectInstance", &SceneParser::object_instance},
            {"Option", &SceneParser::option},
            {"PixelFilter", &SceneParser::pixel_filter},
            {"ReverseOrientation", &SceneParser::reverse_orientation},
            {"Rotate", &SceneParser::rotate},
            {"Sampler", &SceneParser::sampler},
            {"Scale", &SceneParser::scale},
            {"Shape", &SceneParser::shape},
            {"Texture", &SceneParser::texture},
            {"Transform", &SceneParser::transform},
            {"TransformBegin", &SceneParser::transform_begin},
            {"TransformEnd", &SceneParser::attribute_end},
            {"TransformTimes", &SceneParser::transform_times},
            {"Translate", &SceneParser::translate},
            {"WorldBegin", &SceneParser::world_begin},
        };
        return h;
    }

    // ---- Tokens --------------------------------------------------------------------------

    const std::string *intern(const std::string &name) {
        file_names_.push_back(std::make_unique<std::string>(name));
        return file_names_.back().get();
    }

    Token next() {
        if (pending_) return std::exchange(pending_, std::nullopt).value();
        while (!sources_.empty()) {
            Token tok = sources_.back().tokenizer->next();
            if (tok.kind != Token::Kind::End) return tok;
            end_token_ = tok;
            end_of_source();
        }
        return end_token_;
    }

    void unget(Token tok) { pending_ = std::move(tok); }

    // The next token, left in place (for error locations of arguments read afterwards).
    Token peek() {
        Token tok = next();
        unget(tok);
        return tok;
    }

    void end_of_source() {
        Source &s = sources_.back();
        if (s.state_after_import)
            finished_imports_.push_back({std::move(*s.state_after_import), s.pushed_depth_at_import});
        sources_.pop_back();
    }

    // Restores the importer's graphics state after an imported file. This waits until the
    // directive being parsed is complete: the look-ahead for more of its parameters is what
    // reaches the end of the file, and the directive must still see the imported file's state.
    void apply_finished_imports() {
        for (FinishedImport &f : finished_imports_) {
            if (pushed_.size() > f.pushed_depth)
                throw InputError(pushed_.back().loc,
                                 "AttributeBegin in an imported file is not closed in that file");
            state_ = std::move(f.state);
        }
        finished_imports_.clear();
        // The floor of the innermost import still being read applies again.
        attribute_floor_ = 0;
        for (const Source &src : sources_)
            if (src.state_after_import) attribute_floor_ = src.pushed_depth_at_import;
    }

    [[noreturn]] static void error(const Token &tok, const std::string &message) {
        throw InputError(tok.location(), message);
    }

    void warn(const SourceLocation &loc, const std::string &message) {
        desc_.warnings.push_back(loc.to_string() + ": warning: " + message);
        warning(loc, message);
    }

    static bool is_directive_word(const Token &tok) {
        return tok.kind == Token::Kind::Word && handlers().count(tok.text) != 0;
    }

    // ---- Directive arguments ---------------------------------------------------------------

    std::string string_argument(const Token &directive, const char *what) {
        Token t = next();
        if (t.kind == Token::Kind::String) return t.text;
        if (t.kind == Token::Kind::End || is_directive_word(t))
            error(directive, directive.text + ": missing " + what + " (a quoted string)");
        error(t, directive.text + ": expected " + what + " as a quoted string, found " +
                     t.describe());
    }

    double number_from(const Token &t) {
        double v = 0;
        switch (parse_number_text(t.text, &v)) {
        case NumberTextStatus::Ok:
            // Every number ends up a float: beyond this it would become infinite.
            if (std::abs(v) > double(std::numeric_limits<float>::max()))
                error(t, "number " + t.describe() + " is too large for single precision");
            return v;
        case NumberTextStatus::NotFinite: error(t, "non-finite number " + t.describe());
        case NumberTextStatus::NotANumber: break;
        }
        error(t, "expected a number, found " + t.describe());
    }

    // `count` numbers following `directive`.
    std::vector<double> number_arguments(const Token &directive, int count) {
        std::vector<double> v;
        for (int i = 0; i < count; ++i) {
            Token t = next();
            if (t.kind == Token::Kind::End || is_directive_word(t))
                error(directive, directive.text + " expects " + std::to_string(count) +
                                     " numbers, found " + std::to_string(i));
            if (t.kind != Token::Kind::Word)
                error(t, directive.text + ": expected a number, found " + t.describe());
            v.push_back(number_from(t));
        }
        return v;
    }

    // "[ n1 ... n16 ]" for Transform and ConcatTransform.
    std::vector<double> bracketed_matrix(const Token &directive) {
        Token open = next();
        if (open.kind != Token::Kind::OpenBracket)
            error(open, directive.text + ": expected '[' before the 16 matrix values, found " +
                            open.describe());
        std::vector<double> v;
        while (true) {
            Token t = next();
            if (t.kind == Token::Kind::CloseBracket) break;
            if (t.kind == Token::Kind::End)
                error(open, "unbalanced brackets: this '[' is never closed");
            if (t.kind != Token::Kind::Word)
                error(t, directive.text + ": expected a number, found " + t.describe());
            v.push_back(number_from(t));
        }
        if (v.size() != 16)
            error(directive, directive.text + " expects 16 numbers, found " +
                                 std::to_string(v.size()));
        return v;
    }

    // ---- Parameter lists ---------------------------------------------------------------------

    // What tokens a parameter type takes as values.
    enum class ValueKind { Bool, String, Spectrum, Number, Integer };
    static ValueKind value_kind(const std::string &type) {
        if (type == "bool") return ValueKind::Bool;
        if (type == "string" || type == "texture") return ValueKind::String;
        if (type == "spectrum") return ValueKind::Spectrum;
        if (type == "integer") return ValueKind::Integer;
        return ValueKind::Number;
    }

    void add_value(ParsedParameter &p, ValueKind kind, const Token &t) {
        switch (kind) {
        case ValueKind::Bool:
            if (t.text == "true" || t.text == "false") {
                p.bools.push_back(t.text == "true");
                return;
            }
            error(t, "parameter \"" + p.declaration() + "\": expected true or false, found " +
                         t.describe());
        case ValueKind::String:
            if (t.kind != Token::Kind::String)
                error(t, "parameter \"" + p.declaration() + "\": expected a quoted string, found " +
                             t.describe());
            p.strings.push_back(t.text);
            return;
        case ValueKind::Spectrum:
            if (t.kind == Token::Kind::String ? !p.numbers.empty() : !p.strings.empty())
                error(t, "parameter \"" + p.declaration() +
                             "\": a spectrum is either numbers or one name, not both");
            if (t.kind == Token::Kind::String) {
                p.strings.push_back(t.text);
                return;
            }
            break;
        case ValueKind::Number:
        case ValueKind::Integer:
            break;
        }
        if (t.kind != Token::Kind::Word)
            error(t, "parameter \"" + p.declaration() + "\": expected a number, found " +
                         t.describe());
        double v = number_from(t);
        if (kind == ValueKind::Integer && (v != std::floor(v) || std::abs(v) > 2147483647.0))
            error(t, "parameter \"" + p.declaration() + "\": " + t.describe() +
                         " is not a 32-bit integer");
        p.numbers.push_back(v);
    }

    // Typed parameters following a directive's fixed arguments; stops before the first token
    // that is not a quoted declaration.
    std::vector<ParsedParameter> parameter_list() {
        std::vector<ParsedParameter> params;
        while (true) {
            Token decl = next();
            if (decl.kind != Token::Kind::String) {
                unget(std::move(decl));
                return params;
            }
            ParsedParameter p;
            p.loc = decl.location();
            std::istringstream words(decl.text);
            std::string type, name, extra;
            words >> type >> name >> extra;
            if (type.empty()) error(decl, "empty parameter declaration \"\"");
            std::string canonical = canonical_parameter_type(type);
            if (name.empty()) {
                if (!canonical.empty())
                    error(decl, "parameter declaration " + decl.describe() + " has no name");
                error(decl, "parameter declaration " + decl.describe() +
                                " must be \"type name\" (e.g. \"float radius\")");
            }
            if (!extra.empty())
                error(decl, "parameter declaration " + decl.describe() +
                                " has more than a type and a name");
            if (canonical.empty())
                error(decl, "unknown parameter type \"" + type + "\"" +
                                (type == "color" ? " (pbrt-v4 calls it \"rgb\")" : ""));
            p.type = canonical;
            p.name = name;

            ValueKind kind = value_kind(p.type);
            Token value = next();
            if (value.kind == Token::Kind::OpenBracket) {
                while (true) {
                    Token t = next();
                    if (t.kind == Token::Kind::CloseBracket) break;
                    if (t.kind == Token::Kind::End)
                        error(value, "unbalanced brackets: this '[' is never closed");
                    if (t.kind == Token::Kind::OpenBracket)
                        error(t, "unexpected '[' inside the values of \"" + p.declaration() + "\"");
                    add_value(p, kind, t);
                }
            } else if (value.kind == Token::Kind::End || is_directive_word(value)) {
                error(decl, "parameter \"" + p.declaration() + "\" has no value");
            } else if (value.kind == Token::Kind::CloseBracket) {
                error(value, "unbalanced brackets: unexpected ']'");
            } else {
                add_value(p, kind, value);
            }
            validate_parameter(p);
            params.push_back(std::move(p));
        }
    }

    ParameterDictionary dictionary(std::vector<ParsedParameter> params, const Token &directive,
                                   const std::vector<ParsedParameter> *defaults = nullptr) {
        ParameterDictionary d(std::move(params), directive.location(), state_.color_space,
                              base_directory_);
        if (defaults) d.add_defaults(*defaults);
        if (!file_access_) d.disable_file_access();
        return d;
    }

    // "Directive "type" params..." as a SceneEntity.
    SceneEntity entity(const Token &directive, const char *what,
                       const std::vector<ParsedParameter> *defaults = nullptr) {
        std::string type = string_argument(directive, what);
        return {type, dictionary(parameter_list(), directive, defaults), directive.location()};
    }

    // ---- Block structure ----------------------------------------------------------------------

    void require_options_block(const Token &directive) {
        if (in_world_)
            error(directive, directive.text + " is not allowed after WorldBegin (it sets a "
                                              "rendering option)");
    }

    void require_world_block(const Token &directive) {
        if (!in_world_)
            error(directive, directive.text + " is only allowed after WorldBegin");
    }

    // Transform directive `d` applies `t` on the right of the active CTMs.
    void apply(const Token &d, const Transform &t) {
        if (state_.start_transform_active) set_checked(d, state_.ctm, state_.ctm * t);
        if (state_.end_transform_active) set_checked(d, state_.ctm_end, state_.ctm_end * t);
    }

    void set_ctm(const Token &d, const Transform &t) {
        if (state_.start_transform_active) set_checked(d, state_.ctm, t);
        if (state_.end_transform_active) set_checked(d, state_.ctm_end, t);
    }

    void set_checked(const Token &d, Transform &ctm, const Transform &t) {
        // Each transform may be finite while their product overflows single precision (Scale
        // 1e30 twice): its matrix would then hold infinities and turn every point it moves into
        // NaN. A product whose inverse overflows (Scale 1e-30 twice) collapses space instead,
        // as a Scale by zero does (see collapses()).
        if (!is_finite(t.matrix()))
            error(d, d.text + ": the current transformation is not finite in single precision "
                              "(its entries overflow)");
        ctm = t;
    }

    // pbrt-v4 accepts transformations that collapse space into a plane, a line or a point (a
    // Scale by zero, a singular ConcatTransform: exporters hide objects that way). Nothing
    // placed under one can be traced (rays need the inverse), so what needs the inverse is
    // refused where it is placed: shapes, instances and lights are left out with a warning
    // (pbrt-v4 gives them NaN inverses and draws nothing of its spheres and instances), the
    // camera, media and textures are errors.
    static bool collapses(const Transform &t) { return !is_finite(t.inverse_matrix()); }
    bool ctm_collapses() const { return collapses(state_.ctm) || collapses(state_.ctm_end); }
    static std::string collapse_reason() {
        return "the current transformation is not invertible (a Scale by zero, a singular matrix, or an "
               "inverse that overflows single precision)";
    }
    // Warns and returns true when the directive at d is to be left out.
    bool left_out_as_collapsed(const Token &d, const std::string &what) {
        if (!ctm_collapses()) return false;
        warn(d.location(), collapse_reason() + ": " + what + " is left out");
        return true;
    }
    void require_invertible_ctm(const Token &d) {
        if (ctm_collapses()) error(d, d.text + ": " + collapse_reason());
    }

    bool ctm_moves() const { return !(state_.ctm == state_.ctm_end); }

    // What pbrt-v4 does with a moving transform where it supports none: a warning, and the start.
    void warn_if_moving(const Token &d, const std::string &what) {
        if (ctm_moves())
            warn(d.location(), what + " cannot move (as in pbrt-v4): the start transform is used");
    }

    // ---- Directives ------------------------------------------------------------------------

    void accelerator(const Token &d) {
        SceneEntity e = entity(d, "accelerator type");
        require_options_block(d);
        desc_.accelerator = std::move(e);
    }

    void active_transform(const Token &d) {
        Token which = next();
        if (which.kind == Token::Kind::Word &&
            (which.text == "All" || which.text == "StartTime" || which.text == "EndTime")) {
            state_.start_transform_active = which.text != "EndTime";
            state_.end_transform_active = which.text != "StartTime";
            return;
        }
        error(which, "ActiveTransform: expected StartTime, EndTime or All, found " +
                         which.describe());
    }

    void area_light_source(const Token &d) {
        SceneEntity e = entity(d, "area light type", &state_.light_defaults);
        require_world_block(d);
        state_.area_light = std::move(e);
    }

    void attribute(const Token &d) {
        Token target = peek();
        std::string name = string_argument(d, "attribute target");
        std::vector<ParsedParameter> *defaults = nullptr;
        if (name == "shape") defaults = &state_.shape_defaults;
        else if (name == "light") defaults = &state_.light_defaults;
        else if (name == "material") defaults = &state_.material_defaults;
        else if (name == "medium") defaults = &state_.medium_defaults;
        else if (name == "texture") defaults = &state_.texture_defaults;
        else
            error(target, "Attribute: unknown target \"" + name +
                              "\" (expected \"shape\", \"light\", \"material\", \"medium\" or "
                              "\"texture\")");
        for (ParsedParameter &p : parameter_list()) {
            // RGB values keep the colour space in effect where the default was given.
            p.color_space = state_.color_space;
            defaults->push_back(std::move(p));
        }
    }

    void attribute_begin(const Token &d) {
        require_world_block(d);
        pushed_.push_back({state_, PushedState::Kind::Attribute, d.location()});
    }

    void transform_begin(const Token &d) {
        if (!warned_transform_begin_) {
            warned_transform_begin_ = true;
            warn(d.location(), "TransformBegin/TransformEnd are deprecated; they now act as "
                               "AttributeBegin/AttributeEnd (as in pbrt-v4)");
        }
        require_world_block(d);
        pushed_.push_back({state_, PushedState::Kind::Transform, d.location()});
    }

    void attribute_end(const Token &d) {
        require_world_block(d);
        if (pushed_.size() <= attribute_floor_)
            error(d, d.text + " without a matching " +
                         (d.text == "TransformEnd" ? "TransformBegin" : "AttributeBegin"));
        if (pushed_.back().kind == PushedState::Kind::Object)
            error(d, d.text + " inside the ObjectBegin at " + pushed_.back().loc.to_string() +
                         " (close it with ObjectEnd first)");
        state_ = std::move(pushed_.back().state);
        pushed_.pop_back();
    }

    void camera(const Token &d) {
        SceneEntity e = entity(d, "camera type");
        require_options_block(d);
        require_invertible_ctm(d);
        Transform world_from_camera = state_.ctm.inverse();
        named_frames_["camera"] = {world_from_camera, state_.ctm_end.inverse()};
        if (ctm_moves()) desc_.camera.world_from_camera_end = state_.ctm_end.inverse();
        desc_.camera.type = std::move(e.type);
        desc_.camera.params = std::move(e.params);
        desc_.camera.loc = e.loc;
        desc_.camera.world_from_camera = world_from_camera;
        desc_.camera.medium = state_.outside_medium;
        desc_.has_camera = true;
    }

    void color_space(const Token &d) {
        Token name_tok = peek();
        std::string name = string_argument(d, "colour space name");
        const RGBColorSpace *cs = RGBColorSpace::by_name(name);
        if (!cs)
            error(name_tok, "unknown colour space \"" + name +
                                "\" (known: \"srgb\", \"rec2020\", \"aces2065-1\", \"dci-p3\")");
        state_.color_space = cs;
    }

    void concat_transform(const Token &d) { apply(d, matrix_transform(d)); }
    void transform(const Token &d) { set_ctm(d, matrix_transform(d)); }

    Transform matrix_transform(const Token &d) {
        std::vector<double> v = bracketed_matrix(d);
        float values[16];
        for (int i = 0; i < 16; ++i) values[i] = float(v[i]);
        // pbrt lists the matrix column by column (m00 m10 m20 m30 m01 ...), so the translation
        // is in elements 12-14: reading it row-major gives the transpose.
        Matrix4 m = Matrix4::from_row_major(values).transposed();
        // A singular matrix is kept with a NaN inverse, as pbrt-v4 keeps it (see collapses()).
        std::optional<Matrix4> inv = inverse(m);
        if (inv) return Transform(m, *inv);
        Matrix4 nan;
        for (auto &row : nan.m)
            for (float &v : row) v = std::numeric_limits<float>::quiet_NaN();
        return Transform(m, nan);
    }

    void coordinate_system(const Token &d) {
        named_frames_[string_argument(d, "coordinate system name")] = {state_.ctm, state_.ctm_end};
    }

    void coord_sys_transform(const Token &d) {
        std::string name = string_argument(d, "coordinate system name");
        auto it = named_frames_.find(name);
        if (it == named_frames_.end()) {
            warn(d.location(), "CoordSysTransform: no coordinate system named \"" + name +
                                   "\"; the transform is unchanged");
            return;
        }
        state_.ctm = it->second.first;
        state_.ctm_end = it->second.second;
    }

    void film(const Token &d) {
        SceneEntity e = entity(d, "film type");
        require_options_block(d);
        desc_.film = std::move(e);
        film_color_space_ = state_.color_space;
    }

    void identity(const Token &d) { set_ctm(d, Transform()); }

    void include(const Token &d) { include_file(d, false); }

    void import(const Token &d) {
        require_world_block(d);
        include_file(d, true);
    }

    void include_file(const Token &d, bool is_import) {
        Token name_tok = peek();
        std::string name = string_argument(d, "file name");
        if (!file_access_) {
            include_memory_file(d, name_tok, name, is_import);
            return;
        }
        fs::path path(name);
        if (path.is_relative()) {
            // Relative to the including file; pbrt-v4 resolves against the main scene file's
            // directory, which we fall back to so that its scenes keep working.
            fs::path near = sources_.back().directory / path;
            fs::path from_base = fs::path(base_directory_) / path;
            std::error_code ec;
            path = (fs::exists(near, ec) || !fs::exists(from_base, ec)) ? near : from_base;
        }
        std::error_code ec;
        if (!fs::is_regular_file(path, ec))
            error(name_tok, d.text + ": cannot open \"" + name + "\" (looked for " +
                                path.string() + ")");
        fs::path canonical = fs::weakly_canonical(path, ec);
        check_nesting(d, name_tok, name, canonical);
        std::optional<GraphicsState> saved;
        if (is_import) saved = state_;
        SceneWarningOrder::file_included(name_tok.location(), path.string());
        push_file(path, name_tok.location());
        if (is_import) start_import(std::move(saved));
    }

    // Include/Import without file access: the file comes from ParseOptions::files.
    void include_memory_file(const Token &d, const Token &name_tok, const std::string &name,
                             bool is_import) {
        fs::path path = (sources_.back().directory / fs::path(name)).lexically_normal();
        // The main text is no in-memory file, but naming it is a cycle all the same.
        check_nesting(d, name_tok, name, path);
        auto it = memory_files_.find(path);
        if (it == memory_files_.end())
            error(name_tok, d.text + ": cannot open \"" + name + "\" (file access is disabled and "
                                     "no in-memory file is called " + path.string() + ")");
        std::optional<GraphicsState> saved;
        if (is_import) saved = state_;
        SceneWarningOrder::file_included(name_tok.location(), path.string());
        push_text(*it->second, path.string(), path.parent_path());
        if (is_import) start_import(std::move(saved));
    }

    void check_nesting(const Token &d, const Token &name_tok, const std::string &name,
                       const fs::path &canonical) {
        for (const Source &s : sources_)
            if (!s.canonical_path.empty() && s.canonical_path == canonical)
                error(name_tok, d.text + " cycle: \"" + name + "\" is already being read");
        if (int(sources_.size()) >= MaxIncludeDepth)
            error(name_tok, d.text + ": files nested more than " +
                                std::to_string(MaxIncludeDepth) + " levels deep");
    }

    // The file just pushed is imported: the importer's state comes back when it ends.
    void start_import(std::optional<GraphicsState> saved) {
        Source &s = sources_.back();
        s.state_after_import = std::move(saved);
        s.pushed_depth_at_import = pushed_.size();
        attribute_floor_ = pushed_.size();
    }

    void integrator(const Token &d) {
        SceneEntity e = entity(d, "integrator type");
        require_options_block(d);
        desc_.integrator = std::move(e);
    }

    void light_source(const Token &d) {
        SceneEntity e = entity(d, "light type", &state_.light_defaults);
        require_world_block(d);
        LightEntity light;
        static_cast<SceneEntity &>(light) = std::move(e);
        if (left_out_as_collapsed(d, "the light")) return;
        warn_if_moving(d, "a light");
        light.render_from_object = state_.ctm;
        light.medium = state_.outside_medium;
        desc_.lights.push_back(std::move(light));
    }

    void look_at(const Token &d) {
        std::vector<double> v = number_arguments(d, 9);
        Vec3f eye{float(v[0]), float(v[1]), float(v[2])};
        Vec3f target{float(v[3]), float(v[4]), float(v[5])};
        Vec3f up{float(v[6]), float(v[7]), float(v[8])};
        try {
            apply(d, Transform::look_at(eye, target, up));
        } catch (const std::invalid_argument &e) {
            error(d, e.what());
        }
    }

    void make_named_material(const Token &d) {
        SceneEntity e = entity(d, "material name", &state_.material_defaults);
        require_world_block(d);
        std::string name = std::move(e.type);
        e.type = e.params.get_one_string("type", "");
        if (e.type.empty())
            error(d, "MakeNamedMaterial \"" + name + "\": missing \"string type\" parameter");
        for (const auto &[existing, entity] : desc_.named_materials)
            if (existing == name)
                error(d, "named material \"" + name + "\" redefined (first defined at " +
                             entity.loc.to_string() + ")");
        desc_.named_materials.emplace_back(std::move(name), std::move(e));
    }

    void make_named_medium(const Token &d) {
        SceneEntity e = entity(d, "medium name", &state_.medium_defaults);
        MediumEntity m;
        m.name = std::move(e.type);
        m.type = e.params.get_one_string("type", "");
        if (m.type.empty())
            error(d, "MakeNamedMedium \"" + m.name + "\": missing \"string type\" parameter");
        for (const MediumEntity &existing : desc_.media)
            if (existing.name == m.name)
                error(d, "named medium \"" + m.name + "\" redefined (first defined at " +
                             existing.loc.to_string() + ")");
        m.params = std::move(e.params);
        m.loc = e.loc;
        require_invertible_ctm(d);
        warn_if_moving(d, "a medium");
        m.render_from_object = state_.ctm;
        desc_.media.push_back(std::move(m));
    }

    void material(const Token &d) {
        SceneEntity e = entity(d, "material type", &state_.material_defaults);
        require_world_block(d);
        if (e.type.empty() || e.type == "none") {
            warning(d.location(), "Material \"" + e.type + "\" is deprecated; using \"interface\" "
                                  "(no surface, only a boundary between media), as pbrt-v4 does");
            e.type = "interface";
        }
        desc_.materials.push_back(std::move(e));
        state_.material_index = int(desc_.materials.size()) - 1;
        state_.material_name.clear();
    }

    void medium_interface(const Token &d) {
        std::string inside = string_argument(d, "inside medium name");
        std::string outside = inside;
        Token second = next();
        if (second.kind == Token::Kind::String) outside = second.text;
        else unget(std::move(second));
        for (const std::string *name : {&inside, &outside})
            if (!name->empty()) medium_references_.push_back({*name, d.location()});
        state_.inside_medium = std::move(inside);
        state_.outside_medium = std::move(outside);
    }

    void named_material(const Token &d) {
        std::string name = string_argument(d, "material name");
        require_world_block(d);
        material_references_.push_back({name, d.location()});
        state_.material_name = std::move(name);
        state_.material_index = -1;
    }

    void object_begin(const Token &d) {
        std::string name = string_argument(d, "object name");
        require_world_block(d);
        if (active_instance_ >= 0)
            error(d, "ObjectBegin inside the ObjectBegin at " +
                         desc_.instances[active_instance_].loc.to_string());
        for (const InstanceDefinition &def : desc_.instances)
            if (def.name == name)
                error(d, "object \"" + name + "\" redefined (first defined at " +
                             def.loc.to_string() + ")");
        pushed_.push_back({state_, PushedState::Kind::Object, d.location()});
        desc_.instances.push_back({name, {}, d.location()});
        active_instance_ = int(desc_.instances.size()) - 1;
    }

    void object_end(const Token &d) {
        require_world_block(d);
        if (active_instance_ < 0) error(d, "ObjectEnd without a matching ObjectBegin");
        if (pushed_.back().kind != PushedState::Kind::Object)
            error(d, "ObjectEnd while the AttributeBegin at " + pushed_.back().loc.to_string() +
                         " is still open");
        if (pushed_.size() <= attribute_floor_)
            error(d, "ObjectEnd in an imported file for an ObjectBegin outside it");
        state_ = std::move(pushed_.back().state);
        pushed_.pop_back();
        active_instance_ = -1;
    }

    void object_instance(const Token &d) {
        std::string name = string_argument(d, "object name");
        require_world_block(d);
        if (active_instance_ >= 0)
            error(d, "ObjectInstance inside an object definition (ObjectBegin at " +
                         desc_.instances[active_instance_].loc.to_string() + ")");
        if (left_out_as_collapsed(d, "the instance")) return;
        desc_.instance_uses.push_back({name, AnimatedTransform(state_.ctm, state_.ctm_end), d.location()});
    }

    void option(const Token &d) {
        std::string written = string_argument(d, "option name");
        Token value = next();
        if (value.kind == Token::Kind::End || is_directive_word(value))
            error(d, "Option \"" + written + "\": missing value");
        if (value.kind != Token::Kind::Word && value.kind != Token::Kind::String)
            error(value, "Option \"" + written + "\": expected a value, found " + value.describe());
        // pbrt compares option names ignoring case, '-' and '_'. A "type name" spelling is
        // accepted by taking the last word.
        std::string name = written.substr(written.find_last_of(' ') == std::string::npos
                                              ? 0
                                              : written.find_last_of(' ') + 1);
        std::string normalized;
        for (char c : name)
            if (c != '-' && c != '_') normalized.push_back(char(std::tolower((unsigned char)c)));
        static const std::map<std::string, std::string> option_types = {
            {"disablepixeljitter", "bool"},      {"disabletexturefiltering", "bool"},
            {"disablewavelengthjitter", "bool"}, {"forcediffuse", "bool"},
            {"pixelstats", "bool"},              {"wavefront", "bool"},
            {"seed", "integer"},                 {"displacementedgescale", "float"},
            {"msereferenceimage", "string"},     {"msereferenceout", "string"},
            {"rendercoordsys", "string"}};
        auto it = option_types.find(normalized);
        if (it == option_types.end()) {
            warn(d.location(), "unknown option \"" + written + "\" ignored");
            return;
        }
        ParsedParameter p;
        p.type = it->second;
        p.name = normalized;
        p.loc = d.location();
        add_value(p, value_kind(p.type), value);
        validate_parameter(p);
        // Caustica renders in world space whatever the choice: it changes only rounding, and
        // pbrt-v4's interpolation of moving object instances (scenes/motion/moving-sphere.pbrt).
        if (p.name == "rendercoordsys" && p.strings.at(0) != "camera" && p.strings.at(0) != "cameraworld" &&
            p.strings.at(0) != "world")
            error(value, "Option \"rendercoordsys\": expected \"camera\", \"cameraworld\" or \"world\", "
                         "found \"" + p.strings.at(0) + "\"");
        std::erase_if(options_, [&](const ParsedParameter &o) { return o.name == p.name; });
        options_.push_back(std::move(p));
    }

    void pixel_filter(const Token &d) {
        SceneEntity e = entity(d, "filter type");
        require_options_block(d);
        desc_.filter = std::move(e);
    }

    void reverse_orientation(const Token &d) {
        require_world_block(d);
        state_.reverse_orientation = !state_.reverse_orientation;
    }

    void rotate(const Token &d) {
        std::vector<double> v = number_arguments(d, 4);
        Vec3f axis{float(v[1]), float(v[2]), float(v[3])};
        if (length_squared(axis) == 0) error(d, "Rotate: the rotation axis is zero");
        apply(d, Transform::rotate(float(v[0]), axis));
    }

    void sampler(const Token &d) {
        SceneEntity e = entity(d, "sampler type");
        require_options_block(d);
        desc_.sampler = std::move(e);
    }

    void scale(const Token &d) {
        std::vector<double> v = number_arguments(d, 3);
        apply(d, Transform::scale(float(v[0]), float(v[1]), float(v[2])));
    }

    void shape(const Token &d) {
        SceneEntity e = entity(d, "shape type", &state_.shape_defaults);
        require_world_block(d);
        ShapeEntity s;
        static_cast<SceneEntity &>(s) = std::move(e);
        if (left_out_as_collapsed(d, "the shape")) return;
        s.render_from_object = state_.ctm;
        if (ctm_moves()) {
            // pbrt-v4 refuses moving emitters too: light sampling would need the shape's time.
            if (state_.area_light)
                error(d, "an area light cannot move (as in pbrt-v4): the shape's transform differs "
                         "between the start and end times (ActiveTransform)");
            if (active_instance_ >= 0)
                warn(d.location(), "a shape inside ObjectBegin/ObjectEnd cannot move: the start "
                                   "transform is used (move the ObjectInstance instead)");
            else
                s.render_from_object_end = state_.ctm_end;
        }
        s.reverse_orientation = state_.reverse_orientation;
        s.material_index = state_.material_index;
        s.material_name = state_.material_name;
        s.inside_medium = state_.inside_medium;
        s.outside_medium = state_.outside_medium;
        if (state_.area_light) {
            if (active_instance_ >= 0) {
                warn(d.location(), "area lights are not supported on shapes inside "
                                   "ObjectBegin/ObjectEnd; this shape does not emit");
            } else {
                desc_.area_lights.push_back(*state_.area_light);
                s.area_light_index = int(desc_.area_lights.size()) - 1;
            }
        }
        if (active_instance_ >= 0) desc_.instances[active_instance_].shapes.push_back(std::move(s));
        else desc_.shapes.push_back(std::move(s));
    }

    void texture(const Token &d) {
        std::string name = string_argument(d, "texture name");
        Token class_tok = peek();
        std::string texture_class = string_argument(d, "texture class (\"float\" or \"spectrum\")");
        if (texture_class != "float" && texture_class != "spectrum")
            error(class_tok, "Texture \"" + name + "\": the class must be \"float\" or "
                             "\"spectrum\", not \"" + texture_class + "\"");
        std::string type = string_argument(d, "texture type");
        ParameterDictionary params = dictionary(parameter_list(), d, &state_.texture_defaults);
        require_world_block(d);
        for (const TextureEntity &t : desc_.textures)
            if (t.name == name && t.texture_class == texture_class)
                error(d, texture_class + " texture \"" + name + "\" redefined (first defined at " +
                             t.loc.to_string() + ")");
        TextureEntity t;
        t.type = std::move(type);
        t.params = std::move(params);
        t.loc = d.location();
        require_invertible_ctm(d);
        warn_if_moving(d, "a texture's space");
        t.render_from_object = state_.ctm;
        t.name = std::move(name);
        t.texture_class = std::move(texture_class);
        desc_.textures.push_back(std::move(t));
    }

    void transform_times(const Token &d) {
        std::vector<double> v = number_arguments(d, 2);
        require_options_block(d);
        if (!(v[1] >= v[0]) || !std::isfinite(v[0]) || !std::isfinite(v[1]))
            error(d, "TransformTimes: the end time must not precede the start time");
        desc_.transform_times = {float(v[0]), float(v[1])};
    }

    void translate(const Token &d) {
        std::vector<double> v = number_arguments(d, 3);
        apply(d, Transform::translate(Vec3f{float(v[0]), float(v[1]), float(v[2])}));
    }

    void world_begin(const Token &d) {
        require_options_block(d);
        in_world_ = true;
        state_.ctm = state_.ctm_end = Transform();
        state_.start_transform_active = state_.end_transform_active = true;
        named_frames_["world"] = {Transform(), Transform()};
        desc_.color_space = film_color_space_ ? film_color_space_ : state_.color_space;
    }

    // ---- End of input ----------------------------------------------------------------------

    void finish() {
        if (!pushed_.empty()) {
            const PushedState &open = pushed_.back();
            const char *what = open.kind == PushedState::Kind::Object      ? "ObjectBegin"
                               : open.kind == PushedState::Kind::Transform ? "TransformBegin"
                                                                            : "AttributeBegin";
            throw InputError(open.loc, std::string(what) + " is never closed");
        }
        if (!in_world_) error(end_token_, "end of file before WorldBegin");
        std::set<std::string> materials, objects, media;
        for (const auto &m : desc_.named_materials) materials.insert(m.first);
        for (const InstanceDefinition &i : desc_.instances) objects.insert(i.name);
        for (const MediumEntity &m : desc_.media) media.insert(m.name);
        // Names may be used before they are defined (pbrt-v4 resolves them after parsing), so
        // they are checked here, in file order.
        for (const NameReference &r : material_references_)
            if (!materials.count(r.name))
                throw InputError(r.loc, "NamedMaterial: no material named \"" + r.name +
                                            "\" is defined with MakeNamedMaterial");
        for (const InstanceUse &u : desc_.instance_uses)
            if (!objects.count(u.name))
                throw InputError(u.loc, "ObjectInstance: no object named \"" + u.name +
                                            "\" is defined with ObjectBegin");
        for (const NameReference &r : medium_references_)
            if (!media.count(r.name))
                throw InputError(r.loc, "MediumInterface: no medium named \"" + r.name +
                                            "\" is defined with MakeNamedMedium");
        desc_.options = ParameterDictionary(options_, {}, &RGBColorSpace::srgb(), base_directory_);
    }

    SceneDescription &desc_;
    std::string base_directory_;
    bool file_access_ = true;
    std::map<fs::path, const std::string *> memory_files_;  // ParseOptions::files, normalised
    std::vector<std::unique_ptr<std::string>> file_names_;
    std::vector<Source> sources_;
    std::vector<FinishedImport> finished_imports_;
    std::optional<Token> pending_;
    Token end_token_;

    GraphicsState state_;
    std::vector<PushedState> pushed_;
    // Pushed states below this depth belong to a file that Imports the current one.
    size_t attribute_floor_ = 0;
    std::map<std::string, std::pair<Transform, Transform>> named_frames_; // start and end
    bool in_world_ = false;
    int active_instance_ = -1;  // index into desc_.instances while inside ObjectBegin
    const RGBColorSpace *film_color_space_ = nullptr;
    std::vector<NameReference> material_references_, medium_references_;
    std::vector<ParsedParameter> options_;
    bool warned_transform_begin_ = false;
};

} // namespace

SceneDescription parse_scene_file(const std::string &path) {
    SceneDescription desc;
    fs::path p(path);
    SceneParser parser(desc, p.parent_path().string(), ParseOptions{});
    parser.push_file(p, {});
    parser.parse();
    return desc;
}

SceneDescription parse_scene_string(const std::string &text, const std::string &name) {
    return parse_scene_string(text, name, ParseOptions{});
}

SceneDescription parse_scene_string(const std::string &text, const std::string &name,
                                    const ParseOptions &options) {
    SceneDescription desc;
    SceneParser parser(desc, "", options);
    // In-memory files resolve against the text's own name, as files on disk would.
    parser.push_text(text, name, options.file_access ? fs::path() : fs::path(name).parent_path());
    parser.parse();
    return desc;
}

} // namespace caustica
