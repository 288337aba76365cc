// `pathcl compare`: the statistical image comparison the tests use, or a bit-for-bit one.
#include <iostream>

#include "cli/commands.h"
#include "cli/help_format.h"
#include "common/error.h"
#include "image/image_compare.h"
#include "image/image_io.h"

namespace pathcl::cli {
namespace {

struct CompareRequest {
    std::string a, b;
    CompareOptions options;
    bool welch = false, bitwise = false;
};

int run_compare(const CompareRequest& rq)
{
    const Image a = read_image(rq.a), b = read_image(rq.b);
    if (a.width != b.width || a.height != b.height)
        throw Error(rq.b + ": is " + std::to_string(b.width) + "x" + std::to_string(b.height) + ", " + rq.a + " " +
                    std::to_string(a.width) + "x" + std::to_string(a.height) + ": compare needs images of one size");
    if (rq.bitwise) {
        BitwiseReport r = compare_bitwise(a, b);
        std::cout << r.summary();
        return r.identical() ? 0 : 1;
    }
    CompareOptions options = rq.options;
    options.pooled_variance = !rq.welch;
    CompareReport r = compare_images(a, b, options);
    std::cout << r.summary();
    return r.passed ? 0 : 1;
}

} // namespace

Command add_compare_command(CLI::App& app)
{
    auto rq = std::make_shared<CompareRequest>();
    CLI::App* compare = app.add_subcommand(
        "compare", "Statistically compare two EXR renders (per-pixel, tile and image z-tests); exit 1 if they differ");
    compare->add_option("a", rq->a, "first EXR (with variance channels)")->required();
    compare->add_option("b", rq->b, "second EXR")->required();
    compare->add_option("--alpha", rq->options.alpha, "family-wise significance level")->capture_default_str();
    compare->add_option("--max-fail-fraction", rq->options.max_fail_fraction, "tolerated failing fraction per scale")
        ->capture_default_str();
    compare->add_flag("--welch", rq->welch,
                      "separate variances, for renders by different estimators (default: pooled, for a render "
                      "against a reference made by the same estimator)");
    compare->add_flag("--bitwise", rq->bitwise,
                      "instead: are the pixel data (means, variances, spp) identical bit for bit? (reproducibility, "
                      "refactors)");
    describe_command(compare, {{"Test", {"--alpha", "--max-fail-fraction", "--welch", "--bitwise"}}},
                     {{"pathcl compare box.exr reference.exr",
                       "are the two renders the same image up to noise? (exit 1 if not), and the RMSE of the first"},
                      {"pathcl compare nee.exr mis.exr --welch",
                       "the same for renders by different estimators, each with its own variance"},
                      {"pathcl compare before.exr after.exr --bitwise", "are the pixel data identical bit for bit?"}});
    return {compare, [rq] { return run_compare(*rq); }};
}

} // namespace pathcl::cli
