#include "materials/radiance_scaling.h"

#include <cstdlib>
#include <string_view>

namespace caustica {

RadianceScalingFault radiance_scaling_fault() {
    static const RadianceScalingFault fault = [] {
        const char *value = std::getenv("CAUSTICA_TEST_FAULT");
        if (!value) return RadianceScalingFault::None;
        std::string_view name(value);
        if (name == "eta-importance") return RadianceScalingFault::AlsoImportance;
        if (name == "eta-drop") return RadianceScalingFault::DropFromRadiance;
        return RadianceScalingFault::None;
    }();
    return fault;
}

} // namespace caustica
