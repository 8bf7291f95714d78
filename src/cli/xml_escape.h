// Escaping text for the XML and HTML that `caustica compare` writes.
#pragma once

#include <string>

namespace caustica {

// `text` with &, <, >, " and ' replaced by entities: safe as XML or HTML text and inside quoted
// attribute values.
inline std::string xml_escape(const std::string &text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

} // namespace caustica
