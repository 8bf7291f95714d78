#include "geometry/ply_header.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace caustica {

namespace {

// Bytes of a PLY scalar type in binary files; 0 for an unknown name.
int scalar_size(const std::string &type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

struct Element {
    std::string name;
    uint64_t count = 0;
    uint64_t min_binary_bytes = 0;  // per element
    uint64_t properties = 0;
};

} // namespace

void check_ply_element_counts(std::string_view start, uint64_t file_size, const std::string &path,
                              const SourceLocation &loc) {
    if (start.substr(0, 3) != "ply") return;
    size_t header_end = start.find("end_header");
    if (header_end == std::string_view::npos) return;
    size_t body = start.find('\n', header_end);
    if (body == std::string_view::npos) return;
    ++body;

    std::istringstream header{std::string(start.substr(0, header_end))};
    std::string line, format;
    std::vector<Element> elements;
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format") {
            words >> format;
        } else if (keyword == "element") {
            Element e;
            std::string count;
            words >> e.name >> count;
            auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), e.count);
            if (ec != std::errc() || end != count.data() + count.size()) return;
            elements.push_back(e);
        } else if (keyword == "property" && !elements.empty()) {
            std::string type;
            words >> type;
            // A list's items may be absent (a count of zero); its count is always there.
            if (type == "list") words >> type;
            int size = scalar_size(type);
            if (size == 0) return;
            elements.back().min_binary_bytes += uint64_t(size);
            elements.back().properties += 1;
        }
    }
    if (format.empty()) return;
    uint64_t available = file_size > body ? file_size - body : 0;
    uint64_t needed = 0;
    for (const Element &e : elements) {
        uint64_t per_element = format == "ascii" ? e.properties : e.min_binary_bytes;
        if (per_element == 0) continue;
        // Compare without overflowing: count * per_element > available - needed.
        if (e.count > (available - needed) / per_element)
            throw InputError(loc, "mesh file \"" + path + "\": its header declares " +
                                      std::to_string(e.count) + " \"" + e.name +
                                      "\" elements, more than the " + std::to_string(available) +
                                      " bytes after the header can hold");
        needed += e.count * per_element;
    }
}

void check_ply_file_element_counts(const std::string &path, const SourceLocation &loc) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // the mesh reader reports it
    // Headers are short; one that does not end within this prefix is left to the mesh reader.
    std::string start(1 << 16, '\0');
    in.read(start.data(), std::streamsize(start.size()));
    start.resize(size_t(in.gcount()));
    std::error_code ec;
    uint64_t size = std::filesystem::file_size(path, ec);
    if (!ec) check_ply_element_counts(start, size, path, loc);
}

} // namespace caustica
