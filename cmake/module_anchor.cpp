// Gives every module object library at least one source, so a folder whose files are all
// headers still forms a valid CMake target.
