// Creates the sampler a scene's Sampler directive asks for (pbrt-v4 names and parameters).
#pragma once

#include "core/error.h"
#include "params/parameters.h"
#include "sampler/sampler.h"

#include <memory>
#include <string>

namespace caustica {

// "independent" ("pixelsamples", default 4) and "stratified" ("xsamples", "ysamples", default
// 4 each, "jitter", default true) are implemented. pbrt's low-discrepancy samplers ("halton",
// "sobol", "paddedsobol", "zsobol", "pmj02bn"; "pixelsamples", default 16) are replaced, with a
// warning, by a jittered stratified sampler with the same sample count. The "seed" parameter
// overrides `seed`; spp_override > 0 (the command line) replaces the sample count. Unknown
// types and non-positive sample counts are InputErrors.
std::unique_ptr<Sampler> create_sampler(const std::string &type, const ParameterDictionary &params,
                                        const SourceLocation &loc, int seed, int spp_override = 0);

// What a scene without a Sampler directive renders with: pbrt-v4's default is "zsobol" with 16
// samples per pixel; until it exists, a jittered 4x4 stratified sampler (no warning, since the
// scene asked for nothing in particular).
std::unique_ptr<Sampler> create_default_sampler(int seed, int spp_override = 0);

} // namespace caustica
