#include "sampler/sampler_factory.h"

#include "sampler/independent_sampler.h"
#include "sampler/stratified_sampler.h"

namespace caustica {

namespace {

int positive_count(const ParameterDictionary &params, const std::string &name, int def) {
    int n = params.get_one_int(name, def);
    if (n < 1)
        throw InputError(params.location(name),
                         "\"" + name + "\" must be at least 1, got " + std::to_string(n));
    return n;
}

bool is_low_discrepancy(const std::string &type) {
    return type == "halton" || type == "sobol" || type == "paddedsobol" || type == "zsobol" ||
           type == "pmj02bn";
}

} // namespace

std::unique_ptr<Sampler> create_sampler(const std::string &type, const ParameterDictionary &params,
                                        const SourceLocation &loc, int seed, int spp_override) {
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
    if (is_low_discrepancy(type)) {
        int spp = spp_override > 0 ? spp_override : positive_count(params, "pixelsamples", 16);
        // The scrambling choice only means something for the sampler being replaced.
        params.get_one_string("randomization", "");
        warning(loc, "the \"" + type + "\" sampler is not implemented yet (low-discrepancy "
                     "samplers arrive later); using a jittered stratified sampler with the same " +
                         std::to_string(spp) + " samples per pixel");
        Vec2i grid = stratified_grid(spp);
        return std::make_unique<StratifiedSampler>(grid.x, grid.y, true, seed);
    }
    throw InputError(loc, "\"" + type + "\": unknown sampler type");
}

std::unique_ptr<Sampler> create_default_sampler(int seed, int spp_override) {
    Vec2i grid = stratified_grid(spp_override > 0 ? spp_override : 16);
    return std::make_unique<StratifiedSampler>(grid.x, grid.y, true, seed);
}

} // namespace caustica
