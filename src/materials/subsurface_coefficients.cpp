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

// Narasimhan, Gupta, Donner, Ramamoorthi, Nayar and Jensen 2006, "Acquiring Scattering Properties
// of Participating Media by Dilution", Table 1: sigma_s' and sigma_a in mm^-1 of liquids and
// powders dissolved in water (the same values as pbrt-v4's media presets). The paper gives no
// index; these are water's.
constexpr float WaterEta = 1.33f;
constexpr std::array<MeasuredSubsurfaceMedium, 35> DilutionMedia = {{
    {"Lowfat Milk", {0.89187f, 1.5136f, 2.532f}, {0.002875f, 0.00575f, 0.0115f}, WaterEta},
    {"Reduced Milk", {2.4858f, 3.1669f, 4.5214f}, {0.0025556f, 0.0051111f, 0.012778f}, WaterEta},
    {"Regular Milk", {4.5513f, 5.8294f, 7.136f}, {0.0015333f, 0.0046f, 0.019933f}, WaterEta},
    {"Espresso", {0.72378f, 0.84557f, 1.0247f}, {4.7984f, 6.5751f, 8.8493f}, WaterEta},
    {"Mint Mocha Coffee", {0.31602f, 0.38538f, 0.48131f}, {3.772f, 5.8228f, 7.82f}, WaterEta},
    {"Lowfat Soy Milk", {0.30576f, 0.34233f, 0.61664f}, {0.0014375f, 0.0071875f, 0.035937f}, WaterEta},
    {"Regular Soy Milk", {0.59223f, 0.73866f, 1.4693f}, {0.0019167f, 0.0095833f, 0.065167f}, WaterEta},
    {"Lowfat Chocolate Milk", {0.64925f, 0.83916f, 1.1057f}, {0.0115f, 0.0368f, 0.1564f}, WaterEta},
    {"Regular Chocolate Milk", {1.4585f, 2.1289f, 2.9527f}, {0.010063f, 0.043125f, 0.14375f}, WaterEta},
    {"Coke", {8.9053e-05f, 8.372e-05f, 0}, {0.10014f, 0.16503f, 0.2468f}, WaterEta},
    {"Pepsi", {6.1697e-05f, 4.2564e-05f, 0}, {0.091641f, 0.14158f, 0.20729f}, WaterEta},
    {"Sprite", {6.0306e-06f, 6.4139e-06f, 6.5504e-06f}, {0.001886f, 0.0018308f, 0.0020025f}, WaterEta},
    {"Gatorade", {0.0024574f, 0.003007f, 0.0037325f}, {0.024794f, 0.019289f, 0.008878f}, WaterEta},
    {"Chardonnay", {1.7982e-05f, 1.3758e-05f, 1.2023e-05f}, {0.010782f, 0.011855f, 0.023997f}, WaterEta},
    {"White Zinfandel", {1.7501e-05f, 1.9069e-05f, 1.288e-05f}, {0.012072f, 0.016184f, 0.019843f}, WaterEta},
    {"Merlot", {2.1129e-05f, 0, 0}, {0.11632f, 0.25191f, 0.29434f}, WaterEta},
    {"Budweiser Beer", {2.4356e-05f, 2.4079e-05f, 1.0564e-05f}, {0.011492f, 0.024911f, 0.057786f}, WaterEta},
    {"Coors Light Beer", {5.0922e-05f, 4.301e-05f, 0}, {0.006164f, 0.013984f, 0.034983f}, WaterEta},
    {"Clorox", {0.0024035f, 0.0031373f, 0.003991f}, {0.0033542f, 0.014892f, 0.026297f}, WaterEta},
    {"Apple Juice", {0.00013612f, 0.00015836f, 0.000227f}, {0.012957f, 0.023741f, 0.052184f}, WaterEta},
    {"Cranberry Juice", {0.00010402f, 0.00011646f, 7.8139e-05f}, {0.039437f, 0.094223f, 0.12426f}, WaterEta},
    {"Grape Juice", {5.382e-05f, 0, 0}, {0.10404f, 0.23958f, 0.29325f}, WaterEta},
    {"Ruby Grapefruit Juice", {0.011002f, 0.010927f, 0.011036f}, {0.085867f, 0.18314f, 0.25262f}, WaterEta},
    {"White Grapefruit Juice", {0.22826f, 0.23998f, 0.32748f}, {0.0138f, 0.018831f, 0.056781f}, WaterEta},
    {"Shampoo", {0.0007176f, 0.0008303f, 0.0009016f}, {0.014107f, 0.045693f, 0.061717f}, WaterEta},
    {"Strawberry Shampoo", {0.00015671f, 0.00015947f, 1.518e-05f}, {0.01449f, 0.05796f, 0.075823f}, WaterEta},
    {"Head & Shoulders Shampoo", {0.023805f, 0.028804f, 0.034306f}, {0.084621f, 0.15688f, 0.20365f}, WaterEta},
    {"Lemon Tea Powder", {0.040224f, 0.045264f, 0.051081f}, {2.4288f, 4.5757f, 7.2127f}, WaterEta},
    {"Orange Powder", {0.00015617f, 0.00017482f, 0.0001762f}, {0.001449f, 0.003441f, 0.007863f}, WaterEta},
    {"Pink Lemonade Powder", {0.00012103f, 0.00013073f, 0.00012528f}, {0.001165f, 0.002366f, 0.003195f}, WaterEta},
    {"Cappuccino Powder", {1.8436f, 2.5851f, 2.1662f}, {35.844f, 49.547f, 61.084f}, WaterEta},
    {"Salt Powder", {0.027333f, 0.032451f, 0.031979f}, {0.28415f, 0.3257f, 0.34148f}, WaterEta},
    {"Sugar Powder", {0.00022272f, 0.00025513f, 0.000271f}, {0.012638f, 0.031051f, 0.050124f}, WaterEta},
    {"Suisse Mocha Powder", {2.7979f, 3.5452f, 4.3365f}, {17.502f, 27.004f, 35.433f}, WaterEta},
    {"Pacific Ocean Surface Water", {0.0001764f, 0.00032095f, 0.00019617f}, {0.031845f, 0.031324f, 0.030147f}, WaterEta},
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

std::span<const MeasuredSubsurfaceMedium> diluted_media() { return DilutionMedia; }

std::optional<MeasuredSubsurfaceMedium> find_measured_subsurface_medium(std::string_view name) {
    for (auto table : {measured_subsurface_media(), diluted_media()})
        for (const MeasuredSubsurfaceMedium &medium : table)
            if (equal_ignoring_case(medium.name, name)) return medium;
    return std::nullopt;
}

std::string measured_subsurface_media_names() {
    std::string names;
    for (auto table : {measured_subsurface_media(), diluted_media()})
        for (const MeasuredSubsurfaceMedium &medium : table)
            names += (names.empty() ? "" : ", ") + std::string(medium.name);
    return names;
}

} // namespace caustica
