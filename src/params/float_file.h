// Text files of numbers, as pbrt-v4 reads spectra and lens descriptions: whitespace-separated
// values, with '#' starting a comment that runs to the end of the line.
#pragma once

#include <string>
#include <vector>

namespace caustica {

// Every number in the file at `path`, in order. `what` names the kind of file in messages
// ("spectrum file", "lens file"). Throws InputError (without a location; callers rethrow at the
// parameter that named the file) when the file cannot be read, holds anything but finite numbers,
// or holds none.
std::vector<float> read_float_file(const std::string &path, const std::string &what);

} // namespace caustica
