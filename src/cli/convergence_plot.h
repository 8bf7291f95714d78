// A log-log plot of error against render time as a self-contained SVG document: one polyline
// with markers per series, decade ticks (labelled) with unlabelled 2..9 minor ticks, axis
// titles and a legend. No scripts, fonts or other external resources.
#pragma once

#include <string>
#include <vector>

namespace caustica {

struct PlotPoint {
    double x = 0, y = 0;
};

struct PlotSeries {
    std::string name;
    std::vector<PlotPoint> points; // drawn in the order given; points with x or y <= 0 are left out
};

std::string log_log_plot_svg(const std::vector<PlotSeries> &series, const std::string &x_title,
                             const std::string &y_title);

} // namespace caustica
