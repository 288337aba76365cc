#include "cli/options.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "cl/cl_runtime.h"
#include "cli/help_format.h"
#include "cli/usage_errors.h"
#include "common/error.h"
#include "common/text_fields.h"
#include "sampling/samplers.h"

namespace pathcl::cli {
namespace {

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

const char* const kSamplerHelp = "the point sets of each pixel's samples (jittered and multi-jittered round --spp up "
                                 "to a square, hammersley to a power of two)";

} // namespace

CLI::Validator named_values(const std::vector<std::pair<std::string, std::string>>& names)
{
    std::vector<std::string> listed;
    for (const auto& entry : names)
        listed.push_back(entry.first);
    std::string description;
    for (const std::string& name : listed)
        description += (description.empty() ? "{" : ",") + name;
    return CLI::Validator(
        [names, listed](std::string& value) {
            for (const auto& [name, number] : names)
                if (name == lowercase(value)) {
                    value = number;
                    return std::string();
                }
            std::string all;
            for (std::size_t i = 0; i < listed.size(); ++i)
                all += (i == 0 ? "" : i + 1 == listed.size() ? " or " : ", ") + listed[i];
            return quote(value) + " is not " + all + did_you_mean(nearest_names(value, listed));
        },
        description + "}");
}

CLI::Option* add_sampler_option(CLI::App* command, SamplerType& sampler)
{
    std::vector<std::pair<std::string, SamplerType>> names(sampler_names().begin(), sampler_names().end());
    std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return add_enum_option(command, "--sampler", sampler, names, kSamplerHelp); // in the order of SamplerType
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
            ->check(CLI::Range(1u, 1u << 30))
            ->group(kSamplingGroup);
    command->add_option("--width", options.width, "image width")
        ->capture_default_str()
        ->check(CLI::Range(1u, 32768u))
        ->group(kSamplingGroup);
    command->add_option("--height", options.height, "image height")
        ->capture_default_str()
        ->check(CLI::Range(1u, 32768u))
        ->group(kSamplingGroup);
    command
        ->add_option("--max-bounces", options.max_bounces,
                     "scattering events per path (0: emission only, 1: direct light)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 16))
        ->group(kSamplingGroup);
    const std::vector<std::pair<std::string, Strategy>> strategies = {
        {"bsdf", Strategy::Bsdf}, {"nee", Strategy::Nee}, {"one-sample", Strategy::OneSample}, {"mis", Strategy::Mis}};
    add_enum_option(command, "--strategy", options.strategy, strategies,
                    "how direct light is found: bsdf (BSDF sampling alone), nee (next event estimation), "
                    "one-sample (one of the two by a coin) or mis (both, weighted by the power heuristic)")
        ->group(kSamplingGroup);
    const std::vector<std::pair<std::string, LightSampler>> light_samplers = {{"auto", LightSampler::Auto},
                                                                              {"power", LightSampler::Power},
                                                                              {"tree", LightSampler::Tree},
                                                                              {"uniform", LightSampler::Uniform}};
    add_enum_option(command, "--light-sampler", options.light_sampler, light_samplers,
                    "how next event estimation picks a light: power (by power alone), tree (the light tree: power, "
                    "distance and orientation at the shading point), uniform, or auto (the tree where three or "
                    "more lights are spread over a quarter of the scene, else power)")
        ->group(kSamplingGroup);
    const std::vector<std::pair<std::string, TriangleSampling>> triangle_samplings = {
        {"auto", TriangleSampling::Auto},
        {"area", TriangleSampling::Area},
        {"solid-angle", TriangleSampling::SolidAngle}};
    add_enum_option(command, "--triangle-sampling", options.triangle_sampling, triangle_samplings,
                    "how a light sample finds a point on an emissive triangle: area (uniform by area), solid-angle "
                    "(uniform within the solid angle it subtends where it looks large: area over squared distance "
                    "above 0.3), or auto (solid-angle where half the emitters' light meets surfaces that close, or a "
                    "surface comes very close to one, else area; area with the wavefront integrator)")
        ->group(kSamplingGroup);
    add_sampler_option(command, options.sampler)->group(kSamplingGroup);
    command
        ->add_option("--stratified-bounces", options.stratified_bounces,
                     "the camera's decisions and those of the first N bounces take the sampler's stratified sets, "
                     "deeper ones independent numbers (any N >= --max-bounces: all)")
        ->capture_default_str()
        ->group(kSamplingGroup);
    command
        ->add_option("--device", devices,
                     "OpenCL device index, a comma-separated list of them or all (see 'pathcl devices'): several "
                     "devices share the rows, and the image is the one-device image")
        ->capture_default_str()
        ->group(kDeviceGroup);
}

void add_program_options(CLI::App* command, RenderOptions& options)
{
    const std::vector<std::pair<std::string, Integrator>> integrators = {{"megakernel", Integrator::Megakernel},
                                                                         {"wavefront", Integrator::Wavefront}};
    add_enum_option(command, "--integrator", options.integrator, integrators,
                    "megakernel (one work-item per path) or wavefront (one kernel per stage, shading in lanes; "
                    "Lambertian scenes lit by emissive triangles so far)")
        ->group(kKernelGroup);
    command
        ->add_option("--wavefront-lanes", options.wavefront_lanes,
                     "paths per shading work-item of the wavefront: 8 (the default on CPUs) or 1 (elsewhere; on a CPU, "
                     "for measuring what lanes gain)")
        ->check(CLI::IsMember({1u, 8u}))
        ->group(kKernelGroup);
    const std::vector<std::pair<std::string, Specialization>> kinds = {{"scene", Specialization::Scene},
                                                                       {"all", Specialization::All}};
    add_enum_option(command, "--specialization", options.specialization, kinds,
                    "kernel features compiled in: scene (those the scene uses) or all (to measure what "
                    "specializing saves)")
        ->group(kKernelGroup);
    command
        ->add_flag("--fast-math", options.fast_math,
                   "build the kernels with -cl-unsafe-math-optimizations (fast math; not -cl-finite-math-only, "
                   "which traversal cannot take; a measured opt-in: docs/accuracy.md)")
        ->group(kKernelGroup);
    command
        ->add_flag("--single-scattering", options.single_scattering,
                   "rough microfacets without multiple-scattering energy compensation (as pbrt and Mitsuba "
                   "render them; for cross-checks)")
        ->group(kKernelGroup);
}

void add_variant_option(CLI::App* command, std::string& variant)
{
    command
        ->add_option("--variant", variant,
                     "KHR_materials_variants variant to render the scene's materials in (default: the file's own "
                     "materials; 'pathcl info' lists the variants)")
        ->group(kSceneGroup);
}

void add_copy_instances_option(CLI::App* command, bool& copy_instances)
{
    command
        ->add_flag("--copy-instances", copy_instances,
                   "copy a mesh drawn by several nodes or EXT_mesh_gpu_instancing instances into the scene once per "
                   "drawing (one-level BVH) instead of storing it once and drawing instances of it (two-level BVH)")
        ->group(kSceneGroup);
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
