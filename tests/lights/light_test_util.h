// Shared helpers for the light tests: parameter lists and photometric integrals.
#pragma once

#include "params/parameters.h"
#include "spectral/cie.h"

#include <functional>
#include <string>
#include <vector>

namespace caustica::testing {

inline ParsedParameter numbers(const std::string &type, const std::string &name,
                               std::vector<double> values) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(values);
    p.loc = {"test.pbrt", 7, int(name.size())};
    return p;
}
inline ParsedParameter text(const std::string &type, const std::string &name, std::string value) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.strings = {std::move(value)};
    p.loc = {"test.pbrt", 8, int(name.size())};
    return p;
}
inline ParsedParameter boolean(const std::string &name, bool value) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.bools = {value};
    p.loc = {"test.pbrt", 9, 1};
    return p;
}
inline ParameterDictionary dictionary(std::vector<ParsedParameter> params,
                                      std::string base_directory = "") {
    return ParameterDictionary(std::move(params), {"test.pbrt", 1, 1}, nullptr,
                               std::move(base_directory));
}

// Luminance integral, sum over integer nm of ybar(l) f(l): pbrt-v4's SpectrumToPhotometric and
// what its default sensor records as Y (it divides by nothing).
inline double luminance_of(const std::function<float(float)> &f) {
    double sum = 0;
    for (int l = int(LambdaMin); l <= int(LambdaMax); ++l) sum += cie_y()(float(l)) * f(float(l));
    return sum;
}

}  // namespace caustica::testing
