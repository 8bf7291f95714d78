// Tabulated complex refractive indices n + ik (transcribed measured data; definitions in
// metal_data.cpp). Use get_named_spectrum("metal-Cu-eta") etc. (named_spectra.h) instead.
//
// Sources:
// - Ag, Al, Au, Cu: after E. D. Palik (ed.), "Handbook of Optical Constants of Solids",
//   Academic Press (1985), resampled on a 0.05 eV photon-energy grid (4.15 to 1.40 eV). These
//   are the samples pbrt-v3 and pbrt-v4 ship as "metal-*-eta"/"metal-*-k"; we use the same
//   samples so that scenes render alike.
// - Brass (CuZn): M. R. Querry, "Optical constants", US Army CRDEC contractor report
//   CRDC-CR-85034 (1985), cartridge brass Cu70Zn30, 370 to 800 nm in 10 nm steps.
// - MgO, TiO2: the tables pbrt-v4 ships as "metal-MgO-*"/"metal-TiO2-*" (refractiveindex.info
//   data sets, measured at spectral lines).
#pragma once

namespace caustica::metal_data {

inline constexpr int PalikSamples = 56;
extern const float palik_lambda[PalikSamples];
extern const float silver_eta[PalikSamples], silver_k[PalikSamples];
extern const float aluminium_eta[PalikSamples], aluminium_k[PalikSamples];
extern const float gold_eta[PalikSamples], gold_k[PalikSamples];
extern const float copper_eta[PalikSamples], copper_k[PalikSamples];

inline constexpr int BrassSamples = 44;
extern const float brass_lambda[BrassSamples], brass_eta[BrassSamples], brass_k[BrassSamples];

inline constexpr int MagnesiumOxideSamples = 30;
extern const float magnesium_oxide_lambda[MagnesiumOxideSamples];
extern const float magnesium_oxide_eta[MagnesiumOxideSamples];
extern const float magnesium_oxide_k[MagnesiumOxideSamples];

inline constexpr int TitaniumDioxideSamples = 34;
extern const float titanium_dioxide_lambda[TitaniumDioxideSamples];
extern const float titanium_dioxide_eta[TitaniumDioxideSamples];
extern const float titanium_dioxide_k[TitaniumDioxideSamples];

} // namespace caustica::metal_data
