// Statistical comparison of two Monte Carlo renders (the Mitsuba 3 render-test method):
// two-sided z-tests of the pixel means (pooled or separate variances, see CompareOptions),
// with a Šidák-corrected threshold, at three
// scales: every pixel and channel, block x block tiles (more power against small biases),
// and the whole image per channel. A scale passes when at most `max_fail_fraction` of its
// tests fail; the whole-image scale must pass every test.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace pathcl {

struct CompareOptions {
    double alpha = 0.01;             // family-wise false-alarm rate per scale
    double max_fail_fraction = 0.01; // tolerated failing fraction (heavy-tailed estimates)
    int block = 8;
    // Pooled per-pixel variance (the default) is right for a render against a reference
    // made by the same estimator: under the null hypothesis both sample one distribution,
    // and the high-spp reference fixes the low-spp render's underestimated variance.
    // Renders by different estimators (light-sampling strategies, samplers) share only
    // the mean: compare them with separate (Welch) variances.
    bool pooled_variance = true;
    // Judge the per-pixel scale too. Turn off only where single pixels cannot be near
    // normal at the spp used (BSDF-only sampling of a small light: most pixels miss it);
    // it is still reported.
    bool judge_pixels = true;
};

struct CompareScale {
    std::string name;
    std::size_t tests = 0, failures = 0;
    double z_threshold = 0.0;
    double worst_z = 0.0;
};

struct CompareReport {
    std::vector<CompareScale> scales;
    double mean_a[3] = {}, mean_b[3] = {}, stderr_diff[3] = {};
    // Root-mean-square pixel difference per channel, and over all channels (the error of
    // A when B is a converged reference).
    double rmse[3] = {}, rmse_all = 0.0;
    bool passed = false;
    std::string summary() const;
};

// Throws pathcl::Error if sizes differ or an image lacks a sample count.
CompareReport compare_images(const Image& a, const Image& b, const CompareOptions& options = {});

// Bit-for-bit comparison of the pixel data (means, per-sample variances, sample count),
// for refactors that must not change arithmetic and for reproducibility checks.
struct BitwiseReport {
    std::size_t values = 0;      // floats compared (means and variances)
    std::size_t differing = 0;   // of which not bit-identical
    std::size_t first_pixel = 0; // index of the first differing pixel, when differing > 0
    bool same_spp = true;
    bool identical() const { return differing == 0 && same_spp; }
    std::string summary() const;
};

// Throws pathcl::Error if the sizes differ.
BitwiseReport compare_bitwise(const Image& a, const Image& b);

// Two-sided standard-normal critical value for a Šidák-corrected family of `tests`.
double sidak_z_threshold(double alpha, std::size_t tests);

} // namespace pathcl
