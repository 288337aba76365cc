// The sample visualizer (`pathcl samples`): one pixel's point set for a chosen dimension
// pair, drawn over the sampler's strata, and optionally the point sets' power spectrum
// (periodogram averaged over many pixels) beside it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "image/image.h"
#include "sampling/samplers.h"

namespace pathcl {

// The periodogram P(f) = |sum_k exp(-2 pi i f . x_k)|^2 / N of each set of N = set_size
// consecutive points, averaged over the sets, for integer frequencies f in [-F, F]^2
// (F = max_frequency). power[(fy + F) * (2F + 1) + (fx + F)]. Independent uniform points
// have expected power 1 at every f != 0; P(0) = N.
struct PowerSpectrum {
    int max_frequency = 0;
    std::size_t sets = 0;
    std::vector<double> power;
    double at(int fx, int fy) const
    {
        int n = 2 * max_frequency + 1;
        return power[static_cast<std::size_t>((fy + max_frequency) * n + (fx + max_frequency))];
    }
};
PowerSpectrum power_spectrum(const std::vector<glm::vec2>& points, std::size_t set_size, int max_frequency);

struct SamplePlotRequest {
    SamplerType sampler = SamplerType::Independent;
    std::uint32_t spp = 1; // the set size (after sampler_spp)
    std::uint32_t seed = 0;
    std::uint32_t dim0 = 0, dim1 = 1;
    std::uint32_t pixel = 0; // pixel index (y * width + x in a render)
    std::string pixel_label; // shown in the title, e.g. "(10, 20)"
    bool spectrum = false;
};

// The largest spp `--spectrum` accepts (its cost grows with spp^2).
constexpr std::uint32_t kSpectrumMaxSpp = 4096;

// Draws the plot with PLplot (host/plot; linear RGB, for write_image to a PNG): one panel,
// two with the spectrum. `note` receives a one-line
// summary (number of pixels averaged, frequency range).
Image draw_sample_plot(const ClDevice& dev, const cl::Program& program, const SamplePlotRequest& request,
                       std::string* note = nullptr);

} // namespace pathcl
