// Helpers for whole-renderer tests: run the caustica command and read the images it writes.
#pragma once

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace caustica::testing {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<float> rgb; // interleaved, row-major, top row first
    float at(int x, int y, int c) const { return rgb[(size_t(y) * width + x) * 3 + c]; }
};

inline RgbImage read_rgb(const std::string &path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec &spec = in->spec();
    RgbImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.rgb.resize(size_t(spec.width) * spec.height * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, img.rgb.data()))
        throw std::runtime_error("cannot read " + path);
    return img;
}

// The layer of an EXR whose channels are named prefix.R, prefix.G, prefix.B (e.g. the
// "variance" layer of `caustica render --variance`).
inline RgbImage read_layer(const std::string &path, const std::string &prefix) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec &spec = in->spec();
    RgbImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.rgb.resize(size_t(spec.width) * spec.height * 3);
    const char *suffix[3] = {".R", ".G", ".B"};
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read " + path);
    for (int c = 0; c < 3; ++c) {
        int channel = spec.channelindex(prefix + suffix[c]);
        if (channel < 0) throw std::runtime_error(path + " has no channel " + prefix + suffix[c]);
        for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
            img.rgb[i * 3 + c] = all[i * spec.nchannels + channel];
    }
    return img;
}

inline std::string data_path(const std::string &relative) {
    return std::string(CAUSTICA_TEST_DATA) + "/" + relative;
}

// The scratch directories this process made, removed when it exits if every test it ran passed;
// a failed test's outputs stay to be looked at. (ctest runs each test in a process of its own.)
struct ScratchDirectories {
    std::vector<std::filesystem::path> paths;
    ~ScratchDirectories() {
        if (!::testing::UnitTest::GetInstance()->Passed()) return;
        std::error_code ignored;
        for (const std::filesystem::path &p : paths) std::filesystem::remove_all(p, ignored);
    }
};
inline ScratchDirectories &scratch_directories() {
    static ScratchDirectories directories;
    return directories;
}

// A fresh directory for one test's outputs, unique to the process so that concurrent test runs
// (ctest -j, or two checkouts tested at once) never share one.
inline std::string scratch_dir(const std::string &name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("caustica-test-" + name + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    scratch_directories().paths.push_back(dir);
    return dir.string();
}

// Runs `caustica ARGS`, returns its exit status; stderr goes to stderr_path when given, and
// environment (e.g. "NAME=value") is prefixed to the command.
inline int run_caustica(const std::string &args, const std::string &stderr_path = "",
                        const std::string &environment = "") {
    std::string cmd = environment + (environment.empty() ? "" : " ") + std::string(CAUSTICA_BINARY) + " " +
                      args + " > /dev/null";
    cmd += stderr_path.empty() ? " 2>/dev/null" : " 2>" + stderr_path;
    int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::string &path) {
    std::FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    std::string s;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
    return s;
}

// Mean of channel c over the block [x0, x0+size) x [y0, y0+size).
inline double block_mean(const RgbImage &img, int x0, int y0, int size, int c) {
    double sum = 0;
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x) sum += img.at(x, y, c);
    return sum / (size * size);
}

// Per block and channel: the block mean of (A + B) / 2, the unbiased 1-degree-of-freedom
// estimate D^2 / 4 of its variance from the block means' difference D = mean(A) - mean(B), and
// the estimate from the per-pixel differences, sum_i (A_i - B_i)^2 / 4 / n^2 over the block's n
// pixels, which is exact in expectation only when the pixels' errors are independent.
struct BlockEstimate {
    double mean = 0, variance_from_blocks = 0, variance_from_pixels = 0;
};

