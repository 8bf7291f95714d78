#include "cli/merge_command.h"

#include "cli/commands.h"
#include "core/error.h"
#include "film/image_io.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <set>

namespace caustica {

namespace {

// The names of the layers every input has.
std::vector<std::string> common_layers(const std::vector<MergeInput> &inputs) {
    std::vector<std::string> common;
    for (const Image::Layer &layer : inputs[0].image.layers) {
        bool everywhere = true;
        for (const MergeInput &in : inputs) {
            bool has = std::any_of(in.image.layers.begin(), in.image.layers.end(),
                                   [&](const Image::Layer &l) { return l.name == layer.name; });
            everywhere = everywhere && has;
        }
        if (everywhere) common.push_back(layer.name);
        else warning("layer \"" + layer.name + "\" is not in every input; it is left out of the merge");
    }
    return common;
}

const std::vector<float> &layer_of(const Image &image, const std::string &name) {
    for (const Image::Layer &l : image.layers)
        if (l.name == name) return l.rgb;
    throw std::logic_error("no layer " + name);
}

} // namespace

MergeResult merge_images(const std::vector<MergeInput> &inputs) {
    if (inputs.empty()) throw InputError("merge: no input images");
    const Vec2i frame = inputs[0].image.full_resolution;
    Vec2i lo = inputs[0].image.origin, hi = lo;
    for (const MergeInput &in : inputs) {
        if (in.image.full_resolution != frame)
            throw InputError("merge: \"" + in.name + "\" is of a " + std::to_string(in.image.full_resolution.x) +
                             "x" + std::to_string(in.image.full_resolution.y) + " frame, \"" + inputs[0].name +
                             "\" of a " + std::to_string(frame.x) + "x" + std::to_string(frame.y) + " one");
        if (!(in.samples_per_pixel > 0))
            throw InputError("merge: \"" + in.name + "\" has no positive sample count");
        lo = {std::min(lo.x, in.image.origin.x), std::min(lo.y, in.image.origin.y)};
        hi = {std::max(hi.x, in.image.origin.x + in.image.width), std::max(hi.y, in.image.origin.y + in.image.height)};
    }
    const std::vector<std::string> layers = common_layers(inputs);

    MergeResult result;
    Image &out = result.image;
    out = Image(hi.x - lo.x, hi.y - lo.y);
    out.origin = lo;
    out.full_resolution = frame;
    for (const std::string &name : layers) out.layers.push_back({name, std::vector<float>(out.rgb.size(), 0.f)});
    std::vector<double> weight(size_t(out.width) * out.height, 0.0);
    std::vector<double> sum(out.rgb.size(), 0.0);
    std::vector<std::vector<double>> layer_sums(layers.size(), std::vector<double>(out.rgb.size(), 0.0));
    for (const MergeInput &in : inputs) {
        const double w = in.samples_per_pixel;
        std::vector<const std::vector<float> *> values;
        for (const std::string &name : layers) values.push_back(&layer_of(in.image, name));
        for (int y = 0; y < in.image.height; ++y)
            for (int x = 0; x < in.image.width; ++x) {
                const size_t src = size_t(y) * in.image.width + x;
                const size_t dst = size_t(y + in.image.origin.y - lo.y) * out.width + (x + in.image.origin.x - lo.x);
                weight[dst] += w;
                for (int c = 0; c < 3; ++c) sum[dst * 3 + c] += w * in.image.rgb[src * 3 + c];
                for (size_t l = 0; l < layers.size(); ++l) {
                    const double factor = layers[l] == "variance" ? w * w : w;
                    for (int c = 0; c < 3; ++c) layer_sums[l][dst * 3 + c] += factor * (*values[l])[src * 3 + c];
                }
            }
    }
    result.min_samples = std::numeric_limits<double>::infinity();
    for (size_t p = 0; p < weight.size(); ++p) {
        const double w = weight[p];
        if (w == 0) {
            ++result.uncovered_pixels;
            continue;
        }
        result.min_samples = std::min(result.min_samples, w);
        result.max_samples = std::max(result.max_samples, w);
        for (int c = 0; c < 3; ++c) out.rgb[p * 3 + c] = float(sum[p * 3 + c] / w);
        for (size_t l = 0; l < layers.size(); ++l) {
            const double norm = layers[l] == "variance" ? w * w : w;
            for (int c = 0; c < 3; ++c) out.layers[l].rgb[p * 3 + c] = float(layer_sums[l][p * 3 + c] / norm);
        }
    }
    if (result.uncovered_pixels > 0) result.min_samples = 0;
    return result;
}

int run_merge(const MergeCommandOptions &options) {
    if (options.output_path.empty()) throw InputError("merge: an output image (-o) is needed");
    std::vector<MergeInput> inputs;
    std::map<std::string, std::string> first_metadata;
    for (const std::string &path : options.input_paths) {
        MergeInput in;
        in.name = path;
        std::map<std::string, std::string> metadata;
        try {
            in.image = read_exr(path, &metadata);
        } catch (const std::runtime_error &e) {
            throw InputError(e.what());
        }
        auto spp = metadata.find("caustica:spp");
        if (spp == metadata.end())
            throw InputError("merge: \"" + path + "\" has no \"caustica:spp\" attribute (it was not written by "
                             "caustica render), so its weight is unknown");
        try {
            in.samples_per_pixel = std::stod(spp->second);
        } catch (const std::exception &) {
            throw InputError("merge: \"" + path + "\": \"caustica:spp\" is not a number");
        }
        if (inputs.empty()) first_metadata = metadata;
        inputs.push_back(std::move(in));
    }
    MergeResult merged = merge_images(inputs);
    if (merged.uncovered_pixels > 0)
        warning("merge: " + std::to_string(merged.uncovered_pixels) +
                " pixels of the merged region are in no input; they are black");
    std::map<std::string, std::string> metadata;
    for (const char *key : {"caustica:integrator", "caustica:scene"})
        if (first_metadata.count(key)) metadata[key] = first_metadata[key];
    // The samples behind every pixel when that is one number; otherwise the fewest, and a flag.
    metadata["caustica:spp"] = std::to_string(int64_t(merged.min_samples));
    if (merged.max_samples != merged.min_samples) metadata["caustica:spp-varies"] = "true";
    metadata["caustica:merged"] = std::to_string(inputs.size()) + " images";
    write_exr(options.output_path, merged.image, metadata);
    std::printf("merged %zu images into %s: %dx%d pixels at (%d, %d) of a %dx%d frame, %g to %g samples per pixel\n",
                inputs.size(), options.output_path.c_str(), merged.image.width, merged.image.height,
                merged.image.origin.x, merged.image.origin.y, merged.image.full_resolution.x,
                merged.image.full_resolution.y, merged.min_samples, merged.max_samples);
    return 0;
}

} // namespace caustica
