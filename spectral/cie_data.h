// Raw CIE tables (transcribed measured/standardised data; definitions in cie_data.cpp). Use the
// Spectrum objects of cie.h instead; these arrays exist for cie.cpp and the table generator.
#pragma once

namespace caustica::cie_data {

// CIE 1931 2-degree colour matching functions, every 1 nm from 360 to 830 nm.
inline constexpr int CmfSamples = 471;
inline constexpr int CmfLambdaMin = 360;
extern const float x_bar[CmfSamples];
extern const float y_bar[CmfSamples];
extern const float z_bar[CmfSamples];

// Daylight basis functions and illuminant D65, every 5 nm from 300 to 830 nm.
inline constexpr int DaylightSamples = 107;
inline constexpr float DaylightLambdaMin = 300, DaylightLambdaStep = 5;
extern const float daylight_s0[DaylightSamples];
extern const float daylight_s1[DaylightSamples];
extern const float daylight_s2[DaylightSamples];
extern const float illuminant_d65[DaylightSamples];

// Fluorescent illuminants F1..F12, every 5 nm from 380 to 780 nm.
inline constexpr int FluorescentSamples = 81;
inline constexpr float FluorescentLambdaMin = 380, FluorescentLambdaStep = 5;
extern const float illuminant_f[12][FluorescentSamples];

} // namespace caustica::cie_data
