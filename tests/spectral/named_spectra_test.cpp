// Named spectra: every pbrt-v4 name scenes use resolves, and the data is physically sane.
#include "spectral/named_spectra.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

using namespace caustica;

TEST(NamedSpectra, PbrtNamesResolve) {
    for (const char *name :
         {"glass-BK7",      "glass-BAF10",  "glass-FK51A",        "glass-LASF9",  "glass-F5",
          "glass-F10",      "glass-F11",    "glass-fused-silica", "glass-SF11",   "gem-sapphire",
          "gem-diamond",    "water",        "metal-Ag-eta",       "metal-Ag-k",   "metal-Al-eta",
          "metal-Al-k",     "metal-Au-eta", "metal-Au-k",         "metal-Cu-eta", "metal-Cu-k",
          "metal-CuZn-eta", "metal-CuZn-k", "metal-MgO-eta",      "metal-MgO-k",  "metal-TiO2-eta",
          "metal-TiO2-k",   "stdillum-A",   "stdillum-D50",       "stdillum-D65", "stdillum-F1",
          "stdillum-F12",   "illum-acesD60"})
        EXPECT_NE(get_named_spectrum(name), nullptr) << name;
    EXPECT_EQ(get_named_spectrum("metal-Unobtainium-eta"), nullptr);
    std::vector<std::string> names = named_spectrum_names();
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    EXPECT_EQ(get_named_spectrum("glass-BK7"), get_named_spectrum("glass-BK7"));  // shared
}

// Metals: eta > 0 and k > 0 across the whole sampled range (data held constant past the ends),
// and the normal-incidence reflectance ((n-1)^2 + k^2) / ((n+1)^2 + k^2) shows each metal's
// colour: silver and aluminium high and flat, gold and copper dark in the blue.
TEST(NamedSpectra, MetalsArePlausible) {
    auto reflectance = [](const char *metal, float lambda) {
        float n = (*get_named_spectrum(std::string("metal-") + metal + "-eta"))(lambda);
        float k = (*get_named_spectrum(std::string("metal-") + metal + "-k"))(lambda);
        return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    };
    for (const char *metal : {"Ag", "Al", "Au", "Cu", "CuZn"})
        for (float l = LambdaMin; l <= LambdaMax; l += 1) {
            EXPECT_GT((*get_named_spectrum(std::string("metal-") + metal + "-eta"))(l), 0)
                << metal << l;
            EXPECT_GT((*get_named_spectrum(std::string("metal-") + metal + "-k"))(l), 0)
                << metal << l;
        }
    EXPECT_GT(reflectance("Ag", 550), 0.9f);
    EXPECT_GT(reflectance("Al", 550), 0.85f);
    EXPECT_LT(reflectance("Au", 450), 0.45f);
    EXPECT_GT(reflectance("Au", 650), 0.9f);
    EXPECT_LT(reflectance("Cu", 450), 0.65f);
    EXPECT_GT(reflectance("Cu", 700), 0.9f);
    EXPECT_GT(reflectance("CuZn", 650), reflectance("CuZn", 420));
}
