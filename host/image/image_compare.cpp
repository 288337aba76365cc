#include "image/image_compare.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "common/error.h"

namespace pathcl {
namespace {

// Relative precision to which two correct renders of a noise-free pixel agree: float32
// radiance (6e-8) accumulated and converted by different code paths.
constexpr double kRelativeRounding = 1e-6;

struct Estimate {
    double mean = 0.0, var_of_mean = 0.0;
};

// Counts the failing tests among paired estimates.
CompareScale run_scale(const std::string& name, const std::vector<Estimate>& a, const std::vector<Estimate>& b,
                       double alpha)
{
    CompareScale s;
    s.name = name;
    s.tests = a.size();
    s.z_threshold = sidak_z_threshold(alpha, a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        double diff = a[i].mean - b[i].mean;
        // Float rounding floor: a pixel that sees only a light has (almost) no Monte
        // Carlo variance, its variance estimate is rounding residue, and two renderers
        // round the same radiance differently in the last bits.
        double rounding = kRelativeRounding * std::max(std::fabs(a[i].mean), std::fabs(b[i].mean));
        double se = std::sqrt(a[i].var_of_mean + b[i].var_of_mean + rounding * rounding);
        double z = (se > 0.0) ? std::fabs(diff) / se : (diff == 0.0 ? 0.0 : INFINITY);
        if (!std::isfinite(a[i].mean) || !std::isfinite(b[i].mean))
            z = INFINITY;
        s.worst_z = std::max(s.worst_z, z);
        if (!(z <= s.z_threshold))
            ++s.failures;
    }
    return s;
}

// Means and variances of means of block x block tiles (partial tiles at the edges).
std::vector<Estimate> tiles(const Image& img, int block)
{
    std::vector<Estimate> out;
    for (std::uint32_t ty = 0; ty < img.height; ty += static_cast<std::uint32_t>(block))
        for (std::uint32_t tx = 0; tx < img.width; tx += static_cast<std::uint32_t>(block))
            for (int c = 0; c < 3; ++c) {
                Estimate e;
                double count = 0.0;
                for (std::uint32_t y = ty; y < std::min(img.height, ty + block); ++y)
                    for (std::uint32_t x = tx; x < std::min(img.width, tx + block); ++x) {
                        std::size_t p = static_cast<std::size_t>(y) * img.width + x;
                        std::size_t i = p * 3 + static_cast<std::size_t>(c);
                        e.mean += img.rgb[i];
                        e.var_of_mean += img.variance[i] / img.pixel_spp(p);
                        count += 1.0;
                    }
                e.mean /= count;
                e.var_of_mean /= count * count;
                out.push_back(e);
            }
    return out;
}

} // namespace

double sidak_z_threshold(double alpha, std::size_t tests)
{
    double per_test = 1.0 - std::pow(1.0 - alpha, 1.0 / static_cast<double>(std::max<std::size_t>(tests, 1)));
    // Solve erfc(z / sqrt 2) = per_test by bisection (erfc is decreasing).
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > per_test ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

CompareReport compare_images(const Image& a, const Image& b, const CompareOptions& opt)
{
    if (a.width != b.width || a.height != b.height)
        throw Error("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
    if (a.spp == 0 || b.spp == 0)
        throw Error("an image has no sample count (pathcl:spp), so its variance cannot be used");
    CompareReport r;
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height;

    // Pooled: under the null hypothesis both renders sample one distribution per pixel,
    // so its variance is estimated from both together (as in Student's t-test); a low-spp
    // render alone underestimates the variance of pixels whose rare bright paths it
    // missed. Separate (Welch): each render's own variance.
    double sq[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n * 3; ++i) {
        double d = static_cast<double>(a.rgb[i]) - static_cast<double>(b.rgb[i]);
        sq[i % 3] += d * d;
    }
    for (int c = 0; c < 3; ++c)
        r.rmse[c] = std::sqrt(sq[c] / static_cast<double>(n));
    r.rmse_all = std::sqrt((sq[0] + sq[1] + sq[2]) / (3.0 * static_cast<double>(n)));
    Image pooled_a = a, pooled_b = b;
    for (std::size_t i = 0; i < n * 3 && opt.pooled_variance; ++i) {
        const double na = a.pixel_spp(i / 3), nb = b.pixel_spp(i / 3);
        double pooled = ((na - 1.0) * a.variance[i] + (nb - 1.0) * b.variance[i]) / std::max(na + nb - 2.0, 1.0);
        pooled_a.variance[i] = pooled_b.variance[i] = static_cast<float>(pooled);
    }
    std::vector<Estimate> pa(n * 3), pb(n * 3);
    for (std::size_t i = 0; i < n * 3; ++i) {
        pa[i] = {a.rgb[i], pooled_a.variance[i] / a.pixel_spp(i / 3)};
        pb[i] = {b.rgb[i], pooled_b.variance[i] / b.pixel_spp(i / 3)};
    }
    r.scales.push_back(run_scale("pixel", pa, pb, opt.alpha));
    r.scales.push_back(run_scale(std::to_string(opt.block) + "x" + std::to_string(opt.block) + " tile",
                                 tiles(pooled_a, opt.block), tiles(pooled_b, opt.block), opt.alpha));
    int whole = static_cast<int>(std::max(a.width, a.height));
    std::vector<Estimate> wa = tiles(pooled_a, whole), wb = tiles(pooled_b, whole);
    r.scales.push_back(run_scale("image", wa, wb, opt.alpha));
    for (int c = 0; c < 3; ++c) {
        r.mean_a[c] = wa[static_cast<std::size_t>(c)].mean;
        r.mean_b[c] = wb[static_cast<std::size_t>(c)].mean;
        r.stderr_diff[c] =
            std::sqrt(wa[static_cast<std::size_t>(c)].var_of_mean + wb[static_cast<std::size_t>(c)].var_of_mean);
    }
    r.passed = true;
    for (const CompareScale& s : r.scales) {
        if (s.name == "pixel" && !opt.judge_pixels)
            continue;
        double limit = (s.name == "image") ? 0.0 : opt.max_fail_fraction;
        if (static_cast<double>(s.failures) > limit * static_cast<double>(s.tests))
            r.passed = false;
    }
    return r;
}

std::string CompareReport::summary() const
{
    std::string out;
    char line[256];
    for (const CompareScale& s : scales) {
        std::snprintf(line, sizeof line, "%-10s %7zu tests, %5zu fail (%.3f%%), |z| threshold %.2f, worst |z| %.2f\n",
                      s.name.c_str(), s.tests, s.failures,
                      s.tests ? 100.0 * static_cast<double>(s.failures) / static_cast<double>(s.tests) : 0.0,
                      s.z_threshold, s.worst_z);
        out += line;
    }
    std::snprintf(line, sizeof line,
                  "image mean A (%.5f %.5f %.5f)  B (%.5f %.5f %.5f)  std. error of difference (%.5f %.5f %.5f)\n",
                  mean_a[0], mean_a[1], mean_a[2], mean_b[0], mean_b[1], mean_b[2], stderr_diff[0], stderr_diff[1],
                  stderr_diff[2]);
    out += line;
    std::snprintf(line, sizeof line, "RMSE of A against B (%.6g %.6g %.6g), all channels %.6g\n", rmse[0], rmse[1],
                  rmse[2], rmse_all);
    out += line;
    out += passed ? "PASS\n" : "FAIL\n";
    return out;
}

BitwiseReport compare_bitwise(const Image& a, const Image& b)
{
    if (a.width != b.width || a.height != b.height)
        throw Error("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
    BitwiseReport r;
    r.same_spp = a.spp == b.spp && a.samples == b.samples;
    auto scan = [&](const std::vector<float>& x, const std::vector<float>& y) {
        for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
            ++r.values;
            if (std::bit_cast<std::uint32_t>(x[i]) != std::bit_cast<std::uint32_t>(y[i])) {
                if (r.differing == 0)
                    r.first_pixel = i / 3;
                ++r.differing;
            }
        }
    };
    scan(a.rgb, b.rgb);
    scan(a.variance, b.variance);
    return r;
}

std::string BitwiseReport::summary() const
{
    std::string out = std::to_string(values) + " values compared, " + std::to_string(differing) + " differ";
    if (differing > 0)
        out += " (first at pixel " + std::to_string(first_pixel) + ")";
    if (!same_spp)
        out += ", sample counts differ";
    out += identical() ? "\nIDENTICAL\n" : "\nDIFFERENT\n";
    return out;
}

} // namespace pathcl
