// Reading a whole file into memory, decompressing it when its name ends in ".gz", as pbrt-v4
// does for scene files (Include "geometry.pbrt.gz") and for PLY meshes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace caustica {

// The file's bytes, or nullopt with *error saying why it could not be read or decompressed.
std::optional<std::string> read_file_contents(const std::filesystem::path &path, std::string *error);

} // namespace caustica
