// RGB colour spaces: matrices and white points against the standards that define them.
#include "spectral/color_space.h"
#include "spectral/cie.h"
#include "spectral/named_spectra.h"

#include <gtest/gtest.h>

using namespace caustica;

TEST(RGBColorSpace, D65MapsToSrgbWhite) {
    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    RGB white = srgb.rgb_from_xyz(spectrum_to_xyz(*get_named_spectrum("stdillum-D65")));
    EXPECT_NEAR(white.r, 1, 1e-3f);
    EXPECT_NEAR(white.g, 1, 1e-3f);
    EXPECT_NEAR(white.b, 1, 1e-3f);
    XYZ w = srgb.xyz_from_rgb({1, 1, 1});
    EXPECT_NEAR(w.y, 1, 1e-3f);
}

// IEC 61966-2-1 (sRGB) publishes RGB -> XYZ to four decimals for its D65 white
// (0.3127, 0.3290); ours uses the spectral white of D65, equal to 4 digits in xy.
TEST(RGBColorSpace, SrgbMatrixMatchesStandard) {
    const float standard[3][3] = {
        {0.4124f, 0.3576f, 0.1805f}, {0.2126f, 0.7152f, 0.0722f}, {0.0193f, 0.1192f, 0.9505f}};
    const Matrix3 &m = RGBColorSpace::srgb().xyz_from_rgb_matrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(m[i][j], standard[i][j], 1e-3f) << i << j;
    Matrix3 product = m * RGBColorSpace::srgb().rgb_from_xyz_matrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(product[i][j], i == j ? 1 : 0, 1e-5f);
}

TEST(RGBColorSpace, PrimariesHaveTheirChromaticities) {
    for (const char *name : {"srgb", "aces2065-1", "rec2020", "dci-p3"}) {
        const RGBColorSpace *cs = RGBColorSpace::by_name(name);
        ASSERT_NE(cs, nullptr) << name;
        EXPECT_EQ(cs->name(), name);
        Chromaticity red = cs->xyz_from_rgb({1, 0, 0}).xy();
        EXPECT_NEAR(red.x, cs->red().x, 1e-4f) << name;
        EXPECT_NEAR(red.y, cs->red().y, 1e-4f) << name;
        Chromaticity green = cs->xyz_from_rgb({0, 1, 0}).xy();
        EXPECT_NEAR(green.x, cs->green().x, 1e-4f) << name;
        Chromaticity white = cs->xyz_from_rgb({1, 1, 1}).xy();
        EXPECT_NEAR(white.x, cs->whitepoint().xy().x, 1e-5f) << name;
    }
    EXPECT_EQ(RGBColorSpace::by_name("adobe-rgb"), nullptr);
    EXPECT_EQ(RGBColorSpace::by_name("srgb"), &RGBColorSpace::srgb());
}

TEST(RGBColorSpace, AcesWhiteIsD60) {
    Chromaticity w = RGBColorSpace::aces2065_1().whitepoint().xy();
    EXPECT_NEAR(w.x, 0.32168f, 3e-4f);
    EXPECT_NEAR(w.y, 0.33767f, 3e-4f);
}

TEST(RGBColorSpace, ConversionBetweenSpacesPreservesXyz) {
    Matrix3 to_rec2020 = rgb_conversion_matrix(RGBColorSpace::srgb(), RGBColorSpace::rec2020());
    RGB srgb{0.8f, 0.3f, 0.1f};
    XYZ a = RGBColorSpace::srgb().xyz_from_rgb(srgb);
    XYZ b = RGBColorSpace::rec2020().xyz_from_rgb(to_rec2020 * srgb);
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

// The film's Monte Carlo XYZ converges to the spectral XYZ: with stratified u the estimate
// of a smooth spectrum is close after few samples (exactness is tested in
// sampled_wavelengths_test; this checks the CMF wiring and normalisation).
TEST(SampledSpectrumToXyz, MatchesSpectralIntegration) {
    const Spectrum &d65 = *get_named_spectrum("stdillum-D65");
    XYZ reference = spectrum_to_xyz(d65);
    XYZ sum;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
        SampledWavelengths w = SampledWavelengths::sample_visible((i + 0.5f) / n);
        sum = sum + sampled_spectrum_to_xyz(d65.sample(w), w);
    }
    XYZ mean = sum / float(n);
    EXPECT_NEAR(mean.x, reference.x, 5e-3f);
    EXPECT_NEAR(mean.y, reference.y, 5e-3f);
    EXPECT_NEAR(mean.z, reference.z, 5e-3f);
    SampledWavelengths w = SampledWavelengths::sample_visible(0.5f);
    EXPECT_FLOAT_EQ(sampled_spectrum_to_y(d65.sample(w), w),
                    sampled_spectrum_to_xyz(d65.sample(w), w).y);
}
