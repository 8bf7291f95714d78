// Builds ParameterDictionary objects for factory tests, each parameter on its own line of a
// fictitious "test.pbrt" so error locations can be checked.
#pragma once

#include "core/error.h"
#include "params/parameters.h"

#include <vector>

namespace caustica::testing {

inline ParsedParameter numbers(const std::string &type, const std::string &name,
                               std::vector<double> values, int line) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(values);
    p.loc = {"test.pbrt", line, 5};
    return p;
}
inline ParsedParameter strings(const std::string &type, const std::string &name,
                               std::vector<std::string> values, int line) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.strings = std::move(values);
    p.loc = {"test.pbrt", line, 5};
    return p;
}
inline ParsedParameter boolean(const std::string &name, bool value, int line) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.bools = {value};
    p.loc = {"test.pbrt", line, 5};
    return p;
}
inline ParameterDictionary dictionary(std::vector<ParsedParameter> params) {
    return ParameterDictionary(std::move(params), SourceLocation{"test.pbrt", 1, 1}, nullptr, ".");
}
inline const SourceLocation &directive_location() {
    static const SourceLocation loc{"test.pbrt", 1, 1};
    return loc;
}

// The line of the InputError that create() throws, or -1 if it throws none.
template <class Create> int input_error_line(Create &&create) {
    try {
        create();
    } catch (const InputError &e) {
        return e.location().line;
    }
    return -1;
}

} // namespace caustica::testing
