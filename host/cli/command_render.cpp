// `pathcl render`: loads a scene, applies the environment and camera flags, renders, and
// writes every requested image (and the camera-ray log) or none of them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "cl/cl_runtime.h"
#include "cli/commands.h"
#include "cli/help_format.h"
#include "cli/interrupt.h"
#include "cli/options.h"
#include "cli/progress_line.h"
#include "common/elapsed.h"
#include "common/error.h"
#include "common/file_identity.h"
#include "common/staged_files.h"
#include "image/image_io.h"
#include "image/image_module.h"
#include "render/checkpoint.h"
#include "render/partial_renders.h"
#include "render/ray_log.h"
#include "render/renderer.h"
#include "scene/camera_overrides.h"
#include "scene/environment_image.h"
#include "scene/gltf_loader.h"
#include "scene/scene_fingerprint.h"

namespace pathcl::cli {
namespace {

struct EnvironmentFlags {
    std::string file;
    float strength = 1.0f; // used only when given; else the scene's
    CLI::Option* strength_option = nullptr;
    double rotation_degrees = 0.0;
    std::vector<float> background; // empty or R, G, B
};

// Whether anything can be seen: a light, an environment, or an unlit surface.
bool shows_anything(const Scene& scene)
{
    if (!scene.lights.empty() || scene.environment.present)
        return true;
    for (const SceneTriangle& t : scene.triangles) {
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        if (m.emits() || m.unlit)
            return true;
    }
    return false;
}

void apply_environment_flags(Scene& scene, const EnvironmentFlags& f)
{
    SceneEnvironment& env = scene.environment;
    if (!f.background.empty()) {
        for (float c : f.background)
            if (!(c >= 0.0f) || !std::isfinite(c))
                throw Error("--background: components must be finite and non-negative");
        env = SceneEnvironment{};
        env.present = true;
        env.constant = glm::vec3(f.background[0], f.background[1], f.background[2]);
    }
    if (!f.file.empty()) {
        read_environment_image(env, f.file);
        env.strength = 1.0f;
    }
    if (f.strength_option->count()) {
        if (!(f.strength >= 0.0f) || !std::isfinite(f.strength))
            throw Error("--env-strength: must be finite and non-negative");
        env.strength = f.strength;
    }
    // Each factor is finite; their product must be too, for every texel of an image.
    const bool flags_scale = !f.background.empty() || f.strength_option->count();
    const float brightest = env.path.empty()
                                ? std::max({env.constant.x, env.constant.y, env.constant.z})
                                : (env.rgb.empty() ? 0.0f : *std::max_element(env.rgb.begin(), env.rgb.end()));
    if (flags_scale && !std::isfinite(brightest * env.strength)) {
        char text[160];
        std::snprintf(text, sizeof text, "the environment's radiance (%s %g x strength %g) is not finite as a float",
                      env.path.empty() ? "colour" : "brightest texel", static_cast<double>(brightest),
                      static_cast<double>(env.strength));
        throw Error((f.background.empty() ? "--env-strength: " : "--background: ") + std::string(text));
    }
    if (!std::isfinite(f.rotation_degrees))
        throw Error("--env-rotation: must be a finite number of degrees");
    env.rotation_degrees = f.rotation_degrees;
}

struct CameraFlags {
    int camera = -1; // --camera N; -1: the first camera node
    std::vector<double> look_from, look_at, up;
    double fov = 0.0, aperture = 0.0, focus_distance = 0.0;
    CLI::Option *fov_option = nullptr, *aperture_option = nullptr, *focus_option = nullptr;

