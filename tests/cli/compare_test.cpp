// `caustica compare`: the files it writes, what they say, its input errors, its error estimates
// and agreement check without a reference, the report as a browser shows it, the "first to
// reach" table, and the error colour map and plot it draws with. The statistics themselves are
// tested on synthetic images in render_agreement_test.cpp.
#include "../integrators/render_test_support.h"

#include "cli/compare_report.h"
#include "cli/convergence_plot.h"
#include "cli/error_colour_map.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace caustica::testing;
namespace fs = std::filesystem;

namespace {

const std::string kCornell = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";
const std::vector<std::string> kIntegrators = {"pt", "bdpt"};
constexpr double kTimeLimit = 0.5;

// The budgets the command documents: T/16, T/8, T/4, T/2, T, named with printf's %g.
std::vector<std::string> budget_names() {
    std::vector<std::string> names;
    for (int k = 4; k >= 0; --k) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", kTimeLimit / (1 << k));
        names.push_back(buf);
    }
    return names;
}

// Runs `caustica ARGS` with stdout to `stdout_path`; the exit status.
int run_with_stdout(const std::string &args, const std::string &stdout_path) {
    std::string cmd = std::string(CAUSTICA_BINARY) + " " + args + " > " + stdout_path + " 2>/dev/null";
    int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::vector<std::string>> read_csv(const std::string &path) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(read_text(path));
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream fields(line);
        std::string cell;
        while (std::getline(fields, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

// A strict JSON syntax check (RFC 8259 grammar; numbers, strings with escapes, literals),
// enough to know that a JSON parser will accept the file.
class JsonChecker {
  public:
    explicit JsonChecker(const std::string &text) : s_(text) {}
    bool valid() {
        skip_space();
        if (!value()) return false;
        skip_space();
        return i_ == s_.size();
    }

  private:
    const std::string &s_;
    size_t i_ = 0;
    void skip_space() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
    }
    bool literal(const char *word) {
        size_t n = std::strlen(word);
        if (s_.compare(i_, n, word) != 0) return false;
        i_ += n;
        return true;
    }
    bool string() {
        if (s_[i_] != '"') return false;
        for (++i_; i_ < s_.size(); ++i_) {
            unsigned char c = s_[i_];
            if (c == '"') {
                ++i_;
                return true;
            }
            if (c < 0x20) return false;
            if (c == '\\') {
                if (++i_ >= s_.size()) return false;
                if (s_[i_] == 'u') {
                    for (int k = 0; k < 4; ++k)
                        if (++i_ >= s_.size() || !std::isxdigit((unsigned char)s_[i_])) return false;
                } else if (!std::strchr("\"\\/bfnrt", s_[i_])) {
                    return false;
                }
            }
        }
        return false;
    }
    bool number() {
        size_t start = i_;
        if (s_[i_] == '-') ++i_;
        if (i_ >= s_.size() || !std::isdigit((unsigned char)s_[i_])) return false;
        if (s_[i_] == '0') ++i_;
        else
            while (i_ < s_.size() && std::isdigit((unsigned char)s_[i_])) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            if (i_ >= s_.size() || !std::isdigit((unsigned char)s_[i_])) return false;
            while (i_ < s_.size() && std::isdigit((unsigned char)s_[i_])) ++i_;
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (i_ >= s_.size() || !std::isdigit((unsigned char)s_[i_])) return false;
            while (i_ < s_.size() && std::isdigit((unsigned char)s_[i_])) ++i_;
        }
        return i_ > start;
    }
    bool value() {
        if (i_ >= s_.size()) return false;
        char c = s_[i_];
        if (c == '{' || c == '[') {
            const char close = c == '{' ? '}' : ']';
            ++i_;
            skip_space();
            if (i_ < s_.size() && s_[i_] == close) return ++i_, true;
            while (true) {
                skip_space();
                if (c == '{') {
                    if (i_ >= s_.size() || !string()) return false;
                    skip_space();
                    if (i_ >= s_.size() || s_[i_++] != ':') return false;
                    skip_space();
                }
                if (!value()) return false;
                skip_space();
                if (i_ >= s_.size()) return false;
                if (s_[i_] == ',') {
                    ++i_;
                    continue;
                }
                if (s_[i_] != close) return false;
                ++i_;
                return true;
            }
        }
        if (c == '"') return string();
        if (c == 't') return literal("true");
        if (c == 'f') return literal("false");
        if (c == 'n') return literal("null");
        return number();
    }
};

// Relative MSE as `caustica diff` defines it (README): mean over pixels and channels of
// (x - r)^2 / (r^2 + 0.01), computed here from the files.
double relative_mse(const RgbImage &image, const RgbImage &reference) {
    double sum = 0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        double x = image.rgb[i], r = reference.rgb[i];
        sum += (x - r) * (x - r) / (r * r + 0.01);
    }
    return sum / double(image.rgb.size());
}

