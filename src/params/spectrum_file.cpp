#include "params/spectrum_file.h"

#include "core/error.h"
#include "params/number_text.h"

#include <fstream>
#include <sstream>

namespace caustica {

std::vector<float> read_spectrum_file(const std::string &path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot open spectrum file \"" + path + "\"");
    std::vector<float> pairs;
    std::string line;
    int line_number = 0;
    while (std::getline(in, line)) {
        ++line_number;
        if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::string word;
        while (words >> word) {
            double v;
            if (parse_number_text(word, &v) != NumberTextStatus::Ok)
                throw InputError("spectrum file \"" + path + "\" line " +
                                 std::to_string(line_number) + ": \"" + word +
                                 "\" is not a finite number");
            pairs.push_back(float(v));
        }
    }
    if (pairs.empty()) throw InputError("spectrum file \"" + path + "\" holds no values");
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
