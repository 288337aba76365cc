// Ray throughput of pathcl's BVH traversal (the real kernels/bvh/, through the test
// kernels in tests/kernels/trace_test_kernels.cl) against Embree 3 on the same rays and
// the same machine: closest hit and any hit, for incoherent rays (origins uniform in the
// scene's bounds, directions uniform on the sphere, like diffuse bounces) and coherent
// ones (the scene camera's primary rays). Embree runs on one thread per core, through its
// single-ray API (what pathcl's one ray per work-item compares with) and through its
// 16-ray packet API (rtcIntersect16 / rtcOccluded16 on consecutive rays), which is how
// Mitsuba 3's LLVM backend traces on a 16-wide machine.
//
//   bench_rays SCENE.gltf [--rays N] [--runs R] [--device I]
//
// Prints, per case, min / median / max million rays per second over R timed runs (after
// one warm-up) and the ratios of the medians.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <embree3/rtcore.h>

#include "cl/cl_runtime.h"
#include "cl/kernel_args.h"
#include "common/elapsed.h"
#include "common/error.h"
#include "compile/compile_scene.h"
#include "scene/gltf_loader.h"

namespace {

using namespace pathcl;

struct Rays {
    std::vector<pcl_float4> origin, dir;
};

Rays incoherent_rays(const Scene& scene, std::size_t n)
{
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    glm::vec3 margin = 0.01f * (hi - lo);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Rays r;
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 p = lo + margin + (hi - lo - 2.0f * margin) * glm::vec3(u(rng), u(rng), u(rng));
        float z = 2.0f * u(rng) - 1.0f, phi = 6.2831853f * u(rng), s = std::sqrt(std::max(0.0f, 1.0f - z * z));
        r.origin.push_back({p.x, p.y, p.z, 0.0f});
        r.dir.push_back({s * std::cos(phi), s * std::sin(phi), z, 0.0f});
    }
    return r;
}

Rays primary_rays(const Scene& scene, std::size_t n)
{
    // A square image whose side is a multiple of 8, so that the ray count is a multiple of
    // the kernels' 64-item work-groups (for any n >= 64).
    std::uint32_t side = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n))) / 8 * 8;
    Camera c = compile_camera(scene.camera, side, side);
    Rays r;
    for (std::uint32_t y = 0; y < side; ++y)
        for (std::uint32_t x = 0; x < side; ++x) {
            float sx = 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(side) - 1.0f;
            float sy = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(side);
            glm::vec3 d = glm::vec3(c.forward.x, c.forward.y, c.forward.z) +
                          sx * glm::vec3(c.right.x, c.right.y, c.right.z) + sy * glm::vec3(c.up.x, c.up.y, c.up.z);
            d = glm::normalize(d);
            r.origin.push_back(c.position);
            r.dir.push_back({d.x, d.y, d.z, 0.0f});
        }
    return r;
}

struct Stats {
    double min, median, max;
};

template <class F>
Stats time_runs(int runs, std::size_t rays, F f)
{
    f(); // warm-up (PoCL compiles the work-group function on the first launch)
    std::vector<double> rate;
    for (int i = 0; i < runs; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        f();
        double s = seconds_since(t0);
        rate.push_back(static_cast<double>(rays) / s / 1e6);
    }
    std::sort(rate.begin(), rate.end());
    return {rate.front(), rate[rate.size() / 2], rate.back()};
}

struct Pathcl {
    ClDevice dev;
    cl::Program program;
    cl::Buffer nodes, triangles, blocks;

