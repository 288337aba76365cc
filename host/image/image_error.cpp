#include "image/image_error.h"

#include <cmath>

#include "common/error.h"
#include "image/image_compare.h"

namespace pathcl {

ImageError measure_error(const Image& x, const Image& r)
{
    CompareOptions opt;
    opt.pooled_variance = false;                   // the render and the reference may come from different estimators
    CompareReport cmp = compare_images(x, r, opt); // checks the sizes and the sample count
    ImageError e;
    const std::size_t pixels = static_cast<std::size_t>(x.width) * x.height;
    double sq = 0.0, rel = 0.0, sum_x = 0.0, sum_r = 0.0, var_x = 0.0, var_r = 0.0;
    for (std::size_t i = 0; i < pixels * 3; ++i) {
        double d = static_cast<double>(x.rgb[i]) - r.rgb[i];
        sq += d * d;
        rel += d * d / (static_cast<double>(r.rgb[i]) * r.rgb[i] + kRelMseEpsilon);
        sum_x += x.rgb[i];
        sum_r += r.rgb[i];
        var_x += x.variance[i] / x.pixel_spp(i / 3);
        if (r.spp > 0)
            var_r += r.variance[i] / r.pixel_spp(i / 3);
    }
    const double n = static_cast<double>(pixels * 3);
    e.rmse = std::sqrt(sq / n);
    e.relmse = rel / n;
    e.mean_bias = (sum_x - sum_r) / n;
    e.mean_bias_stderr = std::sqrt(var_x + var_r) / n;
    const CompareScale& px = cmp.scales.front();
    e.failing_pixels = px.tests > 0 ? static_cast<double>(px.failures) / static_cast<double>(px.tests) : 0.0;
    return e;
}

} // namespace pathcl
