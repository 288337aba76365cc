#include "render/batches.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "sampling/samplers.h"

namespace pathcl {

namespace {

// Batches per budgeted render before a target error is trusted: the variance of the
// batch means needs two.
constexpr std::uint32_t kMinEstimateBatches = 2;
// Samples per batch under a budget when none is asked for: small enough to stop close to
// a target, large enough for the stratified samplers' sets to pay.
constexpr std::uint32_t kDefaultBudgetBatchSpp = 16;

// The sample range of the options into the plan: whole batches of the render, so that a
// range's batches are those of the whole render and its film state adds to the others'
// exactly.
void plan_range(const RenderOptions& opt, BatchPlan& plan)
{
    if (opt.sample_count == 0) {
        if (opt.sample_first > 0)
            throw ParameterError("sample_range", "needs a sample count: FIRST:COUNT");
        return;
    }
    if (plan.budgeted || opt.adaptive)
        throw ParameterError("sample_range", "is a fixed set of samples: it cannot end early by a time budget or a "
                                             "target error");
    const std::uint64_t end = std::uint64_t(opt.sample_first) + opt.sample_count;
    if (end > plan.max_spp)
        throw ParameterError("sample_range", "ends at sample " + std::to_string(end) + ", past the render's " +
                                                 std::to_string(plan.max_spp) + " samples per pixel ({spp})");
    const std::uint32_t b = plan.batch_spp;
    if (opt.sample_first % b != 0 || (end % b != 0 && end != plan.max_spp))
        throw ParameterError("sample_range",
                             "is made of whole batches: FIRST and FIRST+COUNT must be multiples of the batch size " +
                                 std::to_string(b) + " (or end at {spp} " + std::to_string(plan.max_spp) +
                                 "); choose the batch size with {batch_spp}");
    plan.first_spp = opt.sample_first;
    plan.end_spp = static_cast<std::uint32_t>(end);
    plan.ranged = true;
}

} // namespace

std::uint32_t BatchPlan::batch_passes(std::uint32_t b) const
{
    const std::uint64_t first = static_cast<std::uint64_t>(b) * batch_spp;
    if (first >= end_spp)
        return 0;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(batch_spp, end_spp - first));
}

BatchPlan plan_batches(const RenderOptions& opt)
{
    if (!(opt.time_budget >= 0.0) || !std::isfinite(opt.time_budget))
        throw ParameterError("time_budget", "must be a finite number of seconds >= 0");
    if (!(opt.target_error >= 0.0) || !std::isfinite(opt.target_error))
        throw ParameterError("target_error", "must be a finite relative MSE >= 0");
    if (opt.adaptive && opt.target_error <= 0.0)
        throw ParameterError("adaptive", "needs a target error: pixels stop when they reach it ({target_error})");
    if (opt.spp == 0)
        throw ParameterError("spp", "must be at least 1");
    if (opt.min_spp > opt.spp)
        throw ParameterError("min_spp", "exceeds the samples per pixel at most ({spp})");
    if (opt.min_spp > 0 && opt.target_error <= 0.0)
        throw ParameterError("min_spp", "applies to a target error only ({target_error})");

    BatchPlan plan;
    plan.budgeted = opt.time_budget > 0.0 || opt.target_error > 0.0;
    if (opt.batch_spp == 0 && !plan.budgeted) {
        // One point set of spp samples: the plain render.
        plan.batch_spp = plan.max_spp = plan.end_spp = sampler_spp(opt.sampler, opt.spp);
        plan_range(opt, plan);
        return plan;
    }
    plan.batch_spp = sampler_spp(opt.sampler, opt.batch_spp > 0 ? opt.batch_spp : kDefaultBudgetBatchSpp);
    plan.max_spp = opt.spp;
    if (opt.target_error > 0.0) {
        const std::uint64_t two = static_cast<std::uint64_t>(kMinEstimateBatches) * plan.batch_spp;
        plan.min_spp =
            opt.min_spp > 0 ? opt.min_spp : static_cast<std::uint32_t>(std::min<std::uint64_t>(two, opt.spp));
        if (plan.max_spp < two)
            throw ParameterError("spp", "a target error needs two batches: at least " + std::to_string(two) +
                                            " samples per pixel ({batch_spp} " + std::to_string(plan.batch_spp) + ")");
    }
    plan.end_spp = plan.max_spp;
    plan_range(opt, plan);
    return plan;
}

std::uint32_t batch_seed(std::uint32_t seed, std::uint32_t batch)
{
    if (batch == 0)
        return seed;
    // SplitMix64's finalizer over (seed, batch): neighbouring batches and seeds get
    // unrelated scrambles.
    std::uint64_t z = (static_cast<std::uint64_t>(seed) << 32 | batch) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<std::uint32_t>(z ^ (z >> 32));
}

const char* stop_reason_name(StopReason reason)
{
    switch (reason) {
    case StopReason::Spp:
        return "spp";
    case StopReason::Time:
        return "time";
    case StopReason::TargetError:
        return "target error";
    case StopReason::Interrupted:
        return "interrupted";
    }
    return "unknown";
}

} // namespace pathcl
