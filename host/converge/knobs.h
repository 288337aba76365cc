// The knobs a convergence study varies (`pathcl converge --vary KNOB=V1,V2,...`) and the
// settings they make: every combination of the values of every knob, applied to the
// study's base render options.
//
//   sampler             independent, jittered, multi-jittered, n-rooks, sobol, halton, hammersley
//   strategy            bsdf, nee, one-sample, mis
//   max-bounces         N
//   stratified-bounces  N
//   batch-spp           N (0: every render one batch)
//   fast-math           off, on (-cl-unsafe-math-optimizations)
//   specialization      scene, all
//   adaptive            off, on (per-pixel adaptive sampling; see converge/convergence.h)
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/render_options.h"

namespace pathcl {

struct Knob {
    std::string name;
    std::vector<std::string> values;
};

// Parses "KNOB=V1,V2,..."; throws pathcl::Error naming the knob or value it cannot use.
Knob parse_knob(const std::string& spec);

// Every knob's name.
const std::vector<std::string>& knob_names();

struct Setting {
    std::vector<std::pair<std::string, std::string>> values; // knob, value; in --vary order
    RenderOptions options;

    // "sampler=sobol, strategy=mis" ("base" with no knob).
    std::string label() const;
    // The value of `knob` in this setting, "" if not varied.
    std::string value(const std::string& knob) const;
};

// A study renders every setting with its own kernel build: at most this many settings.
constexpr std::uint64_t kMaxSettings = 1024;

// The number of settings the knobs make (the product of their value counts, saturated).
std::uint64_t settings_count(const std::vector<Knob>& knobs);

// The product of the knobs' values, the first knob varying slowest; throws for a knob
// given twice or a product of more than kMaxSettings settings (counted before any is made).
std::vector<Setting> settings_product(const RenderOptions& base, const std::vector<Knob>& knobs);

} // namespace pathcl
