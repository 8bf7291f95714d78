// RGB to spectrum (Jakob and Hanika 2019): spectra built from RGB have that RGB.
#include "spectral/rgb_spectrum.h"
#include "spectral/cie.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace caustica;

namespace {

// The spectrum's product with the colour space's illuminant: a reflectance as the film sees
// it under that light, or an emission spectrum as is.
class Product final : public Spectrum {
  public:
    Product(const Spectrum &a, const Spectrum &b) : a_(a), b_(b) {}
    float operator()(float l) const override { return a_(l) * b_(l); }
    float max_value() const override { return a_.max_value() * b_.max_value(); }

  private:
    const Spectrum &a_, &b_;
};

RGB rgb_of(const RGBColorSpace &cs, const Spectrum &s) {
    return cs.rgb_from_xyz(spectrum_to_xyz(s));
}

} // namespace

// Every colour of an 11^3 grid over [0, 1]^3 in sRGB: the reflectance stays in [0, 1] and its
// colour under D65 is the input within 0.005 (0.5% of full scale; the table interpolates
// optimised coefficients and is exact only at its nodes).
TEST(RGBAlbedoSpectrum, RoundTripsTheSrgbCube) {
    const RGBColorSpace &cs = RGBColorSpace::srgb();
    for (int r = 0; r <= 10; ++r)
        for (int g = 0; g <= 10; ++g)
            for (int b = 0; b <= 10; ++b) {
                RGB rgb{r / 10.f, g / 10.f, b / 10.f};
                RGBAlbedoSpectrum s(cs, rgb);
                for (float l = LambdaMin; l <= LambdaMax; l += 5) {
                    ASSERT_GE(s(l), 0.f);
                    ASSERT_LE(s(l), 1.f);
                }
                EXPECT_LE(s.max_value(), 1.f);
                RGB back = rgb_of(cs, Product(s, cs.illuminant()));
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(back[c], rgb[c], 0.005f)
                        << "rgb (" << rgb.r << ", " << rgb.g << ", " << rgb.b << ") channel " << c;
            }
}

// Inside-gamut colours of the other spaces round-trip too (the cube corners of the wide gamuts
// lie outside the spectral locus and have no reflectance spectrum at all).
TEST(RGBAlbedoSpectrum, RoundTripsOtherSpaces) {
    for (const char *name : {"aces2065-1", "rec2020", "dci-p3"}) {
        const RGBColorSpace &cs = *RGBColorSpace::by_name(name);
        for (RGB rgb : {RGB{0.5f, 0.4f, 0.3f}, RGB{0.2f, 0.3f, 0.25f}, RGB{0.7f, 0.7f, 0.6f}}) {
            RGBAlbedoSpectrum s(cs, rgb);
            RGB back = rgb_of(cs, Product(s, cs.illuminant()));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 0.005f) << name << " " << c;
        }
    }
}

TEST(RGBAlbedoSpectrum, GreysAreConstant) {
    const RGBColorSpace &cs = RGBColorSpace::srgb();
    for (float v : {0.f, 0.25f, 0.5f, 1.f}) {
        RGBAlbedoSpectrum s(cs, {v, v, v});
        for (float l : {400.f, 550.f, 700.f}) EXPECT_NEAR(s(l), v, 1e-6f);
    }
}

TEST(RGBIlluminantSpectrum, WhiteIsTheIlluminant) {
    for (const char *name : {"srgb", "aces2065-1"}) {
        const RGBColorSpace &cs = *RGBColorSpace::by_name(name);
        RGBIlluminantSpectrum s(cs, {1, 1, 1});
        for (float l = LambdaMin; l <= LambdaMax; l += 1) EXPECT_FLOAT_EQ(s(l), cs.illuminant()(l));
        EXPECT_EQ(&s.illuminant_spectrum(), &cs.illuminant());
        SampledWavelengths w = SampledWavelengths::sample_visible(0.37f);
        SampledSpectrum v = s.sample(w);
        for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(v[i], cs.illuminant()(w[i]));
    }
}

// Emission colours, including ones brighter than 1, are reproduced: the unbounded spectrum
// of rgb / (2 max) is scaled back up.
TEST(RGBIlluminantSpectrum, RoundTripsBrightColours) {
    const RGBColorSpace &cs = RGBColorSpace::srgb();
    for (RGB rgb :
         {RGB{4, 2, 1}, RGB{0.3f, 0.9f, 0.2f}, RGB{10, 10, 10}, RGB{0.05f, 0.02f, 0.1f}}) {
        RGBIlluminantSpectrum s(cs, rgb);
        RGB back = rgb_of(cs, s);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 0.005f * rgb.max_component()) << c;
    }
    RGBIlluminantSpectrum black(cs, {0, 0, 0});
    EXPECT_EQ(black(550), 0);
}

TEST(RGBUnboundedSpectrum, RoundTripsAboveOne) {
    const RGBColorSpace &cs = RGBColorSpace::srgb();
    RGB rgb{2.0f, 0.5f, 1.0f};
    RGBUnboundedSpectrum s(cs, rgb);
    RGB back = rgb_of(cs, Product(s, cs.illuminant()));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 0.01f) << c;
    EXPECT_GE(s.max_value(), 1.f);
    SampledWavelengths w = SampledWavelengths::sample_visible(0.61f);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(s.sample(w)[i], s(w[i]));
}