    Pathcl(int device, const SceneArrays& ds) : dev(open_device(device))
    {
        std::string src;
        {
            std::FILE* f = std::fopen(PATHCL_SOURCE_DIR "/tests/kernels/trace_test_kernels.cl", "rb");
            if (!f)
                throw Error(PATHCL_SOURCE_DIR "/tests/kernels/trace_test_kernels.cl: cannot open");
            char buf[4096];
            std::size_t got;
            while ((got = std::fread(buf, 1, sizeof buf, f)) > 0)
                src.append(buf, got);
            std::fclose(f);
        }
        ProgramSource source;
        source.root = "tests/kernels/trace_test_kernels.cl";
        source.text = src;
        program = build_program(dev, "", source).program;
        nodes = cl::Buffer(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, ds.nodes.size() * sizeof(BvhNode),
                           const_cast<BvhNode*>(ds.nodes.data()));
        triangles = cl::Buffer(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                               ds.triangles.size() * sizeof(Triangle), const_cast<Triangle*>(ds.triangles.data()));
        blocks = cl::Buffer(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                            ds.triangle_blocks.size() * sizeof(TriangleBlock),
                            const_cast<TriangleBlock*>(ds.triangle_blocks.data()));
    }

    Stats run(const Rays& r, bool any_hit, int runs)
    {
        std::size_t n = r.origin.size();
        cl::Buffer o(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4),
                     const_cast<pcl_float4*>(r.origin.data()));
        cl::Buffer d(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4),
                     const_cast<pcl_float4*>(r.dir.data()));
        cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
        cl::Kernel k(program, any_hit ? "test_any_hit" : "test_trace_closest");
        if (any_hit)
            set_kernel_args(k, o, d, nodes, triangles, blocks, INFINITY, out);
        else
            set_kernel_args(k, o, d, nodes, triangles, blocks, out);
        std::size_t global = (n + 63) / 64 * 64;
        if (global != n)
            throw Error("bench_rays: the ray count must be a multiple of 64");
        return time_runs(runs, n, [&] {
            dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(global), cl::NDRange(64));
            dev.queue.finish();
        });
    }
};

