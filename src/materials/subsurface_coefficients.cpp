#include "materials/subsurface_coefficients.h"

#include "core/vecmath.h"

#include <array>
#include <cctype>
#include <cmath>

namespace caustica {

float christensen_burley_scaling(float albedo) {
    float a = clamp(albedo, 0.f, 1.f);
    return 1.9f - a + 3.5f * sqr(a - 0.8f);
}

namespace {

// Jensen et al. 2001, Table 1 (transcribed; the same values as pbrt-v3's
// SubsurfaceParameterTable, which cites the paper). The paper computed the table's diffuse
// reflectances with eta = 1.3 for every material.
constexpr float JensenEta = 1.3f;
constexpr std::array<MeasuredSubsurfaceMedium, 12> JensenMedia = {{
    {"apple", {2.29f, 2.39f, 1.97f}, {0.0030f, 0.0034f, 0.046f}, JensenEta},
    {"chicken1", {0.15f, 0.21f, 0.38f}, {0.015f, 0.077f, 0.19f}, JensenEta},
    {"chicken2", {0.19f, 0.25f, 0.32f}, {0.018f, 0.088f, 0.20f}, JensenEta},
    {"cream", {7.38f, 5.47f, 3.15f}, {0.0002f, 0.0028f, 0.0163f}, JensenEta},
    {"ketchup", {0.18f, 0.07f, 0.03f}, {0.061f, 0.97f, 1.45f}, JensenEta},
    {"marble", {2.19f, 2.62f, 3.00f}, {0.0021f, 0.0041f, 0.0071f}, JensenEta},
    {"potato", {0.68f, 0.70f, 0.55f}, {0.0024f, 0.0090f, 0.12f}, JensenEta},
    {"skimmilk", {0.70f, 1.22f, 1.90f}, {0.0014f, 0.0025f, 0.0142f}, JensenEta},
    {"skin1", {0.74f, 0.88f, 1.01f}, {0.032f, 0.17f, 0.48f}, JensenEta},
    {"skin2", {1.09f, 1.59f, 1.79f}, {0.013f, 0.070f, 0.145f}, JensenEta},
    {"spectralon", {11.6f, 20.4f, 14.9f}, {0.00f, 0.00f, 0.00f}, JensenEta},
    {"wholemilk", {2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}, JensenEta},
}};

bool equal_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    auto lower = [](char c) { return std::tolower(static_cast<unsigned char>(c)); };
    for (size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i])) return false;
    return true;
}

} // namespace

std::span<const MeasuredSubsurfaceMedium> measured_subsurface_media() { return JensenMedia; }

std::optional<MeasuredSubsurfaceMedium> find_measured_subsurface_medium(std::string_view name) {
    for (const MeasuredSubsurfaceMedium &medium : JensenMedia)
        if (equal_ignoring_case(medium.name, name)) return medium;
    return std::nullopt;
}

std::string measured_subsurface_media_names() {
    std::string names;
    for (const MeasuredSubsurfaceMedium &medium : JensenMedia)
        names += (names.empty() ? "" : ", ") + std::string(medium.name);
    return names;
}

} // namespace caustica