// The relative MSE of the average of two renders as the command estimates it (README): mean
// over pixels and channels of h^2 / (m^2 + 0.01), m = (a + b) / 2 and h = (a - b) / 2,
// computed here from the two renders' files.
double estimated_relative_mse(const RgbImage &a, const RgbImage &b) {
    double sum = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        double m = 0.5 * (double(a.rgb[i]) + b.rgb[i]), h = 0.5 * (double(a.rgb[i]) - b.rgb[i]);
        sum += h * h / (m * m + 0.01);
    }
    return sum / double(a.rgb.size());
}

// The header row's column indices by name.
std::map<std::string, size_t> columns(const std::vector<std::string> &header) {
    std::map<std::string, size_t> column;
    for (size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
    return column;
}

// Every image (32x32) and report file the command documents, and a summary naming the reference.
void expect_every_image_and_report_file(const std::string &dir, const std::string &out, const std::string &reference) {
    for (const char *file : {"convergence.csv", "results.json", "convergence.svg", "index.html",
                             "images/reference.png"})
        EXPECT_TRUE(fs::is_regular_file(out + "/" + file)) << file;
    for (const std::string &integrator : kIntegrators)
        for (const std::string &budget : budget_names()) {
            std::string stem = out + "/images/" + integrator + "-" + budget + "s";
            for (const char *suffix : {".exr", ".png", "-error.png", "-a.exr", "-b.exr"}) {
                ASSERT_TRUE(fs::is_regular_file(stem + suffix)) << stem + suffix;
                RgbImage image = read_rgb(stem + suffix);
                EXPECT_EQ(image.width, 32);
                EXPECT_EQ(image.height, 32);
            }
        }
    std::string summary = read_text(dir + "/stdout.txt");
    EXPECT_NE(summary.find("reference: reference image " + reference), std::string::npos) << summary;
    EXPECT_NE(summary.find("agreement at the longest budget:\n  "), std::string::npos) << summary;
    EXPECT_NE(summary.find("first to reach a relative MSE"), std::string::npos) << summary;
    EXPECT_NE(summary.find("index.html"), std::string::npos) << summary;
}

// One CSV row per (integrator, budget); the relative MSE it reports is the one computed here
// from the EXRs, and so is the estimate from the two renders, whose average the run's image is;
// pt's error falls from the shortest to the longest budget.
//
// Why the fall is reliable: pt renders this 32x32 scene at roughly 5e5 samples/s, so the 1/32 s
// budget (two renders of 1/64 s) gets some 10-20 spp and the 0.5 s budget some 150-300 (16
// times the time; a render always completes at least 1 spp). With the same seeds the longer
// budget's samples include the shorter one's, and against the independent 512-spp reference the
// expected relative MSE goes as V/n + V/512: the longest run's is about a tenth of the
// shortest's. The measured value is a mean over 3072 pixel channels, whose spread is a few
// percent of it, so the order can only flip if the long renders got less than about a tenth of
// the processor time per second that the short ones did.
void expect_csv_rows_and_path_tracing_convergence(const std::string &out, const std::string &reference_path) {
    auto rows = read_csv(out + "/convergence.csv");
    ASSERT_FALSE(rows.empty());
    std::map<std::string, size_t> column = columns(rows[0]);
    for (const char *name : {"integrator", "budget_seconds", "seconds", "samples_per_pixel", "relative_mse", "rmse",
                             "estimated_relative_mse", "rays", "non_finite_samples", "image", "render_a", "render_b"})
        ASSERT_TRUE(column.count(name)) << name;
    ASSERT_EQ(rows.size(), 1 + kIntegrators.size() * budget_names().size());

    RgbImage reference = read_rgb(reference_path);
    std::set<std::pair<std::string, double>> seen;
    std::map<std::string, std::vector<double>> relmse_by_integrator;
    for (size_t r = 1; r < rows.size(); ++r) {
        const auto &row = rows[r];
        ASSERT_EQ(row.size(), rows[0].size());
        std::string integrator = row[column["integrator"]];
        double budget = std::stod(row[column["budget_seconds"]]);
        EXPECT_TRUE(seen.insert({integrator, budget}).second) << "duplicate row " << r;
        EXPECT_GT(std::stod(row[column["seconds"]]), 0);
        EXPECT_GE(std::stoi(row[column["samples_per_pixel"]]), 1);
        EXPECT_GT(std::stoull(row[column["rays"]]), 0u);
        double relmse = std::stod(row[column["relative_mse"]]);
        RgbImage image = read_rgb(out + "/" + row[column["image"]]);
        EXPECT_NEAR(relmse, relative_mse(image, reference), 1e-6 * relmse + 1e-12) << row[column["image"]];
        RgbImage a = read_rgb(out + "/" + row[column["render_a"]]), b = read_rgb(out + "/" + row[column["render_b"]]);
        double estimate = std::stod(row[column["estimated_relative_mse"]]);
        EXPECT_GT(estimate, 0) << row[column["image"]];
        EXPECT_NEAR(estimate, estimated_relative_mse(a, b), 1e-5 * estimate) << row[column["image"]];
        for (size_t i = 0; i < image.rgb.size(); ++i)
            ASSERT_FLOAT_EQ(image.rgb[i], 0.5f * (a.rgb[i] + b.rgb[i])) << row[column["image"]] << " value " << i;
        relmse_by_integrator[integrator].push_back(relmse);
    }
    for (const std::string &integrator : kIntegrators)
        for (const std::string &budget : budget_names())
            EXPECT_TRUE(seen.count({integrator, std::stod(budget)})) << integrator << " " << budget;
    const std::vector<double> &pt = relmse_by_integrator["pt"];
    ASSERT_EQ(pt.size(), 5u);
    EXPECT_LT(pt.back(), pt.front());
}

void expect_valid_results_json(const std::string &out) {
    std::string json = read_text(out + "/results.json");
    EXPECT_TRUE(JsonChecker(json).valid()) << json;
    size_t runs = 0;
    for (size_t at = json.find("\"budget_seconds\":"); at != std::string::npos;
         at = json.find("\"budget_seconds\":", at + 1))
        ++runs;
    EXPECT_EQ(runs, kIntegrators.size() * budget_names().size());
    for (const char *key : {"\"relative_mse\"", "\"rmse\"", "\"samples_per_pixel\"", "\"non_finite_samples\"",
                            "\"reference\"", "\"rays\"", "\"estimated_relative_mse\"", "\"agreement\"",
                            "\"first_to_reach\""})
        EXPECT_NE(json.find(key), std::string::npos) << key;
}

// One comparison of pt and bdpt on the Cornell box at 32x32 with T = 0.5 s against an
// independent pt reference (512 spp, another seed), shared by the tests below.
class Compare : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = scratch_dir("compare");
        out_ = dir_ + "/report";
        reference_ = dir_ + "/reference.exr";
        ASSERT_EQ(run_caustica("render " + kCornell + " --quiet --spp 512 --seed 7 --resolution 32x32 -o " +
                               reference_),
                  0);
        ASSERT_EQ(run_with_stdout("compare " + kCornell + " --integrators pt,bdpt --time 0.5 --resolution 32x32 "
                                  "--seed 1 --reference " + reference_ + " --out " + out_,
                                  dir_ + "/stdout.txt"),
                  0);
    }
    static inline std::string dir_, out_, reference_;
};

