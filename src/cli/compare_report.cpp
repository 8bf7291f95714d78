#include "cli/compare_report.h"

#include "cli/convergence_plot.h"
#include "cli/error_colour_map.h"
#include "cli/xml_escape.h"
#include "film/image_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace caustica {

namespace {

// Like the image writers: a temporary file renamed into place, so a failed run never leaves a
// truncated report.
void write_text_file(const std::string &path, const std::string &text) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(tmp, ignored);
            throw std::runtime_error("cannot write \"" + path + "\"");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw std::runtime_error("cannot write \"" + path + "\": " + ec.message());
}

std::string format(const char *spec, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, spec, v);
    return buf;
}

// Full precision for the data files.
std::string exact(double v) { return format("%.9g", v); }

// JSON has no NaN or infinity.
std::string json_number(double v) { return std::isfinite(v) ? exact(v) : "null"; }

std::string json_string(const std::string &text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            out += format("\\u%04x", c);
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string seconds_text(double s) { return format("%g", s) + "&nbsp;s"; }

// Display size of an image in the page: small renders are enlarged by a whole factor (drawn
// with visible pixels) to at least `min_width`; large ones are shown at most `max_width` wide.
struct DisplaySize {
    int width, height;
    bool enlarged;
};

DisplaySize display_size(int width, int height, int min_width, int max_width) {
    if (width <= 0 || height <= 0) return {min_width, min_width, false};
    if (width < min_width) {
        int factor = (min_width + width - 1) / width;
        return {width * factor, height * factor, true};
    }
    if (width > max_width) return {max_width, std::max(1, int(std::lround(double(height) * max_width / width))), false};
    return {width, height, false};
}

std::string img_tag(const std::string &src, const std::string &alt, DisplaySize size) {
    return "<img src=\"" + xml_escape(src) + "\" alt=\"" + xml_escape(alt) + "\" width=\"" +
           std::to_string(size.width) + "\" height=\"" + std::to_string(size.height) + "\"" +
           (size.enlarged ? " class=\"pixelated\"" : "") + ">";
}

std::string hex_colour(const RGB &linear) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", tone_map_clamp_srgb8(linear.r), tone_map_clamp_srgb8(linear.g),
                  tone_map_clamp_srgb8(linear.b));
    return buf;
}

// The error images' colour scale as an inline SVG: the map as a gradient, with a tick and a
// label at every decade of relative error.
std::string error_scale_svg() {
    constexpr int width = 360, bar_height = 18, left = 24;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width + 2 * left << "\" height=\"52\""
        << " role=\"img\" aria-label=\"colour scale of the error images\" style=\"font: 12px sans-serif\">"
        << "<defs><linearGradient id=\"error-scale\">";
    for (int i = 0; i <= 16; ++i) {
        double t = i / 16.0;
        svg << "<stop offset=\"" << format("%.4f", t) << "\" stop-color=\"" << hex_colour(error_colour(t)) << "\"/>";
    }
    svg << "</linearGradient></defs><rect x=\"" << left << "\" y=\"4\" width=\"" << width << "\" height=\""
        << bar_height << "\" fill=\"url(#error-scale)\" stroke=\"#444\"/>";
    const int decades = int(kErrorImageLog10Max - kErrorImageLog10Min);
    for (int d = 0; d <= decades; ++d) {
        double x = left + double(width) * d / decades;
        int exponent = int(kErrorImageLog10Min) + d;
        std::string label = exponent == 0 ? "1" : "10<tspan dy=\"-6\" font-size=\"9\">&#8722;" +
                                                      std::to_string(-exponent) + "</tspan>";
        svg << "<line x1=\"" << x << "\" y1=\"" << 4 + bar_height << "\" x2=\"" << x << "\" y2=\"" << 8 + bar_height
            << "\" stroke=\"#444\"/><text x=\"" << x << "\" y=\"" << 24 + bar_height
            << "\" text-anchor=\"middle\">" << label << "</text>";
    }
    svg << "</svg>";
    return svg.str();
}

std::string scene_name(const Comparison &c) { return std::filesystem::path(c.scene_path).filename().string(); }

} // namespace

ReachTime time_to_reach(const Comparison &comparison, const std::string &integrator, double level) {
    const ComparisonRun *previous = nullptr;
    for (const ComparisonRun &run : comparison.runs) {
        if (run.integrator != integrator) continue;
        if (run.error.relative_mse <= level) {
            if (!previous) return {run.seconds, true};
            const double e0 = previous->error.relative_mse, e1 = run.error.relative_mse;
            const double t0 = previous->seconds, t1 = run.seconds;
            // A zero error or time has no logarithm: no interpolation then.
            if (e1 <= 0 || t0 <= 0 || t1 <= 0) return {t1, false};
            const double fraction = std::log(level / e0) / std::log(e1 / e0);
            return {t0 * std::pow(t1 / t0, fraction), false};
        }
        previous = &run;
    }
    return {};
}

