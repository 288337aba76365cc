#include "converge/convergence.h"

#include <algorithm>
#include <numeric>

#include "cl/cl_runtime.h"
#include "compile/kernel_features.h"
#include "sampling/samplers.h"
#include "scene/scene_fingerprint.h"

namespace pathcl {
namespace {

// The reference's seed: far from the rows' seeds (base.seed + k).
constexpr std::uint32_t kReferenceSeedOffset = 1000003;
// Adaptive rows: the pilot's batches, and how far past the ladder's spp a row may go.
constexpr std::uint32_t kPilotBatchSpp = 16, kPilotBatches = 2, kAdaptiveSppFactor = 4;

double mean_samples(const Image& img, std::uint32_t spp)
{
    if (img.samples.empty())
        return spp;
    double sum = std::accumulate(img.samples.begin(), img.samples.end(), 0.0);
    return sum / static_cast<double>(img.samples.size());
}

// After the setting's Renderer is made: its build stored the binary if the cache lacked it.
// `o` as the Renderer resolved them, so that the scene's auto choices are not made again.
SettingBuild measure_build(const Scene& scene, const RenderOptions& o)
{
    SettingBuild b;
    ClDevice dev = open_device(o.devices.empty() ? 0 : o.devices.front());
    const std::string options = program_build_options(kernel_features(scene, o), o);
    ProgramSource cold;
    cold.use_cache = false;
    b.cold_seconds = build_program(dev, options, cold).seconds;
    b.cached_seconds = build_program(dev, options, ProgramSource{}).seconds;
    return b;
}

} // namespace

RenderOptions reference_options(const ConvergenceStudy& study, std::uint32_t reference_spp)
{
    RenderOptions r = study.base;
    for (const Setting& s : study.settings)
        r.max_bounces = std::max(r.max_bounces, s.options.max_bounces);
    r.spp = reference_spp;
    r.seed = study.base.seed + kReferenceSeedOffset;
    r.batch_spp = 0;
    r.time_budget = r.target_error = 0.0;
    r.min_spp = 0;
    r.adaptive = false;
    r.specialization = Specialization::Scene;
    r.fast_math = false;
    return r;
}

std::string reference_key(const Scene& scene, const RenderOptions& r)
{
    return "scene " + scene_fingerprint_hex(scene) + ", " + std::to_string(r.width) + "x" + std::to_string(r.height) +
           ", " + std::to_string(r.spp) + " spp " + sampler_name(r.sampler) + ", strategy " +
           strategy_name(r.strategy) + ", max bounces " + std::to_string(r.max_bounces) + ", stratified bounces " +
           std::to_string(r.stratified_bounces) + (r.single_scattering ? ", single scattering" : "") + ", seed " +
           std::to_string(r.seed);
}

bool run_convergence(const Scene& scene, const ConvergenceStudy& study, const Image& reference,
                     const ConvergenceCallbacks& cb)
{
    for (std::size_t si = 0; si < study.settings.size(); ++si) {
        RenderOptions o = study.settings[si].options;
        const bool adaptive = o.adaptive;
        if (adaptive) {
            o.target_error = 1.0; // a placeholder: each row sets its own
            if (o.batch_spp == 0)
                o.batch_spp = kPilotBatchSpp;
        }
        Renderer renderer(scene, o);
        SettingBuild build = measure_build(scene, renderer.options());
        RenderRun warmup;
        warmup.seed = study.base.seed;
        warmup.spp = adaptive ? 2 * o.batch_spp : 1; // adaptive: the two batches an estimate needs
        build.first_render_seconds = renderer.render(warmup).stats.render_seconds;
        if (cb.setting_built)
            cb.setting_built(si, build);
        // Adaptive rows: the relMSE times spp of a uniform render, per seed.
        std::vector<double> pilot(study.seeds, 0.0);
        if (adaptive) {
            RenderOptions p = o;
            p.adaptive = false;
            p.target_error = 0.0;
            p.batch_spp = kPilotBatchSpp;
            p.spp = kPilotBatchSpp * kPilotBatches;
            Renderer pilot_renderer(scene, p);
            for (std::uint32_t k = 0; k < study.seeds; ++k) {
                RenderResult r = pilot_renderer.render(study.base.seed + k);
                pilot[k] = r.stats.error_estimate * r.stats.spp;
            }
        }
        for (std::uint32_t n : study.ladder)
            for (std::uint32_t k = 0; k < study.seeds; ++k) {
                ConvergenceRow row;
                row.setting = si;
                row.spp = n;
                row.seed = study.base.seed + k;
                RenderRun run;
                run.seed = row.seed;
                run.spp = n;
                if (adaptive) {
                    run.spp = std::max(n * kAdaptiveSppFactor, 2 * o.batch_spp);
                    run.target_error = pilot[k] / n;
                }
                bool stopped_by_caller = false;
                if (cb.progress)
                    run.progress = [&](const RenderProgress& p) {
                        stopped_by_caller = !cb.progress(row, p);
                        return !stopped_by_caller;
                    };
                RenderResult r = renderer.render(run);
                if (stopped_by_caller)
                    return false; // an interrupted render is not a point of the curve
                row.spp_taken = mean_samples(r.image, r.stats.spp);
                row.render_seconds = r.stats.render_seconds;
                row.samples_per_second = r.stats.samples_per_second;
                row.error = measure_error(r.image, reference);
                row.error_estimate = r.stats.error_estimate;
                row.stop = stop_reason_name(r.stats.stop);
                if (cb.row && !cb.row(row))
                    return false;
            }
    }
    return true;
}

} // namespace pathcl