// The files, the data in them, and pt's convergence, checked in one test so that the
// comparison (a few seconds) runs once per process: ctest runs every test in its own.
TEST_F(Compare, WritesEveryFileWithConsistentData) {
    expect_every_image_and_report_file(dir_, out_, reference_);
    expect_csv_rows_and_path_tracing_convergence(out_, reference_);
    expect_valid_results_json(out_);
}

// The report as a browser shows it: headless Chromium loads index.html, the page's own check
// (every <img>, the plot included, decoded with a non-zero size) marks <body>, and a screenshot
// of it is a real picture, not a blank page.
TEST_F(Compare, ReportLoadsInABrowser) {
    if (std::system("command -v chromium > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it); the browser check is skipped";
    const std::string page = "file://" + fs::absolute(out_ + "/index.html").string();
    // Root (CI, containers) needs --no-sandbox; a private profile keeps runs apart.
    const std::string chromium = "timeout 120 chromium --headless --no-sandbox --disable-gpu "
                                 "--user-data-dir=" + dir_ + "/chromium-profile ";
    const std::string dom = dir_ + "/dom.html";
    ASSERT_EQ(std::system((chromium + "--dump-dom " + page + " > " + dom + " 2>/dev/null").c_str()), 0);
    // 1 reference + 1 plot + a render and its error image per run.
    const size_t images = 2 + 2 * kIntegrators.size() * budget_names().size();
    EXPECT_NE(read_text(dom).find("data-images=\"loaded " + std::to_string(images) + "\""), std::string::npos)
        << read_text(dom).substr(0, 2000);

    const std::string shot = dir_ + "/screenshot.png";
    ASSERT_EQ(std::system((chromium + "--screenshot=" + shot + " --window-size=1200,2000 " + page +
                           " > /dev/null 2>&1")
                              .c_str()),
              0);
    RgbImage screenshot = read_rgb(shot);
    EXPECT_EQ(screenshot.width, 1200);
    // Not a blank or text-only page: anti-aliased text gives at most 256 grey levels, while the
    // renders and the error images give thousands of distinct colours that are not grey.
    std::set<uint32_t> colours;
    for (size_t i = 0; i + 2 < screenshot.rgb.size(); i += 3) {
        uint32_t r = uint32_t(std::lround(screenshot.rgb[i] * 255)), g = uint32_t(std::lround(screenshot.rgb[i + 1] * 255)),
                 b = uint32_t(std::lround(screenshot.rgb[i + 2] * 255));
        if (r != g || g != b) colours.insert(r << 16 | g << 8 | b);
    }
    EXPECT_GT(colours.size(), 1000u);
}

TEST(CompareInput, BadInputExitsWithStatusTwoBeforeWritingAnything) {
    std::string dir = scratch_dir("compare-input");
    std::string reference = dir + "/reference.exr";
    ASSERT_EQ(run_caustica("render " + kCornell + " --quiet --spp 1 --resolution 16x16 -o " + reference), 0);
    const std::string base = "compare " + kCornell + " --time 0.1 --resolution 16x16 ";
    EXPECT_EQ(run_caustica(base + "--integrators pt,frobnicate --out " + dir + "/unknown"), 2);
    EXPECT_FALSE(fs::exists(dir + "/unknown"));
    EXPECT_EQ(run_caustica(base + "--integrators pt,path --out " + dir + "/twice"), 2);
    EXPECT_FALSE(fs::exists(dir + "/twice"));
    EXPECT_EQ(run_caustica("compare " + kCornell + " --time 0.1 --resolution 24x16 --integrators pt --reference " +
                           reference + " --out " + dir + "/size"),
              2);
    EXPECT_FALSE(fs::exists(dir + "/size"));
    EXPECT_EQ(run_caustica(base + "--integrators pt --reference " + dir + "/missing.exr --out " + dir + "/missing"),
              2);
    EXPECT_FALSE(fs::exists(dir + "/missing"));
    EXPECT_EQ(run_caustica(base + "--integrators pt --out " + dir + "/no-time --time 0"), 2);
    EXPECT_FALSE(fs::exists(dir + "/no-time"));

    // A Sampler "seed" would make each budget's two renders the same, and their difference zero.
    std::string scene = read_text(kCornell);
    const std::string sampler = "Sampler \"independent\" \"integer pixelsamples\" [ 64 ]";
    ASSERT_NE(scene.find(sampler), std::string::npos);
    scene.replace(scene.find(sampler), sampler.size(), sampler + " \"integer seed\" [ 3 ]");
    const std::string seeded = dir + "/seeded.pbrt";
    std::ofstream(seeded) << scene;
    EXPECT_EQ(run_caustica("compare " + seeded + " --time 0.1 --resolution 16x16 --integrators pt --out " + dir +
                               "/seeded",
                           dir + "/seeded.txt"),
              2);
    const std::string message = read_text(dir + "/seeded.txt");
    EXPECT_NE(message.find("seeded.pbrt:6:"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(dir + "/seeded"));
}

// An Integrator parameter that one integrator of the comparison reads is not reported unused
// because another ignores it; one that none reads is.
TEST(CompareInput, ReportsOnlyTheIntegratorParametersNoIntegratorRead) {
    const std::string dir = scratch_dir("compare-unused");
    std::string scene = read_text(kCornell);
    const std::string integrator = "Integrator \"path\"";
    ASSERT_NE(scene.find(integrator), std::string::npos);
    scene.replace(scene.find(integrator), integrator.size(),
                  "Integrator \"sppm\" \"integer photonsperiteration\" [ 2000 ] \"integer frobs\" [ 3 ]");
    const std::string path = dir + "/sppm-parameters.pbrt";
    std::ofstream(path) << scene;
    ASSERT_EQ(run_caustica("compare " + path + " --time 0.05 --resolution 8x8 --integrators pt,sppm --out " + dir +
                               "/out",
                           dir + "/stderr.txt"),
              0);
    const std::string warnings = read_text(dir + "/stderr.txt");
    EXPECT_NE(warnings.find("unused parameter \"integer frobs\""), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find("photonsperiteration"), std::string::npos) << warnings;
}

// Without --reference no run is the reference: every run's error is the one estimated from its
// two renders (positive, and what is computed here from their files), the summary says so and
// reports the agreement of pt's and bdpt's longest runs and the first to reach each error level.
TEST(CompareInput, WithoutReferenceEveryRunHasAnErrorEstimatedFromItsTwoRenders) {
    std::string dir = scratch_dir("compare-self");
    // The scene after --integrators's list is not read as a second integrator.
    ASSERT_EQ(run_with_stdout("compare --integrators pt,bdpt " + kCornell + " --time 0.125 --resolution 16x16 --out " +
                                  dir + "/out",
                              dir + "/stdout.txt"),
              0);
    std::string summary = read_text(dir + "/stdout.txt");
    EXPECT_NE(summary.find("reference: none given: each error is estimated from the difference of the budget's two "
                           "independent renders"),
              std::string::npos)
        << summary;
    EXPECT_EQ(summary.find("longest run"), std::string::npos) << summary;
    EXPECT_TRUE(summary.find("  agree: pt and bdpt differ by ") != std::string::npos ||
                summary.find("  DISAGREE: pt and bdpt differ by ") != std::string::npos)
        << summary;
    EXPECT_NE(summary.find("  <= 0.1: "), std::string::npos) << summary;
    EXPECT_EQ(read_text(dir + "/out/index.html").find("images/reference.png"), std::string::npos);

    auto rows = read_csv(dir + "/out/convergence.csv");
    ASSERT_EQ(rows.size(), 11u);
    std::map<std::string, size_t> column = columns(rows[0]);
    EXPECT_FALSE(column.count("is_reference"));
    ASSERT_TRUE(column.count("relative_mse") && column.count("estimated_relative_mse") && column.count("render_a") &&
                column.count("render_b"));
    for (size_t r = 1; r < rows.size(); ++r) {
        double relmse = std::stod(rows[r][column["relative_mse"]]);
        EXPECT_GT(relmse, 0) << r;
        EXPECT_EQ(relmse, std::stod(rows[r][column["estimated_relative_mse"]])) << r;
        EXPECT_NEAR(relmse,
                    estimated_relative_mse(read_rgb(dir + "/out/" + rows[r][column["render_a"]]),
                                           read_rgb(dir + "/out/" + rows[r][column["render_b"]])),
                    1e-5 * relmse)
            << r;
    }
}

// The error colour map's lightness: L* computed here from the colour's luminance (Rec. 709
// luminance weights of linear sRGB, CIE 1976 L*) rises linearly from 15 to 92, and every
// component lies strictly inside [0, 1], so the map was never clipped to the gamut (clipping
// would pin a component at 0 or 1). The 0.5 tolerance covers the difference between these
// rounded standard weights and the renderer's own sRGB matrix.
TEST(ErrorColourMap, LightnessRisesLinearlyInsideTheGamut) {
    for (int i = 0; i <= 100; ++i) {
        double t = i / 100.0;
        caustica::RGB c = caustica::error_colour(t);
        for (int k = 0; k < 3; ++k) {
            EXPECT_GT(c[k], 0.f) << t;
            EXPECT_LT(c[k], 1.f) << t;
        }
        double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        double lightness = y > 216.0 / 24389 ? 116 * std::cbrt(y) - 16 : 24389.0 / 27 * y;
        EXPECT_NEAR(lightness, 15 + 77 * t, 0.5) << t;
    }
    // Dark blue-violet at the bottom, yellow at the top.
    caustica::RGB low = caustica::error_colour(0), high = caustica::error_colour(1);
    EXPECT_GT(low.b, low.r);
    EXPECT_GT(low.b, low.g);
    EXPECT_GT(high.r, 4 * high.b);
    EXPECT_GT(high.g, 4 * high.b);
}

// The plot draws one polyline per series with data and one marker per valid point (plus one in
// the legend per series), leaves out points that a log axis cannot show, and labels the decades
// that cover the data: x in [0.03, 2] -> 10^-2 .. 10^1, y in [2e-4, 0.5] -> 10^-4 .. 10^0.
TEST(ConvergencePlot, DrawsSeriesMarkersAndDecadeLabels) {
    std::vector<caustica::PlotSeries> series = {
        {"pt", {{0.03, 0.5}, {0.1, 0.1}, {2, 2e-4}}},
        {"lt", {{0.05, 0.2}, {0.5, 0}, {1, -1}}}, // the last two cannot be shown
    };
    std::string svg = caustica::log_log_plot_svg(series, "time", "error");
    auto count = [&](const std::string &what) {
        size_t n = 0;
        for (size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_EQ(count("<polyline"), 2u);
    // Circles for the first series, squares for the second (the background is a <rect> too).
    EXPECT_EQ(count("<circle"), 3u + 1u);
    EXPECT_EQ(count("<rect x="), 1u + 1u + 1u); // markers + legend + the plot frame
    for (const char *label : {">&#8722;2<", ">1<", ">&#8722;4<", ">0<"})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
}

// The "first to reach" table on runs with known errors: pt's relative MSE halves with each
// doubling of time (0.1, 0.05, 0.025 at 1, 2, 4 s), bdpt's falls five-fold (0.2, 0.04, 0.008).
// Between budgets the time is interpolated on log-log axes, so for 0.03 pt needs 2 s x 2^(log
// (0.03/0.05) / log(1/2)) = 10/3 s and bdpt 2^(log(0.15) / log(0.2)) = 2.26 s: bdpt is first,
// though both first reach it at their 4 s budget. 0.1 pt's shortest run already had (at most
// 1 s, before bdpt's 1.35 s); 0.01 only bdpt reaches; 0.001 neither.
TEST(CompareFirstToReach, InterpolatesBetweenBudgetsOnLogLogAxes) {
    caustica::Comparison c;
    c.integrators = {"pt", "bdpt"};
    auto add = [&](const std::string &name, double seconds, double relmse) {
        caustica::ComparisonRun run;
        run.integrator = name;
        run.seconds = seconds;
        run.error.relative_mse = relmse;
        c.runs.push_back(run);
    };
    add("pt", 1, 0.1);
    add("pt", 2, 0.05);
    add("pt", 4, 0.025);
    add("bdpt", 1, 0.2);
    add("bdpt", 2, 0.04);
    add("bdpt", 4, 0.008);

    EXPECT_EQ(caustica::first_to_reach(c, 0.03), "bdpt");
    EXPECT_NEAR(caustica::time_to_reach(c, "pt", 0.03).seconds, 10.0 / 3, 1e-9);
    EXPECT_NEAR(caustica::time_to_reach(c, "bdpt", 0.03).seconds, std::pow(2.0, std::log(0.15) / std::log(0.2)), 1e-9);
    EXPECT_FALSE(caustica::time_to_reach(c, "bdpt", 0.03).at_most);

    EXPECT_EQ(caustica::first_to_reach(c, 0.1), "pt");
    EXPECT_EQ(caustica::time_to_reach(c, "pt", 0.1).seconds, 1);
    EXPECT_TRUE(caustica::time_to_reach(c, "pt", 0.1).at_most);

    EXPECT_EQ(caustica::first_to_reach(c, 0.01), "bdpt");
    EXPECT_LT(caustica::time_to_reach(c, "pt", 0.01).seconds, 0);

    EXPECT_EQ(caustica::first_to_reach(c, 0.001), "");
}

} // namespace
