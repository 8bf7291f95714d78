#include "integrators/integrator.h"

#include <algorithm>
#include <cstring>

namespace caustica {

float RenderShare::max(float value) const {
    if (ranks() == 1) return value;
    std::vector<char> bytes(sizeof value);
    std::memcpy(bytes.data(), &value, sizeof value);
    bytes = gather_all(std::move(bytes));
    for (size_t offset = 0; offset + sizeof value <= bytes.size(); offset += sizeof value) {
        float v;
        std::memcpy(&v, &bytes[offset], sizeof v);
        value = std::max(value, v);
    }
    return value;
}

const RenderShare &RenderShare::alone() {
    static const RenderShare share;
    return share;
}

} // namespace caustica
