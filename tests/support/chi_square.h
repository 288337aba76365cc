// Chi-square goodness-of-fit test for direction samplers (the method of pbrt and Mitsuba):
// bin sampled directions on a (theta, phi) grid, integrate the claimed pdf over each cell
// for the expected counts, and let Pearson's test decide whether the observed counts could
// have come from that pdf. A sampler and its pdf that disagree anywhere fail.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace pathcl::test {

struct ChiSquareResult {
    bool passed = false;
    double p_value = 0.0;
    double statistic = 0.0; // Pearson's X^2 over the pooled cells
    int degrees_of_freedom = 0;
    double pdf_integral = 0.0; // over the sphere; 1 - (probability the sampler fails)
    std::size_t samples_used = 0, samples_discarded = 0;
    // Samples within 1e-5 rad of a cell edge moved out of a cell the pdf says is empty
    // (float directions exactly on the horizon, say); they are not evidence of a bug.
    std::size_t samples_moved = 0;
    double threshold = 0.0; // Sidak-corrected significance level the p-value must reach
    std::string diagnosis;  // on failure: why, and the cells that disagree most
    std::string summary() const;
};

// sample_directions: unit vectors anywhere on the sphere, one per sampler call; a zero or
// NaN vector means the sampler produced no sample (it is counted, then discarded).
// pdf: the solid-angle density the sampler claims; it integrates to 1 - P(no sample).
// theta is measured from +Z, phi = atan2(y, x). test_count: how many chi-square tests the
// caller runs in total, for the Sidak correction of alpha.
ChiSquareResult chi_square_directions(const std::vector<glm::dvec3>& sample_directions,
                                      const std::function<double(const glm::dvec3&)>& pdf, int theta_res = 10,
                                      int phi_res = 20, double alpha = 0.01, int test_count = 1);

// Regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double regularized_gamma_q(double a, double x);

// P(X >= x) for X chi-square distributed with k degrees of freedom.
double chi_square_survival(double x, int k);

// Directions read back from a device buffer of float4 (pcl_float4, glm::vec4, ...): xyz.
template <class Float4>
std::vector<glm::dvec3> to_directions(const std::vector<Float4>& v)
{
    std::vector<glm::dvec3> out;
    out.reserve(v.size());
    for (const Float4& d : v)
        out.emplace_back(d.x, d.y, d.z);
    return out;
}

} // namespace pathcl::test
