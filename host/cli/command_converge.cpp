// `pathcl converge`: what accuracy costs in time on the user's own scene. Renders every
// setting of the --vary knobs at every spp of a ladder with several seeds, against a
// reference (rendered by pathcl and cached in DIR, or read from a file), and writes
// DIR/convergence.csv (row by row: an interrupted study keeps its rows),
// DIR/error_vs_time.png, DIR/error_vs_spp.png and DIR/summary.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "cl/cl_runtime.h"
#include "cli/commands.h"
#include "cli/help_format.h"
#include "cli/interrupt.h"
#include "cli/options.h"
#include "cli/progress_line.h"
#include "common/error.h"
#include "common/staged_files.h"
#include "common/text_fields.h"
#include "converge/convergence.h"
#include "converge/convergence_csv.h"
#include "converge/convergence_plots.h"
#include "converge/convergence_summary.h"
#include "image/image_io.h"
#include "image/image_module.h"
#include "render/batches.h"
#include "scene/gltf_loader.h"

namespace pathcl::cli {
namespace {

namespace fs = std::filesystem;

struct ConvergeRequest {
    std::string scene_path, out_dir;
    std::string variant;         // --variant NAME
    bool copy_instances = false; // --copy-instances
    std::vector<std::string> vary;
    std::string ladder_text = "1,2,4,8,16,32,64,128,256"; // --spp-ladder
    std::vector<std::uint32_t> ladder;
    std::uint32_t seeds = 3;
    std::string reference_file;
    std::uint32_t reference_spp = 4096;
    std::string targets_text; // --targets
    std::vector<double> targets;
    RenderOptions options;
    std::string device = "0"; // --device: an index, a list or all
    bool quiet = false;
    std::string command; // as typed, for summary.md
};

// The reference image: the file given, or the one cached in DIR when it was rendered
// from this scene with these options, or a new render (written to DIR at once, so an
// interrupted study keeps it). `how` says which, for summary.md. Empty when interrupted.
std::optional<Image> obtain_reference(const ConvergeRequest& rq, const Scene& scene, const ConvergenceStudy& study,
                                      std::string& how)
{
    const std::uint32_t w = study.base.width, h = study.base.height;
    if (!rq.reference_file.empty()) {
        Image ref = read_image(rq.reference_file);
        if (ref.width != w || ref.height != h)
            throw Error(rq.reference_file + ": the reference is " + std::to_string(ref.width) + "x" +
                        std::to_string(ref.height) + ", the study " + std::to_string(w) + "x" + std::to_string(h));
        if (ref.spp == 0) { // another renderer's image: taken as exact
            ref.spp = 1;
            ref.variance.assign(ref.rgb.size(), 0.0f);
        }
        how = "read from " + rq.reference_file;
        return ref;
    }
    RenderOptions ro = reference_options(study, rq.reference_spp);
    const std::string key = reference_key(scene, ro);
    const std::string cached = (fs::path(rq.out_dir) / "reference.exr").string();
    how = "rendered by pathcl (" + key + "), cached in reference.exr";
    if (fs::exists(cached)) {
        try {
            Image ref = read_image(cached);
            if (ref.metadata["converge_key"] == key && ref.width == w && ref.height == h)
                return ref;
        } catch (const Error&) {
            // unreadable: render it again
        }
    }
    Renderer renderer(scene, ro);
    ProgressLine line(rq.quiet ? ProgressLine::Mode::Quiet : ProgressLine::Mode::Auto, "reference");
    RenderResult r = renderer.render(ro.seed, [&](const RenderProgress& p) {
        line.show(p);
        return !interrupted();
    });
    line.finish();
    if (r.stats.stop == StopReason::Interrupted)
        return std::nullopt;
    r.image.metadata["converge_key"] = key;
    write_image(cached, r.image);
    std::fprintf(stderr, "reference: %u spp in %.1f s, written to %s\n", r.stats.spp, r.stats.render_seconds,
                 cached.c_str());
    return r.image;
}

// A study renders at most this many images (settings x ladder steps x seeds).
constexpr std::uint64_t kMaxStudyRenders = 100000;

// --spp-ladder: whole numbers from 1 to 2^20, each larger than the one before.
std::vector<std::uint32_t> parse_ladder(const std::string& text)
{
    std::vector<std::uint32_t> ladder;
    for (const std::string& item : split_commas(text)) {
        auto v = parse_whole_number(item, 1u << 20);
        if (!v || *v == 0)
            throw Error("--spp-ladder: " + quote(item) + " in " + quote(text) +
                        " is not a number of samples from 1 to 1048576");
        if (!ladder.empty() && *v <= ladder.back())
            throw Error("--spp-ladder: " + quote(text) +
                        " does not rise: each step takes more samples than the one "
                        "before");
        ladder.push_back(static_cast<std::uint32_t>(*v));
    }
    return ladder;
}

// --targets: relative MSEs, finite and positive.
std::vector<double> parse_targets(const std::string& text)
{
    std::vector<double> targets;
    for (const std::string& item : split_commas(text)) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v) || !(v > 0.0))
            throw Error("--targets: " + quote(item) + " is not a finite relative MSE above 0");
        targets.push_back(v);
    }
    return targets;
}