struct Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;

    explicit Embree(const SceneArrays& ds)
    {
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        std::size_t n = ds.triangles.size();
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
        for (std::size_t i = 0; i < n; ++i) {
            const pcl_float4* p[3] = {&ds.triangles[i].v0, &ds.triangles[i].v1, &ds.triangles[i].v2};
            for (int k = 0; k < 3; ++k) {
                v[(3 * i + k) * 3 + 0] = p[k]->x;
                v[(3 * i + k) * 3 + 1] = p[k]->y;
                v[(3 * i + k) * 3 + 2] = p[k]->z;
                idx[3 * i + k] = static_cast<unsigned>(3 * i + k);
            }
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    ~Embree()
    {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }

    // On one thread per core: `work(t, threads)` traces thread t's share.
    template <class Work>
    static Stats on_every_core(int runs, std::size_t n, Work work)
    {
        unsigned threads = std::max(1u, std::thread::hardware_concurrency());
        return time_runs(runs, n, [&] {
            std::vector<std::thread> pool;
            for (unsigned t = 1; t < threads; ++t)
                pool.emplace_back(work, t, threads);
            work(0, threads);
            for (std::thread& th : pool)
                th.join();
        });
    }

    Stats run(const Rays& r, bool any_hit, int runs)
    {
        std::size_t n = r.origin.size();
        std::vector<float> sink(std::max(1u, std::thread::hardware_concurrency()), 0.0f);
        auto work = [&](unsigned t, unsigned threads) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            float acc = 0.0f;
            for (std::size_t i = t; i < n; i += threads) {
                RTCRay ray{};
                ray.org_x = r.origin[i].x;
                ray.org_y = r.origin[i].y;
                ray.org_z = r.origin[i].z;
                ray.dir_x = r.dir[i].x;
                ray.dir_y = r.dir[i].y;
                ray.dir_z = r.dir[i].z;
                ray.tnear = 0.0f;
                ray.tfar = INFINITY;
                ray.mask = ~0u;
                if (any_hit) {
                    rtcOccluded1(scene, &ctx, &ray);
                    acc += ray.tfar;
                } else {
                    RTCRayHit rh{};
                    rh.ray = ray;
                    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                    rtcIntersect1(scene, &ctx, &rh);
                    acc += rh.ray.tfar;
                }
            }
            sink[t] = acc;
        };
        return on_every_core(runs, n, work);
    }

    // The same rays through the 16-ray packet API: consecutive rays make a packet.
    Stats run_packets(const Rays& r, bool any_hit, int runs)
    {
        std::size_t n = r.origin.size();
        std::vector<float> sink(std::max(1u, std::thread::hardware_concurrency()), 0.0f);
        auto work = [&](unsigned t, unsigned threads) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            alignas(64) int valid[16];
            alignas(64) RTCRayHit16 rh;
            float acc = 0.0f;
            for (std::size_t first = 16 * t; first < n; first += 16 * static_cast<std::size_t>(threads)) {
                for (std::size_t k = 0; k < 16; ++k) {
                    std::size_t i = std::min(first + k, n - 1);
                    valid[k] = first + k < n ? -1 : 0;
                    rh.ray.org_x[k] = r.origin[i].x;
                    rh.ray.org_y[k] = r.origin[i].y;
                    rh.ray.org_z[k] = r.origin[i].z;
                    rh.ray.dir_x[k] = r.dir[i].x;
                    rh.ray.dir_y[k] = r.dir[i].y;
                    rh.ray.dir_z[k] = r.dir[i].z;
                    rh.ray.tnear[k] = 0.0f;
                    rh.ray.tfar[k] = INFINITY;
                    rh.ray.mask[k] = ~0u;
                    rh.ray.time[k] = 0.0f;
                    rh.ray.flags[k] = 0;
                    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                }
                if (any_hit)
                    rtcOccluded16(valid, scene, &ctx, &rh.ray);
                else
                    rtcIntersect16(valid, scene, &ctx, &rh);
                for (std::size_t k = 0; k < 16; ++k)
                    acc += rh.ray.tfar[k];
            }
            sink[t] = acc;
        };
        return on_every_core(runs, n, work);
    }
};

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"Ray throughput of pathcl's BVH traversal against Embree on the same rays"};
    std::string path;
    std::size_t rays = 1 << 20;
    int runs = 5, device = 0;
    app.add_option("scene", path, "glTF 2.0 scene")->required();
    app.add_option("--rays", rays, "rays per run (a multiple of 64)")->capture_default_str();
    app.add_option("--runs", runs, "timed runs after one warm-up")->capture_default_str()->check(CLI::Range(1, 1000));
    app.add_option("--device", device, "OpenCL device index")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (rays == 0 || rays % 64 != 0) {
        std::fprintf(stderr, "bench_rays: error: --rays %zu is not a positive multiple of 64\n", rays);
        return 2;
    }
    try {
        // Embree here gets the triangles in render space: instanced meshes are copied.
        SceneChoice copies;
        copies.copy_instances = true;
        Scene scene = load_gltf(path, copies);
        CompiledScene cs = compile_scene(scene, kernel_features(scene, RenderOptions{}));
        const SceneArrays& ds = cs.arrays;
        Pathcl pc(device, ds);
        Embree em(ds);
        std::printf("%s: %zu triangles, %zu rays per run, %d runs; Mrays/s min / median / max (pathcl / embree)\n",
                    path.c_str(), ds.triangles.size(), rays, runs);
        Rays incoherent = incoherent_rays(scene, rays), primary = primary_rays(scene, rays);
        rays = primary.origin.size();
        for (auto [name, r] : {std::pair{"incoherent", &incoherent}, std::pair{"primary", &primary}})
            for (bool any : {false, true}) {
                Stats p = pc.run(*r, any, runs), e = em.run(*r, any, runs), q = em.run_packets(*r, any, runs);
                std::printf("  %-10s %-7s pathcl %6.2f / %6.2f / %6.2f | embree %6.2f / %6.2f / %6.2f (%.2f) | embree "
                            "16-ray packets %6.2f / %6.2f / %6.2f (%.2f)\n",
                            name, any ? "any" : "closest", p.min, p.median, p.max, e.min, e.median, e.max,
                            p.median / e.median, q.min, q.median, q.max, p.median / q.median);
            }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_rays: error: %s\n", e.what());
        return 2;
    }
    return 0;
}
