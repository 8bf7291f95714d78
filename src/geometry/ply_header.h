// A sanity check of a PLY file's header before the mesh reader trusts it: Assimp allocates the
// element counts the header declares, so a header claiming two billion vertices in a file of a
// few bytes would exhaust memory instead of failing.
#pragma once

#include "core/error.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace caustica {

// `start` is the beginning of the file (the whole header must be in it for the check to apply),
// `file_size` the size of the whole file in bytes. Throws InputError at loc when the declared
// elements cannot fit in the bytes after the header: in a binary file each element takes at
// least the sizes of its scalar properties and list counts, in an ASCII file at least one
// character per property. Text that is not a complete PLY header is left to the mesh reader.
void check_ply_element_counts(std::string_view start, uint64_t file_size, const std::string &path,
                              const SourceLocation &loc);
// The same check for the file at `path` (read as far as its header).
void check_ply_file_element_counts(const std::string &path, const SourceLocation &loc);

} // namespace caustica
