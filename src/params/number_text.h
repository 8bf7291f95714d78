// Reading numbers written in scene and data files: decimal integers and floating-point values
// ("1", "-2.5", ".5", "+3e-2"). NaN and infinity, whether spelt out or reached by overflow, are
// rejected: no scene quantity may be non-finite.
#pragma once

#include <string_view>

namespace caustica {

enum class NumberTextStatus { Ok, NotANumber, NotFinite };

// Parses the whole of `text`; `*value` is set only when the status is Ok.
NumberTextStatus parse_number_text(std::string_view text, double *value);

} // namespace caustica
