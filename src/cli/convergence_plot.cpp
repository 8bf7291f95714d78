#include "cli/convergence_plot.h"

#include "cli/xml_escape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace caustica {

namespace {

// Distinct hues of similar weight, and a marker shape per series as well so that the lines can
// be told apart without colour.
const char *const kColours[] = {"#1f5fbf", "#d9480f", "#2b8a3e", "#ae3ec9", "#c92a2a", "#0c8599", "#8f6a00", "#495057"};
enum class Marker { Circle, Square, Triangle, Diamond };
constexpr Marker kMarkers[] = {Marker::Circle, Marker::Square, Marker::Triangle, Marker::Diamond};

// Plot geometry in SVG user units (pixels).
constexpr double kWidth = 760, kHeight = 480;
constexpr double kLeft = 84, kRight = 580, kTop = 20, kBottom = 416;
constexpr double kLegendX = 600;

// Whole decades [first, last] covering [lo, hi] (at least one decade wide).
struct DecadeRange {
    int first = 0, last = 1;
};

DecadeRange decades_covering(double lo, double hi) {
    DecadeRange r{int(std::floor(std::log10(lo))), int(std::ceil(std::log10(hi)))};
    if (r.last <= r.first) r.last = r.first + 1;
    return r;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// "10" with the exponent as a superscript; U+2212 for the minus sign.
std::string decade_label(int exponent) {
    std::string e = exponent < 0 ? "&#8722;" + std::to_string(-exponent) : std::to_string(exponent);
    return "10<tspan dy=\"-7\" font-size=\"10\">" + e + "</tspan>";
}

std::string marker_svg(Marker marker, double x, double y, const char *colour) {
    const double r = 4.5;
    std::string fill = std::string(" fill=\"") + colour + "\"";
    switch (marker) {
    case Marker::Circle: return "<circle cx=\"" + number(x) + "\" cy=\"" + number(y) + "\" r=\"" + number(r) + "\"" + fill + "/>";
    case Marker::Square:
        return "<rect x=\"" + number(x - r) + "\" y=\"" + number(y - r) + "\" width=\"" + number(2 * r) +
               "\" height=\"" + number(2 * r) + "\"" + fill + "/>";
    case Marker::Triangle:
        return "<polygon points=\"" + number(x) + "," + number(y - 1.2 * r) + " " + number(x - 1.1 * r) + "," +
               number(y + 0.8 * r) + " " + number(x + 1.1 * r) + "," + number(y + 0.8 * r) + "\"" + fill + "/>";
    case Marker::Diamond:
        return "<polygon points=\"" + number(x) + "," + number(y - 1.3 * r) + " " + number(x + 1.1 * r) + "," +
               number(y) + " " + number(x) + "," + number(y + 1.3 * r) + " " + number(x - 1.1 * r) + "," +
               number(y) + "\"" + fill + "/>";
    }
    return {};
}

} // namespace

std::string log_log_plot_svg(const std::vector<PlotSeries> &series, const std::string &x_title,
                             const std::string &y_title) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double x_lo = inf, x_hi = 0, y_lo = inf, y_hi = 0;
    for (const PlotSeries &s : series)
        for (const PlotPoint &p : s.points) {
            if (!(p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y))) continue;
            x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
            y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
        }
    const bool has_data = x_hi > 0;
    // Without data, empty axes over a neutral range, and a note saying so.
    DecadeRange xd = has_data ? decades_covering(x_lo, x_hi) : DecadeRange{-1, 1};
    DecadeRange yd = has_data ? decades_covering(y_lo, y_hi) : DecadeRange{-3, 0};
    auto px = [&](double x) { return kLeft + (std::log10(x) - xd.first) / (xd.last - xd.first) * (kRight - kLeft); };
    auto py = [&](double y) { return kBottom - (std::log10(y) - yd.first) / (yd.last - yd.first) * (kBottom - kTop); };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
        << "\" viewBox=\"0 0 " << kWidth << " " << kHeight << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

    // Grid and ticks: a faint line and a labelled tick at every decade, short ticks at 2..9
    // times each decade (left out when there are so many decades that they would crowd).
    auto axis_ticks = [&](DecadeRange d, bool horizontal) {
        const bool minor = d.last - d.first <= 6;
        for (int e = d.first; e <= d.last; ++e) {
            for (int m = 1; m <= 9; ++m) {
                if (e == d.last && m > 1) break;
                if (m > 1 && !minor) continue;
                double v = m * std::pow(10.0, e);
                double p = horizontal ? px(v) : py(v);
                double tick = m == 1 ? 7 : 4;
                if (horizontal) {
                    if (m == 1)
                        svg << "<line x1=\"" << number(p) << "\" y1=\"" << kTop << "\" x2=\"" << number(p)
                            << "\" y2=\"" << kBottom << "\" stroke=\"#e5e5e5\"/>\n"
                            << "<text x=\"" << number(p) << "\" y=\"" << kBottom + 24
                            << "\" text-anchor=\"middle\">" << decade_label(e) << "</text>\n";
                    svg << "<line x1=\"" << number(p) << "\" y1=\"" << kBottom << "\" x2=\"" << number(p)
                        << "\" y2=\"" << kBottom + tick << "\" stroke=\"black\"/>\n";
                } else {
                    if (m == 1)
                        svg << "<line x1=\"" << kLeft << "\" y1=\"" << number(p) << "\" x2=\"" << kRight
                            << "\" y2=\"" << number(p) << "\" stroke=\"#e5e5e5\"/>\n"
                            << "<text x=\"" << kLeft - 12 << "\" y=\"" << number(p + 5)
                            << "\" text-anchor=\"end\">" << decade_label(e) << "</text>\n";
                    svg << "<line x1=\"" << kLeft - tick << "\" y1=\"" << number(p) << "\" x2=\"" << kLeft
                        << "\" y2=\"" << number(p) << "\" stroke=\"black\"/>\n";
                }
            }
        }
    };
    axis_ticks(xd, true);
    axis_ticks(yd, false);
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << kRight - kLeft << "\" height=\""
        << kBottom - kTop << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << number((kLeft + kRight) / 2) << "\" y=\"" << kHeight - 14
        << "\" text-anchor=\"middle\">" << xml_escape(x_title) << "</text>\n"
        << "<text transform=\"translate(20 " << number((kTop + kBottom) / 2)
        << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(y_title) << "</text>\n";
    if (!has_data)
        svg << "<text x=\"" << number((kLeft + kRight) / 2) << "\" y=\"" << number((kTop + kBottom) / 2)
            << "\" text-anchor=\"middle\" fill=\"#777\">no data to plot</text>\n";

    for (size_t i = 0; i < series.size(); ++i) {
        const char *colour = kColours[i % std::size(kColours)];
        const Marker marker = kMarkers[i % std::size(kMarkers)];
        std::string points, markers;
        for (const PlotPoint &p : series[i].points) {
            if (!(p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y))) continue;
            points += number(px(p.x)) + "," + number(py(p.y)) + " ";
            markers += marker_svg(marker, px(p.x), py(p.y), colour) + "\n";
        }
        svg << "<g>\n<title>" << xml_escape(series[i].name) << "</title>\n";
        if (!points.empty())
            svg << "<polyline points=\"" << points << "\" fill=\"none\" stroke=\"" << colour
                << "\" stroke-width=\"2\"/>\n";
        svg << markers << "</g>\n";

        // Legend entry: a line segment with the marker, then the name.
        double ly = kTop + 14 + 24 * double(i);
        svg << "<line x1=\"" << kLegendX << "\" y1=\"" << number(ly) << "\" x2=\"" << kLegendX + 32 << "\" y2=\""
            << number(ly) << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n"
            << marker_svg(marker, kLegendX + 16, ly, colour) << "\n"
            << "<text x=\"" << kLegendX + 42 << "\" y=\"" << number(ly + 5) << "\">" << xml_escape(series[i].name)
            << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

} // namespace caustica