int run_converge(ConvergeRequest rq)
{
    set_image_module_prelude(load_opencl_platforms); // the OpenCL implementations before OpenImageIO
    if (rq.vary.empty())
        throw Error("--vary: give at least one knob to vary (KNOB=V1,V2,...)");
    rq.ladder = parse_ladder(rq.ladder_text);
    if (!rq.targets_text.empty())
        rq.targets = parse_targets(rq.targets_text);
    if (fs::exists(rq.out_dir) && !fs::is_directory(rq.out_dir))
        throw Error(rq.out_dir + ": exists and is not a directory");
    std::vector<Knob> knobs;
    for (const std::string& v : rq.vary)
        knobs.push_back(parse_knob(v));
    ConvergenceStudy study;
    study.base = rq.options;
    study.base.devices = parse_devices(rq.device);
    study.settings = settings_product(study.base, knobs);
    study.ladder = rq.ladder;
    study.seeds = rq.seeds;
    const std::uint64_t renders = std::uint64_t(study.settings.size()) * study.ladder.size() * study.seeds;
    if (renders > kMaxStudyRenders)
        throw Error("converge: " + std::to_string(study.settings.size()) + " settings x " +
                    std::to_string(study.ladder.size()) + " ladder steps (--spp-ladder) x " +
                    std::to_string(study.seeds) + " seeds (--seeds) make " + std::to_string(renders) +
                    " renders, more than the " + std::to_string(kMaxStudyRenders) + " a study may have");
    for (const Setting& s : study.settings) { // fail on a bad combination before any render
        RenderOptions o = s.options;
        if (o.adaptive)
            o.target_error = 1.0;
        plan_batches(o);
    }
    Scene scene = load_gltf(rq.scene_path, {-1, rq.variant, rq.copy_instances});
    fs::create_directories(rq.out_dir);
    catch_interrupts();

    ConvergenceReport report;
    report.scene_path = rq.scene_path;
    report.command = rq.command;
    report.study = &study;
    report.targets = rq.targets;
    report.builds.resize(study.settings.size());
    std::optional<Image> reference = obtain_reference(rq, scene, study, report.reference);
    if (!reference) {
        std::fprintf(stderr, "pathcl: interrupted while rendering the reference; nothing written\n");
        return interrupted_exit_code();
    }

    const fs::path dir(rq.out_dir);
    StagedFiles staged;
    const std::string csv_path = staged.stage((dir / "convergence.csv").string());
    std::ofstream csv(csv_path);
    csv << csv_header(study) << std::flush;
    const std::size_t total = study.settings.size() * study.ladder.size() * study.seeds;
    ProgressLine line(rq.quiet ? ProgressLine::Mode::Quiet : ProgressLine::Mode::Auto, "converge");
    ConvergenceCallbacks cb;
    cb.setting_built = [&](std::size_t s, const SettingBuild& b) {
        report.builds[s] = b;
        line.finish();
        if (!rq.quiet)
            std::fprintf(stderr, "setting %zu/%zu (%s): kernel build %.2f s cold, %.3f s cached, first render %.3f s\n",
                         s + 1, study.settings.size(), study.settings[s].label().c_str(), b.cold_seconds,
                         b.cached_seconds, b.first_render_seconds);
    };
    cb.row = [&](const ConvergenceRow& row) {
        report.rows.push_back(row);
        csv << csv_line(study, report.builds, row) << std::flush;
        if (!csv)
            throw Error(csv_path + ": cannot write the CSV rows");
        return !interrupted();
    };
    cb.progress = [&](const ConvergenceRow& row, const RenderProgress& p) {
        line.show(p, "render " + std::to_string(report.rows.size() + 1) + "/" + std::to_string(total) + " (" +
                         study.settings[row.setting].label() + ", " + std::to_string(row.spp) + " spp, seed " +
                         std::to_string(row.seed) + ")");
        return !interrupted();
    };
    report.interrupted = !run_convergence(scene, study, *reference, cb);
    line.finish();
    csv.close();

    std::ofstream md(staged.stage((dir / "summary.md").string()));
    md << summary_markdown(report);
    md.close();
    if (!md)
        throw Error((dir / "summary.md").string() + ": cannot write");
    write_image_file(staged.stage((dir / "error_vs_time.png").string()), (dir / "error_vs_time.png").string(),
                     error_plot(report, true));
    write_image_file(staged.stage((dir / "error_vs_spp.png").string()), (dir / "error_vs_spp.png").string(),
                     error_plot(report, false));
    staged.commit();
    std::printf("%s: %zu of %zu renders; convergence.csv, summary.md, error_vs_time.png, error_vs_spp.png%s\n",
                rq.out_dir.c_str(), report.rows.size(), total, report.interrupted ? " (interrupted)" : "");
    return report.interrupted ? interrupted_exit_code() : 0;
}

} // namespace