inline std::vector<BlockEstimate> block_estimates(const RgbImage &a, const RgbImage &b, int block) {
    std::vector<BlockEstimate> blocks;
    for (int by = 0; by + block <= a.height; by += block)
        for (int bx = 0; bx + block <= a.width; bx += block)
            for (int c = 0; c < 3; ++c) {
                BlockEstimate e;
                double difference = 0;
                for (int y = by; y < by + block; ++y)
                    for (int x = bx; x < bx + block; ++x) {
                        double va = a.at(x, y, c), vb = b.at(x, y, c);
                        e.mean += (va + vb) / 2;
                        difference += va - vb;
                        e.variance_from_pixels += (va - vb) * (va - vb) / 4;
                    }
                const double n = block * block;
                e.mean /= n;
                difference /= n;
                e.variance_from_blocks = difference * difference / 4;
                e.variance_from_pixels /= n * n;
                blocks.push_back(e);
            }
    return blocks;
}

// The correlation factor k of an image pair: the average over its block-channels of the
// block-level variance estimate over the per-pixel one, at least 1. Splats (light tracing,
// connections to the lens) and merges (photons shared by neighbouring pixels, wavelength groups
// shared across the image) correlate neighbouring pixels' errors, which the per-pixel estimate
// ignores; each term is k times a one-degree-of-freedom chi-square over its mean, so the average
// of n terms is within about sqrt(2 / n) of k.
inline double correlation_factor(const std::vector<BlockEstimate> &blocks) {
    double sum = 0;
    int count = 0;
    for (const BlockEstimate &e : blocks)
        if (e.variance_from_pixels > 0) {
            sum += e.variance_from_blocks / e.variance_from_pixels;
            ++count;
        }
    return count > 0 ? std::max(1.0, sum / count) : 1.0;
}

// The mean over all pixels and channels of (A + B) / 2.
inline double image_mean(const RgbImage &a, const RgbImage &b) {
    double sum = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sum += (a.rgb[i] + b.rgb[i]) / 2;
    return sum / double(a.rgb.size());
}

// One scene rendered by one integrator at spp samples per pixel (iterations for lt, sppm, bpm and
// vcm): a case of the agreement suites.
struct RenderCase {
    const char *scene;
    const char *integrator;
    int spp;
};

// A gtest name for a case: scene_integrator, without the scene's folder and with its dashes made
// underscores.
inline std::string case_name(const RenderCase &c) {
    const std::string scene = c.scene;
    std::string name = scene.substr(scene.find_last_of('/') + 1) + "_" + c.integrator;
    for (char &ch : name)
        if (ch == '-') ch = '_';
    return name;
}
inline std::string witness_case_name(const ::testing::TestParamInfo<RenderCase> &info) {
    return case_name(info.param);
}

// The suites that render scenes in several integrators against pbrt-v4's image of the same file
// (lights, heterogeneous media, motion blur, alpha cut-outs) each instantiate this fixture with
// their cases: INSTANTIATE_TEST_SUITE_P(Suite, PbrtWitness, ::testing::Values(...), witness_case_name).
// Its one test, expect_agreement_with_pbrt, is in pbrt_witness_test.cpp.
class PbrtWitness : public ::testing::TestWithParam<RenderCase> {};

// Two renders of one scene by one integrator with seeds seed and seed + 1, into dir;
// environment (e.g. "CAUSTICA_TEST_FAULT=...") is set for the command.
struct RenderPair {
    RgbImage runs[2];
};

inline RenderPair render_pair(const std::string &scene_path, const std::string &integrator, int spp, int seed,
                              const std::string &dir, const std::string &environment = "") {
    RenderPair pair;
    for (int i = 0; i < 2; ++i) {
        const std::string out = dir + "/run" + std::to_string(i) + ".exr";
        const std::string args = "render " + scene_path + " --quiet --integrator " + integrator + " --spp " +
                                 std::to_string(spp) + " --seed " + std::to_string(seed + i) + " -o " + out;
        if (run_caustica(args, "", environment) != 0) throw std::runtime_error("caustica " + args + " failed");
        pair.runs[i] = read_rgb(out);
    }
    return pair;
}

struct PbrtAgreement {
    double mean_relative_error = 0;
    double mean_standard_error = 0; // of the renders' image mean, relative to the reference's
    double worst_z = 0;
    bool passes() const { return mean_relative_error < 0.01 && worst_z < 5.0; }
};

