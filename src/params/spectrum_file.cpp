#include "params/spectrum_file.h"

#include "core/error.h"
#include "params/float_file.h"

namespace caustica {

std::vector<float> read_spectrum_file(const std::string &path) {
    std::vector<float> pairs = read_float_file(path, "spectrum file");
    if (pairs.size() % 2 != 0)
        throw InputError("spectrum file \"" + path +
                         "\" holds an odd number of values (expected wavelength-value pairs)");
    for (size_t i = 2; i < pairs.size(); i += 2)
        if (!(pairs[i] > pairs[i - 2]))
            throw InputError("spectrum file \"" + path + "\": wavelengths must increase (" +
                             std::to_string(pairs[i - 2]) + " is followed by " +
                             std::to_string(pairs[i]) + ")");
    return pairs;
}

} // namespace caustica
