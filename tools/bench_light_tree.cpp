// Build speed of the light tree (compile/light_tree.h) on the host: build_light_tree over
// light records and their powers, as `pathcl bench` times it, over a scene's lights or over N random
// lights of every kind with a position (emissive triangles, points, spots, rectangular
// spots, spheres; a few directional ones stay beside the tree) spread over a 100 m cube.
//
//   bench_light_tree [SCENE.gltf] [--lights N] [--seed S] [--runs R] [--dump FILE]
//
// Prints min / median / max build time and million lights a second over R timed runs
// (after one warm-up), and a hash of the tree (what the device reads of it, and its
// depth): builds that must agree bit for bit print the same hash. --dump writes those
// bytes to FILE.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/elapsed.h"
#include "common/error.h"
#include "common/fnv1a.h"
#include "compile/compile_scene.h"
#include "compile/light_tree.h"
#include "scene/gltf_loader.h"

namespace {

using namespace pathcl;

pcl_float4 float4(const glm::dvec3& v)
{
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

glm::dvec3 random_direction(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double z = 2.0 * u(rng) - 1.0, phi = 2.0 * std::numbers::pi * u(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// n light records of mixed kinds and their powers (over four decades): mostly small
// triangles, as a scene of emissive meshes has, and every punctual kind.
void random_lights(std::size_t n, std::uint64_t seed, std::vector<Light>& lights, std::vector<double>& power)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> position(-50.0, 50.0), size(0.001, 0.5), decades(-2.0, 2.0), unit(0.0, 1.0);
    lights.assign(n, Light{});
    power.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Light& l = lights[i];
        const glm::dvec3 p(position(rng), position(rng), position(rng));
        const double kind = unit(rng);
        if (kind < 0.6) {
            l.type = LIGHT_TRIANGLE;
            const double s = size(rng);
            l.data.triangle.v0 = float4(p);
            l.data.triangle.v1 = float4(p + s * random_direction(rng));
            l.data.triangle.v2 = float4(p + s * random_direction(rng));
        } else if (kind < 0.7) {
            l.type = LIGHT_POINT;
            l.data.point.position = float4(p);
        } else if (kind < 0.8) {
            l.type = LIGHT_SPOT;
            l.data.spot.position = float4(p);
            l.data.spot.axis = float4(random_direction(rng));
            l.data.spot.cos_outer = static_cast<float>(std::cos(unit(rng) * 1.5));
        } else if (kind < 0.9) {
            l.type = LIGHT_RECT_SPOT;
            l.data.rect_spot.position = float4(p);
            l.data.rect_spot.axis = float4(random_direction(rng));
            l.data.rect_spot.tan_half_h = static_cast<float>(0.1 + 2.0 * unit(rng));
            l.data.rect_spot.tan_half_v = static_cast<float>(0.1 + 2.0 * unit(rng));
        } else if (kind < 0.9999) {
            l.type = LIGHT_SPHERE;
            l.data.sphere.centre = float4(p);
            l.data.sphere.radius = static_cast<float>(size(rng));
        } else {
            l.type = LIGHT_DIRECTIONAL;
            l.data.directional.direction = float4(random_direction(rng));
        }
        power[i] = std::pow(10.0, decades(rng));
    }
}

// The tree as bytes: everything the device reads of it (its node array, the trails, the
// clusters' lights, the infinite lights and how often one is picked) and its depth.
std::string tree_bytes(const LightTree& tree)
{
    std::string out;
    const auto append = [&out](const auto* data, std::size_t count) {
        out.append(reinterpret_cast<const char*>(data), count * sizeof(*data));
    };
    append(tree.nodes.data(), tree.nodes.size());
    append(tree.trails.data(), tree.trails.size());
    append(tree.cluster.data(), tree.cluster.size());
    append(tree.infinite.data(), tree.infinite.size());
    append(&tree.infinite_pick, 1);
    append(&tree.depth, 1);
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    std::string scene_path, dump_path;
    std::size_t count = 1000000;
    std::uint64_t seed = 1;
    int runs = 5;
    CLI::App app{"Build speed of the light tree"};
    app.add_option("scene", scene_path, "a glTF scene whose lights to build over (default: random lights)");
    app.add_option("--lights", count, "random lights to build over")->check(CLI::Range(1, 1 << 30));
    app.add_option("--seed", seed, "seed of the random lights");
    app.add_option("--runs", runs, "timed runs")->check(CLI::Range(1, 1000));
    app.add_option("--dump", dump_path, "write the tree's bytes (as hashed) to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        std::vector<Light> lights;
        std::vector<double> power;
        if (scene_path.empty()) {
            random_lights(count, seed, lights, power);
        } else {
            const Scene scene = load_gltf(scene_path);
            RenderOptions options;
            options.light_sampler = LightSampler::Tree;
            CompiledScene compiled;
            const std::vector<std::uint32_t> leaf_order = compile_geometry(scene, compiled);
            compile_materials(scene, kernel_features(scene, options), compiled.arrays);
            power = compile_lights(scene, leaf_order, compiled);
            lights = compiled.arrays.lights;
        }
        LightTree tree = build_light_tree(lights, power); // warm-up
        std::vector<double> seconds;
        for (int i = 0; i < runs; ++i) {
            const auto start = std::chrono::steady_clock::now();
            tree = build_light_tree(lights, power);
            seconds.push_back(seconds_since(start));
        }
        std::sort(seconds.begin(), seconds.end());
        const double n = static_cast<double>(lights.size());
        const std::string bytes = tree_bytes(tree);
        std::printf("%zu lights (%zu infinite): %zu nodes, %u levels, hash %016llx\n", lights.size(),
                    tree.infinite.size(), tree.nodes.size(), tree.depth,
                    static_cast<unsigned long long>(fnv1a64(bytes.data(), bytes.size())));
        std::printf("build ms min / median / max: %.1f / %.1f / %.1f | Mlights/s: %.3f / %.3f / %.3f\n",
                    seconds.front() * 1e3, seconds[seconds.size() / 2] * 1e3, seconds.back() * 1e3,
                    n / seconds.back() * 1e-6, n / seconds[seconds.size() / 2] * 1e-6, n / seconds.front() * 1e-6);
        if (!dump_path.empty()) {
            std::ofstream out(dump_path, std::ios::binary);
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            if (!out)
                throw Error("cannot write " + dump_path);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_light_tree: %s\n", e.what());
        return 1;
    }
    return 0;
}