inline constexpr int kPbrtBlock = 16;

// The reference's two halves, from its mean and half-difference layers.
inline std::pair<RgbImage, RgbImage> reference_halves(const std::string &scene) {
    const std::string path = data_path("pbrt-v4/" + scene + ".exr");
    RgbImage plus = read_rgb(path), minus = plus;
    const RgbImage difference = read_layer(path, "difference");
    for (size_t i = 0; i < plus.rgb.size(); ++i) {
        plus.rgb[i] += difference.rgb[i];
        minus.rgb[i] -= difference.rgb[i];
    }
    return {plus, minus};
}

// `scene` (e.g. "hard/fog-point") names scenes/SCENE.pbrt and its pbrt-v4 reference
// tests/data/pbrt-v4/SCENE.exr (scripts/make-pbrt-references.sh). The check is the one that
// hard_transport_test.cpp states: image mean within 1%, every 16x16 block-channel |z| < 5.
inline PbrtAgreement pbrt_agreement(const std::string &scene, const std::string &integrator, int spp,
                                    const std::string &fault = "") {
    std::string flat = scene;
    for (char &ch : flat)
        if (ch == '/') ch = '-';
    const std::string dir = scratch_dir("pbrt-" + flat + "-" + integrator + (fault.empty() ? "" : "-" + fault));
    const std::string environment = fault.empty() ? "" : "CAUSTICA_TEST_FAULT=" + fault;
    const RenderPair pair = render_pair(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + scene + ".pbrt",
                                        integrator, spp, 31, dir, environment);
    const RgbImage(&runs)[2] = pair.runs;
    const auto [ref_a, ref_b] = reference_halves(scene);
    EXPECT_EQ(runs[0].width, ref_a.width);
    EXPECT_EQ(runs[0].height, ref_a.height);

    PbrtAgreement result;
    const double mean = image_mean(runs[0], runs[1]), reference_mean = image_mean(ref_a, ref_b);
    result.mean_relative_error = std::abs(mean - reference_mean) / reference_mean;

    const std::vector<BlockEstimate> blocks = block_estimates(runs[0], runs[1], kPbrtBlock);
    const std::vector<BlockEstimate> reference = block_estimates(ref_a, ref_b, kPbrtBlock);
    const double k = correlation_factor(blocks), k_ref = correlation_factor(reference);
    double mean_variance = 0; // the image mean is the average of the block-channel means
    size_t worst = 0;
    for (size_t i = 0; i < blocks.size(); ++i) {
        const double var = k * blocks[i].variance_from_pixels + k_ref * reference[i].variance_from_pixels;
        const double z = std::abs(blocks[i].mean - reference[i].mean) / std::sqrt(var + 1e-30);
        if (z > result.worst_z) worst = i;
        result.worst_z = std::max(result.worst_z, z);
        mean_variance += k * blocks[i].variance_from_pixels;
    }
    result.mean_standard_error = std::sqrt(mean_variance) / double(blocks.size()) / reference_mean;
    std::printf("%s %s%s: mean %.5f against pbrt-v4's %.5f (error %.2f%%, standard error %.2f%%), k %.2f, "
                "k_ref %.2f, largest |z| %.2f (block-channel %zu: %.5g against %.5g)\n",
                scene.c_str(), integrator.c_str(), fault.empty() ? "" : (" with fault " + fault).c_str(), mean, reference_mean,
                100 * result.mean_relative_error, 100 * result.mean_standard_error, k, k_ref, result.worst_z, worst,
                blocks[worst].mean, reference[worst].mean);
    return result;
}

// The check as gtest expectations.
inline void expect_agreement_with_pbrt(const std::string &scene, const std::string &integrator, int spp) {
    const PbrtAgreement a = pbrt_agreement(scene, integrator, spp);
    EXPECT_LT(a.mean_relative_error, 0.01) << scene << " " << integrator;
    EXPECT_LT(a.worst_z, 5.0) << scene << " " << integrator;
}

} // namespace caustica::testing
