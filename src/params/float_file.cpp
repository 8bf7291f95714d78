#include "params/float_file.h"

#include "core/error.h"
#include "params/number_text.h"

#include <fstream>
#include <sstream>

namespace caustica {

std::vector<float> read_float_file(const std::string &path, const std::string &what) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot open " + what + " \"" + path + "\"");
    std::vector<float> values;
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
                throw InputError(what + " \"" + path + "\" line " + std::to_string(line_number) + ": \"" + word +
                                 "\" is not a finite number");
            values.push_back(float(v));
        }
    }
    if (in.bad()) throw InputError("cannot read " + what + " \"" + path + "\"");
    if (values.empty()) throw InputError(what + " \"" + path + "\" holds no values");
    return values;
}

} // namespace caustica
