#include "geometry/ply_file.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace caustica {

namespace {

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class Format { Ascii, LittleEndian, BigEndian };

std::optional<Scalar> scalar_named(std::string_view name) {
    if (name == "char" || name == "int8") return Scalar::Int8;
    if (name == "uchar" || name == "uint8") return Scalar::UInt8;
    if (name == "short" || name == "int16") return Scalar::Int16;
    if (name == "ushort" || name == "uint16") return Scalar::UInt16;
    if (name == "int" || name == "int32") return Scalar::Int32;
    if (name == "uint" || name == "uint32") return Scalar::UInt32;
    if (name == "float" || name == "float32") return Scalar::Float32;
    if (name == "double" || name == "float64") return Scalar::Float64;
    return std::nullopt;
}

size_t scalar_bytes(Scalar s) {
    switch (s) {
    case Scalar::Int8: case Scalar::UInt8: return 1;
    case Scalar::Int16: case Scalar::UInt16: return 2;
    case Scalar::Int32: case Scalar::UInt32: case Scalar::Float32: return 4;
    case Scalar::Float64: return 8;
    }
    return 0;
}

struct Property {
    std::string name;
    Scalar type = Scalar::Float32;
    std::optional<Scalar> list_count; // set for "property list <count> <item> <name>"
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t body = 0; // offset of the first byte after the "end_header" line
};

class PlyReader {
  public:
    PlyReader(std::string_view bytes, const std::string &path, const SourceLocation &loc)
        : bytes_(bytes), path_(path), loc_(loc) {}

    MeshData read() {
        Header header = parse_header();
        check_counts(header);
        format_ = header.format;
        pos_ = header.body;
        MeshData mesh;
        // Face corners of triangles and quads, validated once every vertex is known.
        std::vector<int64_t> triangles, quads;
        size_t skipped_faces = 0;
        for (const Element &e : header.elements) {
            if (e.name == "vertex") read_vertices(e, &mesh);
            else if (e.name == "face") read_faces(e, &triangles, &quads, &skipped_faces);
            else skip_element(e);
        }
        for (const std::vector<int64_t> *corners : {&triangles, &quads})
            for (int64_t c : *corners)
                if (c < 0 || c >= int64_t(mesh.p.size()))
                    fail("a face refers to vertex " + std::to_string(c) + ", but there are " +
                         std::to_string(mesh.p.size()) + " vertices");
        mesh.indices.assign(triangles.begin(), triangles.end());
        mesh.quads.assign(quads.begin(), quads.end());
        if (skipped_faces > 0)
            warning(loc_, "plymesh \"" + path_ + "\": ignored " + std::to_string(skipped_faces) +
                              " faces that are neither triangles nor quads, as pbrt-v4 does");
        if (mesh.indices.empty() && mesh.quads.empty()) fail("holds no triangles or quads");
        return mesh;
    }

  private:
    [[noreturn]] void fail(const std::string &message) const {
        throw InputError(loc_, "mesh file \"" + path_ + "\": " + message);
    }

    // The header is text lines ending in "\n" (a "\r" before it is tolerated); the body starts
    // right after the line end of "end_header", whatever byte follows.
    Header parse_header() {
        Header header;
        size_t pos = 0;
        bool has_format = false;
        for (int line_number = 1;; ++line_number) {
            size_t end = bytes_.find('\n', pos);
            if (end == std::string_view::npos) fail("its header has no \"end_header\" line");
            std::string_view line = bytes_.substr(pos, end - pos);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            pos = end + 1;
            std::vector<std::string_view> words = split(line);
            auto bad = [&](const std::string &why) {
                fail("header line " + std::to_string(line_number) + " \"" + std::string(line) +
                     "\": " + why);
            };
            if (line_number == 1) {
                if (words.size() != 1 || words[0] != "ply") bad("a PLY file starts with \"ply\"");
                continue;
            }
            if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
            if (words[0] == "end_header") break;
            if (words[0] == "format") {
                if (words.size() != 3) bad("expected \"format <type> 1.0\"");
                if (words[1] == "ascii") header.format = Format::Ascii;
                else if (words[1] == "binary_little_endian") header.format = Format::LittleEndian;
                else if (words[1] == "binary_big_endian") header.format = Format::BigEndian;
                else bad("unknown format");
                has_format = true;
            } else if (words[0] == "element") {
                Element e;
                if (words.size() != 3) bad("expected \"element <name> <count>\"");
                e.name = std::string(words[1]);
                auto [ptr, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(),
                                                 e.count);
                if (ec != std::errc() || ptr != words[2].data() + words[2].size())
                    bad("the count is not a number");
                header.elements.push_back(std::move(e));
            } else if (words[0] == "property") {
                if (header.elements.empty()) bad("a property before any element");
                Property p;
                bool list = words.size() == 5 && words[1] == "list";
                if (!list && words.size() != 3) bad("expected \"property <type> <name>\"");
                std::optional<Scalar> type = scalar_named(words[list ? 3 : 1]);
                if (!type) bad("unknown property type");
                p.type = *type;
                if (list) {
                    p.list_count = scalar_named(words[2]);
                    if (!p.list_count || *p.list_count == Scalar::Float32 ||
                        *p.list_count == Scalar::Float64)
                        bad("a list count must be an integer type");
                }
                p.name = std::string(words.back());
                header.elements.back().properties.push_back(std::move(p));
            } else {
                bad("unknown keyword");
            }
        }
        if (!has_format) fail("its header has no \"format\" line");
        header.body = pos;
        return header;
    }

