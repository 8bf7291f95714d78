#include "sampler/sampler_factory.h"

#include "sampler/halton_sampler.h"
#include "sampler/independent_sampler.h"
#include "sampler/padded_sobol_sampler.h"
#include "sampler/pmj02bn_sampler.h"
#include "sampler/sobol_sampler.h"
#include "sampler/stratified_sampler.h"
#include "sampler/zsobol_sampler.h"

#include <bit>

namespace caustica {

namespace {

int positive_count(const ParameterDictionary &params, const std::string &name, int def) {
    int n = params.get_one_int(name, def);
    if (n < 1)
        throw InputError(params.location(name),
                         "\"" + name + "\" must be at least 1, got " + std::to_string(n));
    return n;
}

Randomization randomization_parameter(const ParameterDictionary &params, const std::string &def) {
    std::string name = params.get_one_string("randomization", def);
    std::optional<Randomization> r = parse_randomization(name);
    if (!r)
        throw InputError(params.location("randomization"),
                         "\"" + name + "\": unknown randomization (expected \"owen\", \"fastowen\", "
                         "\"permutedigits\" or \"none\")");
    return *r;
}

// zsobol's pixel blocks are 2^k samples long; with fewer, each pixel uses the first spp points
// of its block, which are less evenly spread than a whole block. The warning points at the
// directive, or at nothing when the count came from the command line.
void warn_if_not_power_of_two(const SourceLocation *loc, int spp) {
    if (std::has_single_bit(uint32_t(spp))) return;
    std::string message = "the \"zsobol\" sampler stratifies best with a power-of-two sample "
                          "count; " + std::to_string(spp) + " samples per pixel are the first " +
                          std::to_string(spp) + " of " + std::to_string(std::bit_ceil(uint32_t(spp)));
    if (loc)
        warning(*loc, message);
    else
        warning(message);
}

} // namespace

std::unique_ptr<Sampler> create_sampler(const std::string &type, const ParameterDictionary &params,
                                        const SourceLocation &loc, int seed, int spp_override,
                                        Vec2i resolution) {
    seed = params.get_one_int("seed", seed);
    if (type == "independent") {
        int spp = spp_override > 0 ? spp_override : positive_count(params, "pixelsamples", 4);
        return std::make_unique<IndependentSampler>(spp, seed);
    }
    if (type == "stratified") {
        bool jitter = params.get_one_bool("jitter", true);
        int xs = positive_count(params, "xsamples", 4);
        int ys = positive_count(params, "ysamples", 4);
        if (spp_override > 0) {
            Vec2i grid = stratified_grid(spp_override);
            xs = grid.x;
            ys = grid.y;
        }
        return std::make_unique<StratifiedSampler>(xs, ys, jitter, seed);
    }
    if (type == "halton") {
        int spp = spp_override > 0 ? spp_override : positive_count(params, "pixelsamples", 16);
        Randomization randomization = randomization_parameter(params, "permutedigits");
        if (randomization == Randomization::FastOwen)
            throw InputError(params.location("randomization"),
                             "\"fastowen\" randomization is not supported by the halton sampler (as in pbrt-v4)");
        return std::make_unique<HaltonSampler>(spp, resolution, seed, randomization);
    }
    if (type == "pmj02bn") {
        int spp = spp_override > 0 ? spp_override : positive_count(params, "pixelsamples", 16);
        if (!std::has_single_bit(uint32_t(spp)) || std::countr_zero(uint32_t(spp)) % 2 != 0) {
            std::string message = "the \"pmj02bn\" sampler stratifies best with a power-of-4 sample count "
                                  "(1, 4, 16, 64, ...), not " + std::to_string(spp);
            if (spp_override > 0)
                warning(message);
            else
                warning(loc, message);
        }
        return std::make_unique<Pmj02bnSampler>(spp, seed);
    }
    if (type == "zsobol" || type == "paddedsobol" || type == "sobol") {
        int spp = spp_override > 0 ? spp_override : positive_count(params, "pixelsamples", 16);
        // pbrt-v4's default is fastowen.
        Randomization randomization = randomization_parameter(params, "fastowen");
        if (type == "paddedsobol") return std::make_unique<PaddedSobolSampler>(spp, seed, randomization);
        if (type == "sobol") return std::make_unique<SobolSampler>(spp, seed, randomization);
        warn_if_not_power_of_two(spp_override > 0 ? nullptr : &loc, spp);
        return std::make_unique<ZSobolSampler>(spp, seed, randomization);
    }
    throw InputError(loc, "\"" + type + "\": unknown sampler type");
}

std::unique_ptr<Sampler> create_default_sampler(int seed, int spp_override) {
    int spp = spp_override > 0 ? spp_override : 16;
    warn_if_not_power_of_two(nullptr, spp);
    return std::make_unique<ZSobolSampler>(spp, seed, Randomization::FastOwen);
}

} // namespace caustica
