#include "core/file_contents.h"

#include <zlib.h>

#include <fstream>
#include <sstream>

namespace caustica {

std::optional<std::string> read_file_contents(const std::filesystem::path &path, std::string *error) {
    if (path.extension() != ".gz") {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            *error = "cannot open it";
            return std::nullopt;
        }
        std::ostringstream s;
        s << in.rdbuf();
        if (in.bad()) {
            *error = "cannot read it";
            return std::nullopt;
        }
        return s.str();
    }
    gzFile file = gzopen(path.c_str(), "rb");
    if (!file) {
        *error = "cannot open it";
        return std::nullopt;
    }
    std::string data;
    char buffer[1 << 16];
    int n;
    while ((n = gzread(file, buffer, sizeof buffer)) > 0) data.append(buffer, size_t(n));
    int code = 0;
    if (n < 0) *error = std::string("cannot decompress it: ") + gzerror(file, &code);
    gzclose(file);
    if (n < 0) return std::nullopt;
    return data;
}

} // namespace caustica