Command add_converge_command(CLI::App& app, int argc, char** argv)
{
    auto rq = std::make_shared<ConvergeRequest>();
    rq->options.width = rq->options.height = 256;
    for (int i = 0; i < argc; ++i)
        rq->command += (i ? " " : "") + std::string(argv[i]);
    CLI::App* c = app.add_subcommand("converge", "Error against time for every setting of the knobs you vary");
    c->add_option("scene", rq->scene_path, "glTF 2.0 scene (.gltf or .glb)")->required();
    c->add_option("-o,--output", rq->out_dir, "directory for convergence.csv, summary.md and the plots")->required();
    c->add_option(
         "--vary", rq->vary,
         "KNOB=V1,V2,... (repeatable: the product); knobs: sampler, strategy, max-bounces, "
         "stratified-bounces, batch-spp, fast-math, specialization, adaptive, light-sampler, triangle-sampling, "
         "integrator")
        ->required();
    c->add_option("--spp-ladder", rq->ladder_text, "samples per pixel to render each setting at, rising (S1,S2,...)")
        ->capture_default_str();
    c->add_option("--seeds", rq->seeds, "renders per setting and spp (seeds --seed, --seed + 1, ...)")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1000u));
    auto* file = c->add_option("--reference", rq->reference_file,
                               "reference EXR of the same size (any renderer's; without variances it counts as "
                               "exact)")
                     ->check(CLI::ExistingFile);
    c->add_option("--reference-spp", rq->reference_spp,
                  "spp of the reference pathcl renders (Sobol', with the base options and the largest bounce "
                  "limit), cached in the output directory")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1u << 24))
        ->excludes(file);
    c->add_option("--targets", rq->targets_text,
                  "relMSE targets for the time-to-target columns, E1,E2,... (default: three "
                  "spread over the first setting's range)");
    add_render_options(c, rq->options, rq->device, /*with_spp=*/false);
    c->add_option("--seed", rq->options.seed, "first seed")->capture_default_str();
    add_program_options(c, rq->options);
    add_variant_option(c, rq->variant);
    add_copy_instances_option(c, rq->copy_instances);
    c->add_flag("--quiet", rq->quiet, "no progress line");
    describe_command(
        c,
        {{"Study", {"--output", "--vary", "--spp-ladder", "--seeds", "--reference", "--reference-spp", "--targets"}},
         {kSamplingGroup, {"--seed"}},
         {kSceneGroup, {}},
         {kDeviceGroup, {}},
         {kKernelGroup, {}},
         {"Progress", {"--quiet"}}},
        {{"pathcl converge scenes/cornell-box.gltf -o study --vary sampler=independent,sobol",
          "error against time of two samplers at 1, 2, 4, ..., 256 spp, against a 4096-spp reference"},
         {"pathcl converge scenes/cornell-box-glass-mirror.gltf -o study --vary strategy=nee,mis "
          "--vary max-bounces=4,8 --spp-ladder 4,16,64",
          "two knobs at once: every strategy with every bounce limit"},
         {"pathcl converge scenes/sky-spheres.gltf -o study --vary light-sampler=power,tree --reference ref.exr",
          "against a reference EXR of your own (any renderer's)"}});
    return {c, [rq] { return run_converge(*rq); }};
}

} // namespace pathcl::cli
