// Spectra stored as text files of "wavelength value" pairs (pbrt's format: whitespace-separated
// numbers, '#' starts a comment that runs to the end of the line, wavelengths in nm ascending).
#pragma once

#include <string>
#include <vector>

namespace caustica {

// Interleaved (lambda, value) pairs read from `path`. Throws InputError (without a location;
// callers rethrow at the parameter that named the file) when the file cannot be read, holds
// something other than numbers, has an odd count, or its wavelengths do not increase.
std::vector<float> read_spectrum_file(const std::string &path);

} // namespace caustica
