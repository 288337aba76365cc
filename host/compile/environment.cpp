#include "compile/environment.h"

#include <cmath>
#include <numbers>

#include "common/error.h"

namespace pathcl {
namespace {

double luminance(double r, double g, double b)
{
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

// CDF of n non-negative weights as n + 1 floats from 0 to 1 (uniform if all are 0).
void append_cdf(const std::vector<double>& w, std::vector<float>& out)
{
    double total = 0.0;
    for (double x : w)
        total += x;
    double acc = 0.0;
    out.push_back(0.0f);
    for (std::size_t i = 0; i < w.size(); ++i) {
        acc += (total > 0.0) ? w[i] / total : 1.0 / static_cast<double>(w.size());
        out.push_back(i + 1 == w.size() ? 1.0f : static_cast<float>(acc));
    }
}

} // namespace

void build_environment_distribution(EnvironmentMap& map)
{
    const double pi = std::numbers::pi;
    map.marginal_cdf.clear();
    map.conditional_cdf.clear();
    std::vector<double> row_weight(map.height), w(map.width);
    double solid_angle_sum = 0.0;
    for (std::uint32_t j = 0; j < map.height; ++j) {
        // sin(theta) at the row centre weights the row: texels near the poles cover less.
        double sin_theta = std::sin(pi * (j + 0.5) / map.height);
        double row = 0.0;
        for (std::uint32_t i = 0; i < map.width; ++i) {
            const pcl_float4& t = map.texels[static_cast<std::size_t>(j) * map.width + i];
            w[i] = luminance(t.x, t.y, t.z) * sin_theta;
            row += w[i];
        }
        append_cdf(w, map.conditional_cdf);
        row_weight[j] = row;
        solid_angle_sum += row;
    }
    append_cdf(row_weight, map.marginal_cdf);
    // Mean luminance over the sphere: sum of L sin(theta) dtheta dphi / (4 pi).
    map.average_radiance = solid_angle_sum * (pi / map.height) * (2.0 * pi / map.width) / (4.0 * pi);
}

EnvironmentMap build_environment_map(const SceneEnvironment& env)
{
    EnvironmentMap map;
    if (env.path.empty()) {
        map.width = map.height = 1;
        glm::vec3 c = env.constant * env.strength;
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
            throw Error("the environment's radiance (its colour x strength) is negative, NaN or infinite");
        map.texels = {{c.x, c.y, c.z, 0.0f}};
    } else {
        map.width = env.width;
        map.height = env.height;
        map.texels.resize(static_cast<std::size_t>(env.width) * env.height);
        for (std::size_t i = 0; i < map.texels.size(); ++i) {
            float r = env.rgb[i * 3] * env.strength, g = env.rgb[i * 3 + 1] * env.strength,
                  b = env.rgb[i * 3 + 2] * env.strength;
            if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b) || r < 0.0f || g < 0.0f || b < 0.0f)
                throw Error(env.path + ": environment texel " + std::to_string(i % env.width) + "," +
                            std::to_string(i / env.width) + " is negative, NaN or infinite");
            map.texels[i] = {r, g, b, 0.0f};
        }
    }
    build_environment_distribution(map);
    return map;
}

} // namespace pathcl
