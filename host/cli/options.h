// Option groups several subcommands share, and the flag that names each library
// parameter in error messages (the library names parameters, the CLI names flags).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/render_options.h"

namespace pathcl::cli {

// --spp (unless with_spp is false), --width, --height, --max-bounces, --strategy,
// --sampler, --stratified-bounces and --device, with the values in `options` (and
// `devices`) as their defaults: the group `render`, `bench` and `converge` share.
void add_render_options(CLI::App* command, RenderOptions& options, std::string& devices, bool with_spp = true);

// The devices --device names: "N", "N,M,..." (each once) or "all" (every device `pathcl
// devices` lists); throws pathcl::Error "--device: ..." otherwise.
std::vector<int> parse_devices(const std::string& text);

// --specialization, --fast-math and --single-scattering: the options that choose the
// kernel variant (render, bench, info).
void add_program_options(CLI::App* command, RenderOptions& options);

// --sampler NAME alone (the sample visualizer), with the default `default_name`.
void add_sampler_option(CLI::App* command, SamplerType& sampler, const std::string& default_name);

// The flag of a library parameter ("look_at" -> "--look-at").
std::string flag_for(const std::string& parameter);

// --variant NAME: the KHR_materials_variants variant the scene is loaded in.
void add_variant_option(CLI::App* command, std::string& variant);
// --copy-instances (SceneChoice::copy_instances).
void add_copy_instances_option(CLI::App* command, bool& copy_instances);

} // namespace pathcl::cli
