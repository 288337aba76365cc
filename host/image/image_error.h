// The error of a render against a reference of the same size (a converged render, by
// pathcl or any other renderer): the figures `pathcl converge` records per render.
#pragma once

#include "image/image.h"

namespace pathcl {

// The relative MSE of an image against a reference r: the mean over pixels and channels of
// (x - r)^2 / (r^2 + 0.01) (the 0.01 keeps black pixels from dominating).
constexpr double kRelMseEpsilon = 0.01;

struct ImageError {
    double rmse = 0.0;   // root-mean-square difference over pixels and channels (radiance)
    double relmse = 0.0; // mean over pixels and channels of (x - r)^2 / (r^2 + 0.01)
    // The image mean (over pixels and channels) minus the reference's, and the standard
    // error of that difference from both images' per-pixel variances (zero for a
    // reference without them).
    double mean_bias = 0.0, mean_bias_stderr = 0.0;
    // Fraction of pixel-channel z-tests of compare_images (separate variances) that fail.
    double failing_pixels = 0.0;
};

// Throws pathcl::Error for images of different sizes or a render without a sample count.
ImageError measure_error(const Image& render, const Image& reference);

} // namespace pathcl
