#include "params/number_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace caustica {

NumberTextStatus parse_number_text(std::string_view text, double *value) {
    // from_chars does not take a leading '+', which scene files do use.
    if (!text.empty() && text[0] == '+') text.remove_prefix(1);
    if (text.empty()) return NumberTextStatus::NotANumber;
    // Spelt-out non-finite values ("nan", "-inf", "Infinity") get their own status for a
    // clearer message; from_chars would otherwise accept them.
    std::string_view unsigned_text = text[0] == '-' ? text.substr(1) : text;
    if (!unsigned_text.empty() && std::isalpha(static_cast<unsigned char>(unsigned_text[0]))) {
        std::string lower(unsigned_text);
        for (char &ch : lower) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (lower == "nan" || lower == "inf" || lower == "infinity")
            return NumberTextStatus::NotFinite;
        return NumberTextStatus::NotANumber;
    }
    // Only digits, a sign and '.' may start a number.
    char c = text[0];
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-')) return NumberTextStatus::NotANumber;
    if (c == '-' && text.size() > 1 && !((text[1] >= '0' && text[1] <= '9') || text[1] == '.'))
        return NumberTextStatus::NotANumber;
    double v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (end != text.data() + text.size()) return NumberTextStatus::NotANumber;
    if (ec == std::errc::result_out_of_range) {
        // Out of double's range: strtod tells overflow (+-HUGE_VAL) from harmless underflow.
        double r = std::strtod(std::string(text).c_str(), nullptr);
        if (std::isinf(r)) return NumberTextStatus::NotFinite;
        *value = r;
        return NumberTextStatus::Ok;
    }
    if (ec != std::errc()) return NumberTextStatus::NotANumber;
    if (!std::isfinite(v)) return NumberTextStatus::NotFinite;
    *value = v;
    return NumberTextStatus::Ok;
}

} // namespace caustica