    static std::vector<std::string_view> split(std::string_view line) {
        std::vector<std::string_view> words;
        size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            size_t start = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
            if (i > start) words.push_back(line.substr(start, i - start));
        }
        return words;
    }

    // Each element needs at least its scalars' bytes (binary) or one character per property
    // (ascii), so a header that declares more than the body can hold is refused before anything
    // is allocated for it.
    void check_counts(const Header &header) const {
        uint64_t available = bytes_.size() - header.body;
        uint64_t needed = 0;
        for (const Element &e : header.elements) {
            uint64_t per_element = 0;
            for (const Property &p : e.properties)
                per_element += header.format == Format::Ascii
                                   ? 1
                                   : scalar_bytes(p.list_count ? *p.list_count : p.type);
            if (per_element == 0) continue;
            if (e.count > (available - needed) / per_element)
                fail("its header declares " + std::to_string(e.count) + " \"" + e.name +
                     "\" elements, more than the " + std::to_string(available) +
                     " bytes after the header can hold");
            needed += e.count * per_element;
        }
    }

    double read_scalar(Scalar type, const Element &e) {
        if (format_ == Format::Ascii) return read_ascii(e);
        size_t n = scalar_bytes(type);
        if (bytes_.size() - pos_ < n) truncated(e);
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + pos_, n);
        pos_ += n;
        if ((format_ == Format::BigEndian) != (std::endian::native == std::endian::big))
            for (size_t i = 0; i < n / 2; ++i) std::swap(raw[i], raw[n - 1 - i]);
        switch (type) {
        case Scalar::Int8: { int8_t v; std::memcpy(&v, raw, 1); return v; }
        case Scalar::UInt8: return raw[0];
        case Scalar::Int16: { int16_t v; std::memcpy(&v, raw, 2); return v; }
        case Scalar::UInt16: { uint16_t v; std::memcpy(&v, raw, 2); return v; }
        case Scalar::Int32: { int32_t v; std::memcpy(&v, raw, 4); return v; }
        case Scalar::UInt32: { uint32_t v; std::memcpy(&v, raw, 4); return v; }
        case Scalar::Float32: { float v; std::memcpy(&v, raw, 4); return v; }
        case Scalar::Float64: { double v; std::memcpy(&v, raw, 8); return v; }
        }
        return 0;
    }

    double read_ascii(const Element &e) {
        auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
        while (pos_ < bytes_.size() && space(bytes_[pos_])) ++pos_;
        if (pos_ == bytes_.size()) truncated(e);
        const char *begin = bytes_.data() + pos_, *end = bytes_.data() + bytes_.size();
        double value = 0;
        auto [ptr, ec] = std::from_chars(begin, end, value);
        if (ec != std::errc()) fail("a \"" + e.name + "\" value is not a number");
        pos_ = size_t(ptr - bytes_.data());
        return value;
    }

    [[noreturn]] void truncated(const Element &e) const {
        fail("the file ends before its " + std::to_string(e.count) + " \"" + e.name +
             "\" elements do");
    }

    // A list's length, checked against what the rest of the file can hold.
    uint64_t read_list_count(const Property &p, const Element &e) {
        double count = read_scalar(*p.list_count, e);
        if (!(count >= 0) || count != std::floor(count)) fail("a list has a negative length");
        size_t least = format_ == Format::Ascii ? 1 : scalar_bytes(p.type);
        if (count > double(bytes_.size() - pos_) / double(least)) truncated(e);
        return uint64_t(count);
    }

    void skip_property(const Property &p, const Element &e) {
        uint64_t n = p.list_count ? read_list_count(p, e) : 1;
        if (format_ != Format::Ascii) {
            pos_ += n * scalar_bytes(p.type); // read_list_count checked that these bytes exist
            if (pos_ > bytes_.size()) truncated(e);
        } else {
            for (uint64_t i = 0; i < n; ++i) read_ascii(e);
        }
    }

    void skip_element(const Element &e) {
        for (uint64_t i = 0; i < e.count; ++i)
            for (const Property &p : e.properties) skip_property(p, e);
    }

    void read_vertices(const Element &e, MeshData *mesh) {
        enum Slot { X, Y, Z, NX, NY, NZ, U, V, None };
        auto slot_of = [](const std::string &name) {
            if (name == "x") return X;
            if (name == "y") return Y;
            if (name == "z") return Z;
            if (name == "nx") return NX;
            if (name == "ny") return NY;
            if (name == "nz") return NZ;
            for (const char *u : {"u", "s", "texture_u", "texture_s"})
                if (name == u) return U;
            for (const char *v : {"v", "t", "texture_v", "texture_t"})
                if (name == v) return V;
            return None;
        };
        std::vector<Slot> slots;
        bool present[None] = {};
        for (const Property &p : e.properties) {
            Slot s = p.list_count ? None : slot_of(p.name);
            slots.push_back(s);
            if (s != None) present[s] = true;
        }
        if (!present[X] || !present[Y] || !present[Z])
            fail("its \"vertex\" element lacks x, y or z");
        bool normals = present[NX] && present[NY] && present[NZ];
        bool uv = present[U] && present[V];
        mesh->p.reserve(e.count);
        if (normals) mesh->n.reserve(e.count);
        if (uv) mesh->uv.reserve(e.count);
        for (uint64_t i = 0; i < e.count; ++i) {
            double value[None] = {};
            for (size_t k = 0; k < e.properties.size(); ++k) {
                if (slots[k] == None) skip_property(e.properties[k], e);
                else value[slots[k]] = read_scalar(e.properties[k].type, e);
            }
            mesh->p.push_back(Vec3f(float(value[X]), float(value[Y]), float(value[Z])));
            if (normals)
                mesh->n.push_back(Vec3f(float(value[NX]), float(value[NY]), float(value[NZ])));
            if (uv) mesh->uv.push_back(Vec2f(float(value[U]), float(value[V])));
        }
    }

    void read_faces(const Element &e, std::vector<int64_t> *triangles, std::vector<int64_t> *quads,
                    size_t *skipped) {
        bool found = false;
        for (uint64_t i = 0; i < e.count; ++i) {
            for (const Property &p : e.properties) {
                if (!p.list_count || (p.name != "vertex_indices" && p.name != "vertex_index")) {
                    skip_property(p, e);
                    continue;
                }
                found = true;
                uint64_t n = read_list_count(p, e);
                int64_t v[4];
                for (uint64_t k = 0; k < n; ++k) {
                    double index = read_scalar(p.type, e);
                    if (index != std::floor(index) || std::abs(index) > 2147483647.0)
                        fail("a face index is not a vertex number");
                    if (k < 4) v[k] = int64_t(index);
                }
                if (n == 3) {
                    triangles->insert(triangles->end(), {v[0], v[1], v[2]});
                } else if (n == 4) {
                    // pbrt-v4 makes the quad the bilinear patch (v0, v1, v3, v2).
                    quads->insert(quads->end(), {v[0], v[1], v[3], v[2]});
                } else {
                    ++*skipped;
                }
            }
        }
        if (!found && e.count > 0) fail("its \"face\" element has no vertex_indices list");
    }

    std::string_view bytes_;
    const std::string &path_;
    const SourceLocation &loc_;
    Format format_ = Format::Ascii;
    size_t pos_ = 0;
};

} // namespace

bool is_ply(std::string_view bytes) {
    return bytes.substr(0, 4) == "ply\n" || bytes.substr(0, 5) == "ply\r\n";
}

MeshData read_ply(std::string_view bytes, const std::string &path, const SourceLocation &loc) {
    return PlyReader(bytes, path, loc).read();
}

} // namespace caustica
