#include "cli/options.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "common/text_fields.h"

namespace pathcl::cli {
namespace {

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// --sampler NAME with a readable message for a bad name (CheckedTransformer's would list
// the numeric values too).
CLI::Validator sampler_validator()
{
    return CLI::Validator(
        [](std::string& value) {
            auto it = sampler_names().find(lowercase(value));
            if (it == sampler_names().end())
                return "unknown sampler " + quote(value) +
                       " (independent, jittered, multi-jittered, n-rooks, sobol, halton, hammersley)";
            value = std::to_string(static_cast<std::uint32_t>(it->second));
            return std::string();
        },
        "SAMPLER");
}

const char* const kSamplerHelp =
    "sampler: independent, jittered, multi-jittered, n-rooks, sobol, halton or hammersley (jittered and "
    "multi-jittered round --spp up to a square, hammersley to a power of two)";

} // namespace

void add_sampler_option(CLI::App* command, SamplerType& sampler, const std::string& default_name)
{
    command->add_option("--sampler", sampler, kSamplerHelp)
        ->transform(sampler_validator())
        ->type_name("NAME")
        ->default_str(default_name);
}

std::vector<int> parse_devices(const std::string& text)
{
    std::vector<int> out;
    if (text == "all") {
        for (const DeviceInfo& d : list_devices())
            out.push_back(d.index);
        if (out.empty())
            throw Error("--device: no OpenCL device found");
        return out;
    }
    for (const std::string& item : split_commas(text)) {
        const bool digits = !item.empty() && item.size() <= 6 &&
                            std::all_of(item.begin(), item.end(), [](unsigned char c) { return std::isdigit(c); });
        if (!digits)
            throw Error("--device: " + quote(text) + " is not a device index, a comma-separated list of them or all");
        const int index = std::stoi(item);
        if (std::find(out.begin(), out.end(), index) != out.end())
            throw Error("--device: device " + item + " is listed twice");
        out.push_back(index);
    }
    return out;
}

void add_render_options(CLI::App* command, RenderOptions& options, std::string& devices, bool with_spp)
{
    if (with_spp)
        command->add_option("--spp", options.spp, "samples per pixel")
            ->capture_default_str()
            ->check(CLI::Range(1u, 1u << 30));
    command->add_option("--width", options.width, "image width")->capture_default_str()->check(CLI::Range(1u, 32768u));
    command->add_option("--height", options.height, "image height")
        ->capture_default_str()
        ->check(CLI::Range(1u, 32768u));
    command
        ->add_option("--max-bounces", options.max_bounces,
                     "scattering events per path (0: emission only, 1: direct light)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 16));
    static const std::map<std::string, Strategy> strategies = {
        {"bsdf", Strategy::Bsdf}, {"nee", Strategy::Nee}, {"one-sample", Strategy::OneSample}, {"mis", Strategy::Mis}};
    command->add_option("--strategy", options.strategy, "light sampling: bsdf, nee, one-sample or mis")
        ->transform(CLI::CheckedTransformer(strategies, CLI::ignore_case))
        ->default_str("mis");
    static const std::map<std::string, LightSampler> light_samplers = {{"auto", LightSampler::Auto},
                                                                       {"power", LightSampler::Power},
                                                                       {"tree", LightSampler::Tree},
                                                                       {"uniform", LightSampler::Uniform}};
    command
        ->add_option("--light-sampler", options.light_sampler,
                     "how next event estimation picks a light: power (by power alone), tree (the light tree: power, "
                     "distance and orientation at the shading point), uniform, or auto (the tree where three or "
                     "more lights are spread over a quarter of the scene, else power)")
        ->transform(CLI::CheckedTransformer(light_samplers, CLI::ignore_case))
        ->default_str("auto");
    add_sampler_option(command, options.sampler, sampler_name(options.sampler));
    command
        ->add_option("--stratified-bounces", options.stratified_bounces,
                     "the camera's decisions and those of the first N bounces take the sampler's stratified sets, "
                     "deeper ones independent numbers (any N >= --max-bounces: all)")
        ->capture_default_str();
    command
        ->add_option("--device", devices,
                     "OpenCL device index, a comma-separated list of them or all (see 'pathcl devices'): several "
                     "devices share the rows, and the image is the one-device image")
        ->capture_default_str();
}

void add_program_options(CLI::App* command, RenderOptions& options)
{
    static const std::map<std::string, Specialization> kinds = {{"scene", Specialization::Scene},
                                                                {"all", Specialization::All}};
    command
        ->add_option("--specialization", options.specialization,
                     "kernel features compiled in: scene (those the scene uses) or all (to measure what "
                     "specializing saves)")
        ->transform(CLI::CheckedTransformer(kinds, CLI::ignore_case))
        ->default_str("scene");
    static const std::map<std::string, Integrator> integrators = {{"megakernel", Integrator::Megakernel},
                                                                  {"wavefront", Integrator::Wavefront}};
    command
        ->add_option("--integrator", options.integrator,
                     "megakernel (one work-item per path) or wavefront (one kernel per stage, shading in lanes; "
                     "Lambertian scenes lit by emissive triangles so far)")
        ->transform(CLI::CheckedTransformer(integrators, CLI::ignore_case))
        ->default_str("megakernel");
    command
        ->add_option("--wavefront-lanes", options.wavefront_lanes,
                     "paths per shading work-item of the wavefront: 8 (the default on CPUs) or 1 (elsewhere; on a CPU, "
                     "for measuring what lanes gain)")
        ->check(CLI::IsMember({1u, 8u}));
    command->add_flag("--fast-math", options.fast_math,
                      "build the kernels with -cl-unsafe-math-optimizations (fast math; not -cl-finite-math-only, "
                      "which traversal cannot take; a measured opt-in: docs/accuracy.md)");
    command->add_flag("--single-scattering", options.single_scattering,
                      "rough microfacets without multiple-scattering energy compensation (as pbrt and Mitsuba "
                      "render them; for cross-checks)");
}

void add_variant_option(CLI::App* command, std::string& variant)
{
    command->add_option("--variant", variant,
                        "KHR_materials_variants variant to render the scene's materials in (default: the file's own "
                        "materials; 'pathcl info' lists the variants)");
}

void add_copy_instances_option(CLI::App* command, bool& copy_instances)
{
    command->add_flag("--copy-instances", copy_instances,
                      "copy a mesh drawn by several nodes or EXT_mesh_gpu_instancing instances into the scene once per "
                      "drawing (one-level BVH) instead of storing it once and drawing instances of it (two-level BVH)");
}

std::string flag_for(const std::string& parameter)
{
    static const std::map<std::string, std::string> renamed = {{"time_budget", "--time"}};
    if (auto it = renamed.find(parameter); it != renamed.end())
        return it->second;
    std::string flag = "--" + parameter;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

} // namespace pathcl::cli
