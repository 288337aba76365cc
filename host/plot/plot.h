// Plots for the tools (`converge`, `samples`), drawn by PLplot's cairo memory driver into
// an Image that write_image saves as PNG (atomically, like every output). A Plot is a page
// of panels side by side; each call draws the next panel.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace pathcl {

struct PlotSeries {
    std::string label;
    std::vector<double> x, y;
    std::vector<double> y_low, y_high; // a band around the line (e.g. min and max), or empty
    // Palette entry and dash style (from 0); -1: from the series' index (ten colours, then
    // the next dash style). A two-knob study gives one knob the colour, the other the dash.
    int colour = -1, style = -1;
};

struct PlotAxes {
    std::string title, x_label, y_label;
    std::string legend_title; // the legend's first line (e.g. the knobs a label lists)
    bool log_x = false, log_y = false;
    // Limits; from the data (with a margin) where min >= max.
    double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
};

// Lines at i / cols and j / rows of the unit square, in a grey (0 black, 1 white).
struct PlotGrid {
    unsigned cols = 0, rows = 0;
    double grey = 0.8;
};

class Plot {
public:
    // A width x height pixel page of `columns` panels side by side.
    Plot(int width, int height, int columns = 1);
    ~Plot();
    Plot(const Plot&) = delete;
    Plot& operator=(const Plot&) = delete;

    // Lines (log axes drop points <= 0), each with its band, and a legend to the right of
    // the panel (outside it: it never hides a line).
    void lines(const PlotAxes& axes, const std::vector<PlotSeries>& series);
    // Points of the unit square as dots over grids (the sample visualizer).
    void points(const PlotAxes& axes, const std::vector<glm::vec2>& points, const std::vector<PlotGrid>& grids);
    // A grey map of z[y * nx + x] on [x0, x1] x [y0, y1] (black 0, white z_white or more), and a
    // red circle of radius `circle` about the origin (none if 0).
    void grey_map(const PlotAxes& axes, const std::vector<double>& z, int nx, int ny, double x0, double x1, double y0,
                  double y1, double z_white, double circle);

    // Ends the page: the pixels as a linear-RGB image (for write_image to a PNG).
    Image finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace pathcl