std::string first_to_reach(const Comparison &comparison, double level) {
    std::string first;
    double best = 0;
    for (const std::string &name : comparison.integrators) {
        const ReachTime reach = time_to_reach(comparison, name, level);
        if (reach.seconds >= 0 && (first.empty() || reach.seconds < best)) {
            first = name;
            best = reach.seconds;
        }
    }
    return first;
}

void write_convergence_csv(const std::string &path, const Comparison &c) {
    std::string csv = "integrator,budget_seconds,seconds,samples_per_pixel,relative_mse,rmse,"
                      "estimated_relative_mse,estimated_rmse,rays,non_finite_samples,image,render_a,render_b\n";
    for (const ComparisonRun &r : c.runs)
        csv += r.integrator + "," + exact(r.budget_seconds) + "," + exact(r.seconds) + "," +
               std::to_string(r.samples_per_pixel) + "," + exact(r.error.relative_mse) + "," + exact(r.error.rmse) +
               "," + exact(r.estimated_error.relative_mse) + "," + exact(r.estimated_error.rmse) + "," +
               std::to_string(r.rays) + "," + std::to_string(r.non_finite_samples) + "," + r.image + "," +
               r.render_a + "," + r.render_b + "\n";
    write_text_file(path, csv);
}

void write_results_json(const std::string &path, const Comparison &c) {
    std::ostringstream json;
    json << "{\n"
         << "  \"scene\": " << json_string(c.scene_path) << ",\n"
         << "  \"date\": " << json_string(c.date) << ",\n"
         << "  \"resolution\": [" << c.width << ", " << c.height << "],\n"
         << "  \"seed\": " << c.seed << ",\n"
         << "  \"threads\": " << c.threads << ",\n"
         << "  \"time_limit_seconds\": " << json_number(c.time_limit) << ",\n"
         << "  \"budgets_seconds\": [";
    for (size_t i = 0; i < c.budgets.size(); ++i) json << (i ? ", " : "") << json_number(c.budgets[i]);
    json << "],\n"
         << "  \"reference\": {\"description\": " << json_string(c.reference_description) << ", \"image\": "
         << (c.reference_png.empty() ? "null" : json_string(c.reference_png)) << "},\n"
         << "  \"relative_mse\": \"mean over pixels and channels of (x - r)^2 / (r^2 + 0.01)\",\n"
         << "  \"estimated_relative_mse\": \"mean over pixels and channels of h^2 / (m^2 + 0.01), m and h the "
            "average and half-difference of the two renders\",\n"
         << "  \"runs\": [\n";
    for (size_t i = 0; i < c.runs.size(); ++i) {
        const ComparisonRun &r = c.runs[i];
        json << "    {\"integrator\": " << json_string(r.integrator)
             << ", \"budget_seconds\": " << json_number(r.budget_seconds)
             << ", \"seconds\": " << json_number(r.seconds) << ", \"samples_per_pixel\": " << r.samples_per_pixel
             << ", \"relative_mse\": " << json_number(r.error.relative_mse)
             << ", \"rmse\": " << json_number(r.error.rmse) << ", \"rays\": " << r.rays
             << ", \"estimated_relative_mse\": " << json_number(r.estimated_error.relative_mse)
             << ", \"estimated_rmse\": " << json_number(r.estimated_error.rmse)
             << ", \"non_finite_samples\": " << r.non_finite_samples
             << ", \"image\": " << json_string(r.image) << ", \"png\": " << json_string(r.png)
             << ", \"error_png\": " << json_string(r.error_png) << ", \"renders\": [" << json_string(r.render_a)
             << ", " << json_string(r.render_b) << "]}" << (i + 1 < c.runs.size() ? "," : "") << "\n";
    }
    json << "  ],\n  \"agreement\": [\n";
    for (size_t i = 0; i < c.agreements.size(); ++i) {
        const Agreement &a = c.agreements[i];
        json << "    {\"integrators\": [" << json_string(a.first) << ", " << json_string(a.second)
             << "], \"agree\": " << (a.agree ? "true" : "false")
             << ", \"relative_difference\": " << json_number(a.relative_difference)
             << ", \"z\": " << json_number(a.z) << ", \"threshold\": " << json_number(a.threshold)
             << ", \"block_size\": " << a.block_size << ", \"blocks\": " << a.blocks << ", \"worst_block\": ["
             << a.worst_block_x << ", " << a.worst_block_y << "], \"worst_block_z\": " << json_number(a.worst_block_z)
             << ", \"block_threshold\": " << json_number(a.block_threshold)
             << ", \"summary\": " << json_string(agreement_sentence(a)) << "}"
             << (i + 1 < c.agreements.size() ? "," : "") << "\n";
    }
    json << "  ],\n  \"first_to_reach\": [\n";
    for (size_t i = 0; i < std::size(kRelativeMseLevels); ++i) {
        const double level = kRelativeMseLevels[i];
        const std::string first = first_to_reach(c, level);
        json << "    {\"relative_mse\": " << json_number(level) << ", \"integrator\": "
             << (first.empty() ? "null" : json_string(first)) << ", \"times\": {";
        for (size_t k = 0; k < c.integrators.size(); ++k) {
            const ReachTime reach = time_to_reach(c, c.integrators[k], level);
            json << (k ? ", " : "") << json_string(c.integrators[k]) << ": ";
            if (reach.seconds < 0)
                json << "null";
            else
                json << "{\"seconds\": " << json_number(reach.seconds)
                     << ", \"at_most\": " << (reach.at_most ? "true" : "false") << "}";
        }
        json << "}}" << (i + 1 < std::size(kRelativeMseLevels) ? "," : "") << "\n";
    }
    json << "  ]\n}\n";
    write_text_file(path, json.str());
}

