// Option groups several subcommands share, and the flag that names each library
// parameter in error messages (the library names parameters, the CLI names flags).
#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/render_options.h"

namespace pathcl::cli {

// The values NAME of an option takes, each with the number CLI11 parses into the enum, in
// the order the help lists them (as "NAME:{a,b,c}"). A name matches in any case; another
// value is an error listing the names, and the nearest if one is near.
CLI::Validator named_values(const std::vector<std::pair<std::string, std::string>>& names);

// --flag NAME for an enum `value`, which gives the default; `names` is a list or map of
// (name, value) pairs.
template <class Enum, class Names>
CLI::Option* add_enum_option(CLI::App* command, const std::string& flag, Enum& value, const Names& names,
                             const std::string& help)
{
    std::vector<std::pair<std::string, std::string>> numbers;
    std::string default_name;
    for (const auto& [name, v] : names) {
        numbers.emplace_back(name, std::to_string(static_cast<std::underlying_type_t<Enum>>(v)));
        if (v == value)
            default_name = name;
    }
    return command->add_option(flag, value, help)
        ->transform(named_values(numbers))
        ->type_name("NAME")
        ->default_str(default_name);
}

// --spp (unless with_spp is false), --width, --height, --max-bounces, --strategy,
// --light-sampler, --sampler, --stratified-bounces (help group kSamplingGroup) and
// --device (kDeviceGroup), with the values in `options` (and `devices`) as their
// defaults: the flags `render`, `bench` and `converge` share.
void add_render_options(CLI::App* command, RenderOptions& options, std::string& devices, bool with_spp = true);

// The devices --device names: "N", "N,M,..." (each once) or "all" (every device `pathcl
// devices` lists); throws pathcl::Error "--device: ..." otherwise.
std::vector<int> parse_devices(const std::string& text);

// --integrator, --wavefront-lanes, --specialization, --fast-math and --single-scattering
// (help group kKernelGroup): the options that choose the kernel variant (render, bench,
// converge, info).
void add_program_options(CLI::App* command, RenderOptions& options);

// --sampler NAME alone (the sample visualizer); `sampler` holds the default.
CLI::Option* add_sampler_option(CLI::App* command, SamplerType& sampler);

// The flag of a library parameter ("look_at" -> "--look-at").
std::string flag_for(const std::string& parameter);

// --variant NAME: the KHR_materials_variants variant the scene is loaded in (kSceneGroup).
void add_variant_option(CLI::App* command, std::string& variant);
// --copy-instances (SceneChoice::copy_instances; kSceneGroup).
void add_copy_instances_option(CLI::App* command, bool& copy_instances);

} // namespace pathcl::cli