    CameraOverrides overrides() const
    {
        CameraOverrides co;
        auto vec = [](const std::vector<double>& v) { return glm::dvec3(v[0], v[1], v[2]); };
        if (fov_option->count())
            co.fov_degrees = fov;
        if (!look_from.empty())
            co.look_from = vec(look_from);
        if (!look_at.empty())
            co.look_at = vec(look_at);
        if (!up.empty())
            co.up = vec(up);
        if (aperture_option->count())
            co.aperture = aperture;
        if (focus_option->count())
            co.focus_distance = focus_distance;
        return co;
    }
};

// --time, --target-error, --min-spp, --max-spp, --batch-spp, --adaptive: the budget flags.
struct BudgetFlags {
    CLI::Option *spp_option = nullptr, *max_spp_option = nullptr;
    std::uint32_t max_spp = 1u << 20;

    // A budget renders until it is spent, so --spp (the count) gives way to --max-spp
    // (the cap).
    void apply(RenderOptions& opt) const
    {
        // Before anything reads them as a budget: NaN is neither one nor none.
        if (!std::isfinite(opt.time_budget) || opt.time_budget < 0.0)
            throw Error("--time: must be a finite number of seconds above 0");
        if (!std::isfinite(opt.target_error) || opt.target_error < 0.0)
            throw Error("--target-error: must be a finite relative MSE above 0");
        const bool budget = opt.time_budget > 0.0 || opt.target_error > 0.0;
        if (budget && spp_option->count())
            throw Error("--spp fixes the sample count; with --time or --target-error cap it with --max-spp");
        if (!budget && max_spp_option->count())
            throw Error("--max-spp caps a budgeted render (--time, --target-error); use --spp");
        if (budget)
            opt.spp = max_spp;
    }
};

struct RenderRequest {
    std::string scene_path;
    std::vector<std::string> outputs;
    RenderOptions options;
    BudgetFlags budget;
    bool progress = false, quiet = false;
    std::string device = "0";          // --device: an index, a list or all
    std::vector<double> device_shares; // --device-shares: initial rows per device
    EnvironmentFlags environment;
    CameraFlags camera;
    std::string ray_log;            // --ray-log FILE.ply
    std::string checkpoint, resume; // --checkpoint FILE, --resume FILE
    double checkpoint_every = 60.0;
    DisplayTransform display;    // PNG outputs: --exposure EV, --tone
    std::string sample_range;    // --sample-range FIRST:COUNT
    std::string variant;         // --variant NAME
    bool copy_instances = false; // --copy-instances
};

// Every file the render reads: the scene's (its buffers and images), the environment map
// and the checkpoint it resumes.
std::vector<NamedFile> render_inputs(const RenderRequest& rq, const Scene& scene)
{
    std::vector<NamedFile> inputs;
    for (const std::string& file : scene.input_files)
        inputs.push_back({file, "scene file"});
    if (scene.environment.present && !scene.environment.path.empty())
        inputs.push_back({scene.environment.path, "environment map"});
    if (!rq.resume.empty())
        inputs.push_back({rq.resume, "--resume"});
    return inputs;
}

// Every file it writes.
std::vector<NamedFile> render_outputs(const RenderRequest& rq)
{
    std::vector<NamedFile> outputs;
    for (const std::string& output : rq.outputs)
        outputs.push_back({output, "-o"});
    if (!rq.checkpoint.empty())
        outputs.push_back({rq.checkpoint, "--checkpoint"});
    if (!rq.ray_log.empty())
        outputs.push_back({rq.ray_log, "--ray-log"});
    return outputs;
}

// "relMSE est. 1.2e-03 (batch means)", or the per-sample bound.
std::string error_summary(const RenderStats& s)
{
    if (s.error_estimate < 0.0)
        return "no error estimate";
    char buf[96];
    std::snprintf(buf, sizeof buf, "relMSE est. %s%.3g (%s)", s.error_is_bound ? "<= " : "", s.error_estimate,
                  s.batches >= 2 ? (std::to_string(s.batches) + " batches").c_str() : "per-sample variance");
    return buf;
}

void print_summary(const RenderRequest& rq, const RenderResult& r)
{
    const RenderStats& s = r.stats;
    std::string names;
    for (const std::string& output : rq.outputs)
        names += (names.empty() ? "" : ", ") + output;
    if (!rq.ray_log.empty())
        names += ", " + rq.ray_log + " (" + std::to_string(r.camera_rays.size()) + " rays)";
    std::string spp = std::to_string(s.spp) + " spp " + sampler_name(rq.options.sampler);
    if (rq.options.sample_count > 0)
        spp += " (samples " + rq.sample_range + " of " + std::to_string(rq.options.spp) + ")";
    else if (s.stop == StopReason::Spp && s.spp != rq.options.spp)
        spp += " (rounded up from " + std::to_string(rq.options.spp) + ")";
    std::string triangles = std::to_string(s.drawn_triangles) + " triangles";
    if (s.drawn_triangles != s.triangles)
        triangles += " (" + std::to_string(s.triangles) + " stored)";
    std::printf("%s: %s, %zu lights | %s | BVH build %.1f ms | kernel build %.2f s%s | render %.3f s | "
                "%.3g samples/s | %llu NaN/Inf samples | %s | stopped: %s\n",
                names.c_str(), triangles.c_str(), s.lights, spp.c_str(), s.bvh_build_seconds * 1e3,
                s.kernel_build_seconds, s.kernel_from_cache ? " (cached)" : "", s.render_seconds, s.samples_per_second,
                static_cast<unsigned long long>(s.bad_samples), error_summary(s).c_str(), stop_reason_name(s.stop));
}

int run_render(RenderRequest rq)
{
    set_image_module_prelude(load_opencl_platforms); // the OpenCL implementations before OpenImageIO
    if (!std::isfinite(rq.display.exposure_ev) || std::fabs(rq.display.exposure_ev) > 64.0)
        throw Error("--exposure: must be a finite number of stops between -64 and 64");
    for (const std::string& output : rq.outputs)
        check_output_path(output); // fail before spending time on the render
    if (!rq.ray_log.empty())
        check_ray_log_path(rq.ray_log);
    if (rq.camera.camera < -1)
        throw Error("--camera must be >= 0");
    Scene scene = load_gltf(rq.scene_path, {rq.camera.camera, rq.variant, rq.copy_instances});
    apply_environment_flags(scene, rq.environment);
    if (!shows_anything(scene))
        warn(rq.scene_path + ": has no light (no emissive material, punctual light or environment) and no unlit "
                             "material: the image is black (--background R,G,B or --env FILE adds light)");
    apply_camera_overrides(scene, rq.camera.overrides());
    if (!rq.checkpoint.empty()) {
        check_output_location(rq.checkpoint);
        if (!(rq.checkpoint_every > 0.0) || !std::isfinite(rq.checkpoint_every))
            throw Error("--checkpoint-every must be a positive number of seconds");
    }
    check_distinct_files(render_inputs(rq, scene), render_outputs(rq), [](const NamedFile& out, const NamedFile& in) {
        return out.role == "--checkpoint" && in.role == "--resume"; // a resumed render keeps its checkpoint
    });
    RenderOptions& opt = rq.options;
    rq.budget.apply(opt);
    if (!rq.sample_range.empty()) {
        const SampleRange range = parse_sample_range(rq.sample_range);
        opt.sample_first = range.first;
        opt.sample_count = range.count;
        for (const std::string& output : rq.outputs)
            if (lowercase_extension(output) != ".exr")
                throw Error(output + ": a sample range's film state is kept in EXR only (--sample-range)");
    }
    opt.devices = parse_devices(rq.device);
    if (!rq.device_shares.empty()) {
        double total = 0.0;
        for (double w : rq.device_shares) {
            if (!(w >= 0.0) || !std::isfinite(w))
                throw Error("--device-shares: shares must be finite and non-negative");
            total += w;
        }
        if (rq.device_shares.size() != opt.devices.size() || !(total > 0.0))
            throw Error("--device-shares: needs one share per device (" + std::to_string(opt.devices.size()) +
                        "), not all zero");
        opt.device_weights = rq.device_shares;
    }
    if (!rq.ray_log.empty())
        opt.ray_log_samples = 16; // 16 samples of each of up to 16 x 16 pixels
    std::optional<RenderCheckpoint> resume;
    if (!rq.resume.empty()) {
        if (!rq.ray_log.empty())
            throw Error("--ray-log cannot be combined with --resume (the logged rays are those of the first passes)");
        resume = read_checkpoint(rq.resume, static_cast<std::size_t>(opt.width) * opt.height);
    }
    // The module that writes the outputs (and OpenImageIO's libraries), loaded here: a
    // broken installation fails before the render, and a scene refused above never loads it.
    (void)image_module();
    Renderer renderer(scene, opt);
    catch_interrupts();
    RenderResult r;
    {
        ProgressLine line(rq.quiet      ? ProgressLine::Mode::Quiet
                          : rq.progress ? ProgressLine::Mode::Lines
                                        : ProgressLine::Mode::Auto,
                          rq.outputs.front());
        RenderRun run;
        run.seed = opt.seed;
        run.progress = [&](const RenderProgress& p) {
            line.show(p);
            return !interrupted();
        };
        if (resume || !rq.checkpoint.empty() || opt.sample_count > 0)
            run.scene_key = scene_fingerprint_hex(scene);
        run.resume = resume ? &*resume : nullptr;
        auto last_checkpoint = std::chrono::steady_clock::now();
        if (!rq.checkpoint.empty()) {
            run.checkpoint_due = [&]() { return seconds_since(last_checkpoint) >= rq.checkpoint_every; };
            run.checkpoint = [&](const RenderCheckpoint& cp) {
                write_checkpoint(rq.checkpoint, cp);
                last_checkpoint = std::chrono::steady_clock::now();
            };
        }
        try {
            r = renderer.render(run);
        } catch (const ParameterError& e) {
            if (e.parameter() != "resume")
                throw;
            throw Error(rq.resume + ": " + e.describe(flag_for)); // names the file as well as the flag
        }
    }
    // Every output complete before any replaces what the user has.
    StagedFiles staged;
    for (const std::string& output : rq.outputs)
        write_image_file(staged.stage(output), output, r.image, rq.display);
    if (!rq.ray_log.empty())
        write_ray_log_file(staged.stage(rq.ray_log), rq.ray_log, r.camera_rays);
    staged.commit();
    print_summary(rq, r);
    renderer.store_programs(); // after the image: a cold render shows it a second sooner
    return r.stats.stop == StopReason::Interrupted ? interrupted_exit_code() : 0;
}

void add_budget_flags(CLI::App* render, RenderRequest& rq)
{
    RenderOptions& o = rq.options;
    BudgetFlags& b = rq.budget;
    b.spp_option = render->get_option("--spp");
    render->add_option("--time", o.time_budget, "render whole passes until SECONDS are spent (then --max-spp caps)")
        ->type_name("SECONDS")
        ->check(CLI::PositiveNumber);
    render
        ->add_option("--target-error", o.target_error,
                     "stop when the estimated relMSE of the image (docs/accuracy.md) falls to E")
        ->type_name("E")
        ->check(CLI::PositiveNumber);
    render->add_option("--min-spp", o.min_spp, "with --target-error: take at least N samples per pixel")
        ->check(CLI::Range(1u, 1u << 30));
    b.max_spp_option =
        render->add_option("--max-spp", b.max_spp, "with --time or --target-error: at most N samples per pixel")
            ->capture_default_str()
            ->check(CLI::Range(1u, 1u << 30));
    render
        ->add_option("--batch-spp", o.batch_spp,
                     "samples per batch, each an independently scrambled point set whose spread estimates the error "
                     "(default: --spp in one batch; 16 with a budget)")
        ->check(CLI::Range(1u, 1u << 30));
    render->add_flag("--adaptive", o.adaptive,
                     "with --target-error: pixels whose estimated error (and their neighbours') reach it stop taking "
                     "samples (slightly biased where rare paths carry much light: docs/accuracy.md)");
    auto* progress =
        render->add_flag("--progress", rq.progress, "progress lines on stderr even when it is not a terminal");
    render->add_flag("--quiet", rq.quiet, "no progress line")->excludes(progress);
}

void add_camera_flags(CLI::App* render, CameraFlags& c)
{
    render->add_option("--camera", c.camera,
                       "camera node to render from: N-th camera node (perspective or orthographic) in depth-first "
                       "node order, from 0 (default: the first)");
    c.fov_option = render->add_option("--fov", c.fov, "vertical field of view in degrees (perspective camera)");
    render->add_option("--look-from", c.look_from, "camera position X,Y,Z (world space)")->delimiter(',')->expected(3);
    render->add_option("--look-at", c.look_at, "point the camera looks at X,Y,Z (world space)")
        ->delimiter(',')
        ->expected(3);
    render->add_option("--up", c.up, "up direction X,Y,Z for --look-at (default: the camera's up)")
        ->delimiter(',')
        ->expected(3);
    c.aperture_option = render->add_option("--aperture", c.aperture, "thin-lens radius in world units (0: pinhole)");
    c.focus_option =
        render->add_option("--focus-distance", c.focus_distance, "distance of the plane of focus along the view");
}

void add_environment_flags(CLI::App* render, EnvironmentFlags& e)
{
    render->add_option("--env", e.file, "equirectangular environment map (EXR/HDR), overrides the scene's")
        ->check(CLI::ExistingFile);
    e.strength_option =
        render->add_option("--env-strength", e.strength, "environment radiance scale (default: the scene's, else 1)");
    render->add_option("--env-rotation", e.rotation_degrees, "rotate the environment about +Y, degrees");
    render->add_option("--background", e.background, "constant environment radiance R,G,B")
        ->delimiter(',')
        ->expected(3);
}

// The help's groups in the order of docs/usage.md, and the examples it ends with.
void describe_render_command(CLI::App* render)
{
    describe_command(
        render,
        {{kOutputGroup, {"--output", "--exposure", "--tone"}},
         {kSamplingGroup, {"--seed"}},
         {kBudgetGroup,
          {"--time", "--target-error", "--min-spp", "--max-spp", "--batch-spp", "--adaptive", "--progress", "--quiet"}},
         {kCameraGroup, {"--camera", "--fov", "--look-from", "--look-at", "--up", "--aperture", "--focus-distance"}},
         {kEnvironmentGroup, {"--env", "--env-strength", "--env-rotation", "--background"}},
         {kSceneGroup, {}},
         {kDeviceGroup, {"--device-shares"}},
         {kDistributedGroup, {"--sample-range"}},
         {kCheckpointGroup, {"--checkpoint", "--checkpoint-every", "--resume"}},
         {kKernelGroup, {}},
         {kDiagnosticGroup, {"--ray-log"}}},
        {{"pathcl render scenes/cornell-box.gltf -o box.png",
          "the Cornell box at 512x512 and 64 samples per pixel, as an sRGB PNG"},
         {"pathcl render scenes/sky-spheres.gltf -o sky.exr -o sky.png --width 1280 --height 720 --spp 256 "
          "--tone filmic",
          "one render written twice: a linear EXR (with its variance) and a PNG through the filmic curve"},
         {"pathcl render scenes/cornell-box.gltf -o box.exr --target-error 0.001 --max-spp 4096",
          "render until the estimated relative MSE is 0.001 (or 4096 samples per pixel)"},
         {"pathcl render scenes/material-spheres.gltf -o spheres.png --env scenes/sky.hdr --env-rotation 90",
          "light the scene by an environment map, turned 90 degrees about +Y"},
         {"pathcl render scenes/cornell-box.gltf -o corner.png --look-from 0.05,0.5,-0.3 --look-at 0.3,0.2,0.3 "
          "--fov 50",
          "the same scene seen from another place"},
         {"pathcl render scenes/cornell-box.gltf -o box.exr --time 600 --checkpoint box.ckpt",
          "ten minutes of samples; after Ctrl-C or a crash, the same command with --resume box.ckpt continues it"},
         {"pathcl render scenes/cornell-box.gltf -o half1.exr --spp 1024 --batch-spp 64 --sample-range 0:512",
          "the first half of a 1024-spp render's samples, for 'pathcl merge' to add to the second (512:512)"}});
}

} // namespace

Command add_render_command(CLI::App& app)
{
    auto rq = std::make_shared<RenderRequest>();
    CLI::App* render = app.add_subcommand("render", "Render a glTF scene to an EXR or PNG image");
    render->add_option("scene", rq->scene_path, "glTF 2.0 scene (.gltf or .glb)")->required();
    render
        ->add_option(
            "-o,--output", rq->outputs,
            "output image, repeatable (.exr: linear float + variance; .png: sRGB, after --exposure and --tone)")
        ->type_name("FILE")
        ->required()
        ->allow_extra_args(false);
    add_render_options(render, rq->options, rq->device);
    add_budget_flags(render, *rq);
    render->add_option("--seed", rq->options.seed, "random seed (same seed, scene, options: same image)")
        ->capture_default_str();
    add_environment_flags(render, rq->environment);
    add_camera_flags(render, rq->camera);
    render
        ->add_option("--device-shares", rq->device_shares,
                     "with several devices: each one's initial share of the rows (default: equal; the render "
                     "re-deals them by measured speed after its second pass)")
        ->delimiter(',');
    render
        ->add_option("--exposure", rq->display.exposure_ev,
                     "PNG outputs: scale radiance by 2^EV before the tone curve (EXR stays linear)")
        ->type_name("EV");
    const std::vector<std::pair<std::string, ToneCurve>> tones = {{"clip", ToneCurve::Clip},
                                                                  {"filmic", ToneCurve::Filmic}};
    add_enum_option(render, "--tone", rq->display.tone, tones,
                    "PNG outputs: tone curve, clip (clamp to [0, 1]) or filmic (ACES fit: rolls highlights off)");
    render
        ->add_option("--ray-log", rq->ray_log,
                     "write camera rays (16 samples of up to 16x16 pixels) to a .ply point cloud: origins, with "
                     "directions as normals")
        ->type_name("FILE");
    render
        ->add_option("--checkpoint", rq->checkpoint,
                     "write the render's state to FILE every --checkpoint-every seconds and when it stops early, "
                     "so that --resume FILE continues it")
        ->type_name("FILE");
    render->add_option("--checkpoint-every", rq->checkpoint_every, "seconds between checkpoints")
        ->type_name("SECONDS")
        ->capture_default_str();
    render
        ->add_option("--resume", rq->resume,
                     "continue the render whose checkpoint FILE holds (same scene and options: the image equals "
                     "the uninterrupted render's bit for bit)")
        ->type_name("FILE");
    render
        ->add_option("--sample-range", rq->sample_range,
                     "render only sample indices FIRST .. FIRST+COUNT-1 of the --spp render (whole batches of "
                     "--batch-spp): the EXR keeps the exact film state, and 'pathcl merge' adds the ranges into "
                     "the whole render's image bit for bit")
        ->type_name("FIRST:COUNT");
    add_program_options(render, rq->options);
    add_variant_option(render, rq->variant);
    add_copy_instances_option(render, rq->copy_instances);
    describe_render_command(render);
    return {render, [rq] { return run_render(*rq); }};
}

} // namespace pathcl::cli
