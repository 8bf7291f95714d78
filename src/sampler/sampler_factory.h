// Creates the sampler a scene's Sampler directive asks for (pbrt-v4 names and parameters).
#pragma once

#include "core/error.h"
#include "params/parameters.h"
#include "sampler/sampler.h"

#include <memory>
#include <string>

namespace caustica {

// pbrt-v4's samplers: "independent" ("pixelsamples", default 4), "stratified" ("xsamples",
// "ysamples", default 4 each, "jitter", default true), "zsobol", "paddedsobol" and "sobol"
// ("pixelsamples", default 16; "randomization": "none", "permutedigits", "fastowen" or "owen",
// default "fastowen" as in pbrt-v4), "halton" ("pixelsamples", default 16; "randomization"
// default "permutedigits"; as in pbrt-v4 it rejects "fastowen") and "pmj02bn" ("pixelsamples",
// default 16). zsobol warns about sample counts that are not powers of two, and pmj02bn about
// counts that are not powers of 4, as pbrt-v4 does. The "seed" parameter overrides `seed`;
// spp_override > 0 (the command line) replaces the sample count. Unknown types, unknown
// randomizations and non-positive sample counts are InputErrors.
// `resolution` is the film's (the halton sampler tiles the image with it).
std::unique_ptr<Sampler> create_sampler(const std::string &type, const ParameterDictionary &params,
                                        const SourceLocation &loc, int seed, int spp_override = 0,
                                        Vec2i resolution = {1280, 720});

// What a scene without a Sampler directive renders with, as in pbrt-v4: "zsobol" with its
// default randomization (fastowen) and 16 samples per pixel.
std::unique_ptr<Sampler> create_default_sampler(int seed, int spp_override = 0);

} // namespace caustica
