// Creates the sampler a scene's Sampler directive asks for (pbrt-v4 names and parameters).
#pragma once

#include "core/error.h"
#include "params/parameters.h"
#include "sampler/sampler.h"

#include <memory>
#include <string>

namespace caustica {

// Implemented: "independent" ("pixelsamples", default 4), "stratified" ("xsamples",
// "ysamples", default 4 each, "jitter", default true), "zsobol", "paddedsobol" and "sobol"
// ("pixelsamples", default 16; "randomization": "none", "permutedigits", "fastowen" or "owen",
// default "fastowen" as in pbrt-v4). "halton" and "pmj02bn" are replaced, with a warning, by
// "zsobol" with the same sample count (and halton's randomization when given, whose names
// zsobol shares; as in pbrt, halton rejects "fastowen"). zsobol warns about sample counts that
// are not powers of two. The "seed" parameter overrides `seed`; spp_override > 0 (the command
// line) replaces the sample count. Unknown types, unknown randomizations and non-positive
// sample counts are InputErrors.
// `resolution` is the film's (the halton sampler tiles the image with it).
std::unique_ptr<Sampler> create_sampler(const std::string &type, const ParameterDictionary &params,
                                        const SourceLocation &loc, int seed, int spp_override = 0,
                                        Vec2i resolution = {1280, 720});

// What a scene without a Sampler directive renders with, as in pbrt-v4: "zsobol" with its
// default randomization (fastowen) and 16 samples per pixel.
std::unique_ptr<Sampler> create_default_sampler(int seed, int spp_override = 0);

} // namespace caustica
