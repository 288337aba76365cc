#include "converge/knobs.h"

#include <algorithm>
#include <functional>
#include <map>

#include "common/error.h"
#include "common/text_fields.h"
#include "sampling/samplers.h"

namespace pathcl {
namespace {

std::uint32_t parse_count(const std::string& knob, const std::string& v)
{
    auto n = parse_whole_number(v, 1u << 16);
    if (!n)
        throw Error("--vary " + knob + ": " + quote(v) + " is not a whole number from 0 to 65536");
    return static_cast<std::uint32_t>(*n);
}

bool parse_switch(const std::string& knob, const std::string& v)
{
    if (v == "on")
        return true;
    if (v == "off")
        return false;
    throw Error("--vary " + knob + ": " + quote(v) + " is neither off nor on");
}

using Apply = std::function<void(RenderOptions&, const std::string&)>;

const std::map<std::string, Apply>& appliers()
{
    static const std::map<std::string, Apply> table = {
        {"sampler",
         [](RenderOptions& o, const std::string& v) {
             auto it = sampler_names().find(v);
             if (it == sampler_names().end())
                 throw Error("--vary sampler: unknown sampler " + quote(v));
             o.sampler = it->second;
         }},
        {"strategy",
         [](RenderOptions& o, const std::string& v) {
             for (Strategy s : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis})
                 if (v == strategy_name(s)) {
                     o.strategy = s;
                     return;
                 }
             throw Error("--vary strategy: unknown strategy " + quote(v) + " (bsdf, nee, one-sample, mis)");
         }},
        {"max-bounces", [](RenderOptions& o, const std::string& v) { o.max_bounces = parse_count("max-bounces", v); }},
        {"stratified-bounces",
         [](RenderOptions& o, const std::string& v) { o.stratified_bounces = parse_count("stratified-bounces", v); }},
        {"batch-spp", [](RenderOptions& o, const std::string& v) { o.batch_spp = parse_count("batch-spp", v); }},
        {"fast-math", [](RenderOptions& o, const std::string& v) { o.fast_math = parse_switch("fast-math", v); }},
        {"specialization",
         [](RenderOptions& o, const std::string& v) {
             if (v != "scene" && v != "all")
                 throw Error("--vary specialization: " + quote(v) + " is neither scene nor all");
             o.specialization = v == "all" ? Specialization::All : Specialization::Scene;
         }},
        {"adaptive", [](RenderOptions& o, const std::string& v) { o.adaptive = parse_switch("adaptive", v); }},
        {"light-sampler",
         [](RenderOptions& o, const std::string& v) {
             for (LightSampler s : {LightSampler::Power, LightSampler::Tree, LightSampler::Uniform, LightSampler::Auto})
                 if (v == light_sampler_name(s)) {
                     o.light_sampler = s;
                     return;
                 }
             throw Error("--vary light-sampler: unknown light sampler '" + v + "' (power, tree, uniform, auto)");
         }},
        {"triangle-sampling",
         [](RenderOptions& o, const std::string& v) {
             for (TriangleSampling s : {TriangleSampling::Area, TriangleSampling::SolidAngle, TriangleSampling::Auto})
                 if (v == triangle_sampling_name(s)) {
                     o.triangle_sampling = s;
                     return;
                 }
             throw Error("--vary triangle-sampling: unknown triangle sampling '" + v + "' (area, solid-angle, auto)");
         }},
        {"integrator",
         [](RenderOptions& o, const std::string& v) {
             if (v != "megakernel" && v != "wavefront")
                 throw Error("--vary integrator: '" + v + "' is neither megakernel nor wavefront");
             o.integrator = v == "wavefront" ? Integrator::Wavefront : Integrator::Megakernel;
         }},
    };
    return table;
}

} // namespace

const std::vector<std::string>& knob_names()
{
    static const std::vector<std::string> names = {"sampler",       "strategy",  "max-bounces",    "stratified-bounces",
                                                   "batch-spp",     "fast-math", "specialization", "adaptive",
                                                   "light-sampler", "integrator"};
    return names;
}

Knob parse_knob(const std::string& spec)
{
    std::size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
        throw Error("--vary: " + quote(spec) + " is not KNOB=V1,V2,...");
    Knob k;
    k.name = spec.substr(0, eq);
    auto it = appliers().find(k.name);
    if (it == appliers().end()) {
        std::string all;
        for (const std::string& n : knob_names())
            all += (all.empty() ? "" : ", ") + n;
        throw Error("--vary: unknown knob " + quote(k.name) + " (" + all + ")");
    }
    for (const std::string& v : split_commas(spec.substr(eq + 1))) {
        if (v.empty())
            throw Error("--vary " + k.name + ": an empty value");
        if (std::find(k.values.begin(), k.values.end(), v) != k.values.end())
            throw Error("--vary " + k.name + ": " + quote(v) + " is given twice");
        RenderOptions probe;
        it->second(probe, v); // checks the value now, not after the reference render
        k.values.push_back(v);
    }
    return k;
}

std::string Setting::label() const
{
    std::string s;
    for (const auto& [knob, v] : values)
        s += (s.empty() ? "" : ", ") + knob + "=" + v;
    return s.empty() ? "base" : s;
}

std::string Setting::value(const std::string& knob) const
{
    for (const auto& [k, v] : values)
        if (k == knob)
            return v;
    return "";
}

std::uint64_t settings_count(const std::vector<Knob>& knobs)
{
    std::uint64_t n = 1;
    for (const Knob& k : knobs)
        n = k.values.empty() || n <= UINT64_MAX / k.values.size() ? n * k.values.size() : UINT64_MAX;
    return n;
}

std::vector<Setting> settings_product(const RenderOptions& base, const std::vector<Knob>& knobs)
{
    for (std::size_t i = 0; i < knobs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (knobs[i].name == knobs[j].name)
                throw Error("--vary " + knobs[i].name + " is given twice");
    if (const std::uint64_t n = settings_count(knobs); n > kMaxSettings) {
        std::string product;
        for (const Knob& k : knobs)
            product += (product.empty() ? "" : " x ") + std::to_string(k.values.size()) + " " + k.name;
        throw Error("--vary: " + product + " make " + std::to_string(n) + " settings, each its own kernel build and " +
                    "renders: more than the " + std::to_string(kMaxSettings) +
                    " a study may have; vary fewer values (or run several studies)");
    }
    std::vector<Setting> out(1);
    out[0].options = base;
    for (const Knob& k : knobs) {
        std::vector<Setting> next;
        for (const Setting& s : out)
            for (const std::string& v : k.values) {
                Setting t = s;
                t.values.emplace_back(k.name, v);
                appliers().at(k.name)(t.options, v);
                next.push_back(std::move(t));
            }
        out = std::move(next);
    }
    return out;
}

} // namespace pathcl