void write_convergence_svg(const std::string &path, const Comparison &c) {
    std::vector<PlotSeries> series;
    for (const std::string &name : c.integrators) {
        PlotSeries s{name, {}};
        for (const ComparisonRun &r : c.runs)
            if (r.integrator == name) s.points.push_back({r.seconds, r.error.relative_mse});
        series.push_back(std::move(s));
    }
    write_text_file(path, log_log_plot_svg(series, "render time (s)", "relative MSE"));
}

void write_index_html(const std::string &path, const Comparison &c) {
    const std::string title = "Caustica comparison: " + scene_name(c) + ", " + c.date;
    const DisplaySize thumbnail = display_size(c.width, c.height, 192, 320);
    const DisplaySize reference_size = display_size(c.width, c.height, 384, 640);
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         << "<title>" << xml_escape(title) << "</title>\n"
         << "<style>\n"
            "body { font-family: sans-serif; margin: 1.5em; color: #222; }\n"
            "table { border-collapse: collapse; margin: 0.5em 0 1em; }\n"
            "th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; }\n"
            "th:first-child, td:first-child { text-align: left; }\n"
            ".runs { display: flex; flex-wrap: wrap; gap: 1em; }\n"
            "figure { margin: 0; }\n"
            "figcaption { font-size: 0.85em; max-width: 22em; }\n"
            ".pair { display: flex; gap: 4px; }\n"
            "img.pixelated { image-rendering: pixelated; }\n"
            ".disagree { color: #b00; font-weight: bold; }\n"
            "</style>\n</head>\n<body>\n"
         << "<h1>" << xml_escape(title) << "</h1>\n"
         << "<p>Scene <code>" << xml_escape(c.scene_path) << "</code> at " << c.width << "&times;" << c.height
         << ", seed " << c.seed << ", " << c.threads << " thread" << (c.threads == 1 ? "" : "s")
         << ". Each integrator rendered the scene at each time budget (";
    for (size_t i = 0; i < c.budgets.size(); ++i) html << (i ? ", " : "") << seconds_text(c.budgets[i]);
    html << ") as two independent renders of half the budget (seeds " << c.seed << " and " << c.seed + 1
         << "); the image shown and measured is their average, its time and samples those of both. Its "
            "noise is estimated from the two renders' half-difference h: relative MSE the mean over pixels "
            "and channels of h<sup>2</sup>&nbsp;/&nbsp;(m<sup>2</sup>&nbsp;+&nbsp;0.01), m the average, which "
            "measures variance but not bias. ";
    if (c.reference_png.empty())
        html << "No reference was given: the errors below are these estimates.</p>\n";
    else
        html << "Errors are against the reference below: the relative MSE is the mean over pixels and "
                "channels of (x&nbsp;&minus;&nbsp;r)<sup>2</sup>&nbsp;/&nbsp;(r<sup>2</sup>&nbsp;+&nbsp;0.01).</p>\n"
             << "<h2>Reference</h2>\n<figure>\n"
             << img_tag(c.reference_png, "reference image", reference_size) << "\n<figcaption>"
             << xml_escape(c.reference_description) << "</figcaption>\n</figure>\n";

    html << "<h2>Agreement between integrators</h2>\n"
         << "<p>Each pair's longest-budget images, set against their own noise (estimated from the two "
            "renders): the difference of the image means in standard errors (z), and the largest z of a "
            "block's mean difference, each against a threshold exceeded by chance with probability "
         << format("%g", kAgreementFalseAlarmRate) << " (for the blocks, Bonferroni over their number). "
            "A disagreement means that at least one of the two is biased (or that its noise is far from "
            "normal, e.g. rare fireflies).</p>\n";
    if (c.agreements.empty()) {
        html << "<p>Only one integrator: nothing to compare.</p>\n";
    } else {
        html << "<ul>\n";
        for (const Agreement &a : c.agreements)
            html << "<li" << (a.agree ? "" : " class=\"disagree\"") << ">" << xml_escape(agreement_sentence(a))
                 << "</li>\n";
        html << "</ul>\n";
    }

    html << "<h2>First to reach a relative MSE</h2>\n"
         << "<p>The render time at which each integrator's relative MSE first reaches each level, "
            "interpolated on log-log axes between the budgets around it (&le;: already reached at its "
            "shortest budget, whose time is then an upper bound), and the integrator that got there "
            "first; &mdash; when no budget reached it.</p>\n"
         << "<table>\n<thead><tr><th>relative MSE</th><th>first</th>";
    for (const std::string &name : c.integrators) html << "<th>" << xml_escape(name) << "</th>";
    html << "</tr></thead>\n<tbody>\n";
    for (double level : kRelativeMseLevels) {
        const std::string first = first_to_reach(c, level);
        html << "<tr><td>&le;&nbsp;" << format("%g", level) << "</td><td>"
             << (first.empty() ? "none" : xml_escape(first)) << "</td>";
        for (const std::string &name : c.integrators) {
            const ReachTime reach = time_to_reach(c, name, level);
            html << "<td>";
            if (reach.seconds < 0)
                html << "&mdash;";
            else
                html << (reach.at_most ? "&le;&nbsp;" : "") << format("%.3g", reach.seconds) << "&nbsp;s";
            html << "</td>";
        }
        html << "</tr>\n";
    }
    html << "</tbody>\n</table>\n";

    html << "<h2>Convergence</h2>\n"
         << "<img src=\"convergence.svg\" width=\"760\" height=\"480\" alt=\"log-log plot of relative MSE "
            "against render time, one line per integrator\">\n";

    html << "<h2>Renders and their errors</h2>\n"
         << "<p>Each render (linked to its EXR) beside its error image: every pixel's relative error "
         << (c.reference_png.empty() ? "as estimated, &radic;(mean over channels of h<sup>2</sup>&nbsp;/&nbsp;"
                                       "(m<sup>2</sup>&nbsp;+&nbsp;0.01)), "
                                     : "&radic;(mean over channels of (x&nbsp;&minus;&nbsp;r)<sup>2</sup>&nbsp;/"
                                       "&nbsp;(r<sup>2</sup>&nbsp;+&nbsp;0.01)) ")
         << "on a log scale from 10<sup>" << format("%g", kErrorImageLog10Min) << "</sup> (dark) to "
         << format("%g", std::pow(10.0, kErrorImageLog10Max)) << " (light); values outside are clamped.</p>\n"
         << error_scale_svg() << "\n";
    for (const std::string &name : c.integrators) {
        html << "<h3>" << xml_escape(name) << "</h3>\n<div class=\"runs\">\n";
        for (const ComparisonRun &r : c.runs) {
            if (r.integrator != name) continue;
            std::string label = name + " at " + format("%g", r.budget_seconds) + " s";
            html << "<figure>\n<div class=\"pair\"><a href=\"" << xml_escape(r.image) << "\">"
                 << img_tag(r.png, label, thumbnail) << "</a>"
                 << img_tag(r.error_png, "relative error of " + label, thumbnail) << "</div>\n<figcaption>"
                 << "budget " << seconds_text(r.budget_seconds) << ": " << r.samples_per_pixel << " spp in "
                 << format("%.3g", r.seconds) << "&nbsp;s, "
                 << "relative MSE " << format("%.3g", r.error.relative_mse) << ", RMSE "
                 << format("%.3g", r.error.rmse);
            if (!c.reference_png.empty())
                html << " (estimated from the two renders: " << format("%.3g", r.estimated_error.relative_mse) << ")";
            html << "</figcaption>\n</figure>\n";
        }
        html << "</div>\n";
    }

    // A self-check for people and for tests: after loading, the body says whether every image
    // (the plot included) was found and decoded.
    html << "<script>\n"
            "window.addEventListener(\"load\", function () {\n"
            "  var missing = [];\n"
            "  for (var i = 0; i < document.images.length; ++i) {\n"
            "    var img = document.images[i];\n"
            "    if (!img.complete || img.naturalWidth === 0) missing.push(img.getAttribute(\"src\"));\n"
            "  }\n"
            "  document.body.setAttribute(\"data-images\", missing.length === 0\n"
            "      ? \"loaded \" + document.images.length : \"missing \" + missing.join(\" \"));\n"
            "});\n"
            "</script>\n"
            "</body>\n</html>\n";
    write_text_file(path, html.str());
}

} // namespace caustica
