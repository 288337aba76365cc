// `pathcl samples`: draws one pixel's point set for a dimension pair (and the averaged
// power spectrum) to a PNG, through the kernels' own sampler code.
#include <cstdio>

#include "cl/cl_runtime.h"
#include "cli/commands.h"
#include "cli/help_format.h"
#include "cli/options.h"
#include "common/error.h"
#include "common/staged_files.h"
#include "image/image_io.h"
#include "sampling/sample_plot.h"

namespace pathcl::cli {
namespace {

struct SamplesRequest {
    std::string output;
    SamplerType sampler = SamplerType::Independent;
    std::uint32_t spp = 16, seed = 0, width = 512;
    std::vector<std::uint32_t> pixel{0, 0}, dims{0, 1};
    bool spectrum = false;
    int device = 0;
};

int run_samples(const SamplesRequest& rq)
{
    check_output_path(rq.output);
    if (lowercase_extension(rq.output) != ".png")
        throw Error(rq.output + ": the sample plot must be a .png");
    if (rq.pixel[0] >= rq.width)
        throw Error("--pixel: x must be less than --width (" + std::to_string(rq.width) + ")");
    SamplePlotRequest plot;
    plot.sampler = rq.sampler;
    plot.spp = sampler_spp(rq.sampler, rq.spp);
    plot.seed = rq.seed;
    plot.dim0 = rq.dims[0];
    plot.dim1 = rq.dims[1];
    plot.pixel = rq.pixel[1] * rq.width + rq.pixel[0];
    plot.pixel_label = "(" + std::to_string(rq.pixel[0]) + ", " + std::to_string(rq.pixel[1]) + ")";
    plot.spectrum = rq.spectrum;
    if (plot.dim0 == plot.dim1)
        throw Error("--dims: the two dimensions must differ");
    if (plot.spectrum && plot.spp > kSpectrumMaxSpp)
        throw Error("--spectrum needs --spp at most " + std::to_string(kSpectrumMaxSpp));
    ClDevice dev = open_device(rq.device);
    ProgramBuild pb = build_program(dev, "");
    std::string note;
    Image img = draw_sample_plot(dev, pb.program, plot, &note);
    write_image(rq.output, img);
    std::string spp = std::to_string(plot.spp) + " spp";
    if (plot.spp != rq.spp)
        spp += " (rounded up from " + std::to_string(rq.spp) + ")";
    std::printf("%s: %s, %s, pixel %s, dims %u,%u%s%s\n", rq.output.c_str(), sampler_name(rq.sampler).c_str(),
                spp.c_str(), plot.pixel_label.c_str(), plot.dim0, plot.dim1, note.empty() ? "" : " | ", note.c_str());
    return 0;
}

} // namespace

Command add_samples_command(CLI::App& app)
{
    auto rq = std::make_shared<SamplesRequest>();
    CLI::App* samples = app.add_subcommand(
        "samples", "Draw one pixel's sample points for a dimension pair (and their power spectrum) to a PNG");
    samples->add_option("-o,--output", rq->output, "output PNG")->required();
    add_sampler_option(samples, rq->sampler);
    samples->add_option("--spp", rq->spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1u, 1u << 20));
    samples->add_option("--pixel", rq->pixel, "pixel X,Y (default 0,0)")->delimiter(',')->expected(2);
    samples->add_option("--width", rq->width, "image width the pixel index y * width + x refers to")
        ->capture_default_str()
        ->check(CLI::Range(1u, 32768u));
    samples
        ->add_option("--dims", rq->dims,
                     "dimensions D0,D1 (default 0,1: the film position); D1 = D0 + 1 is the 2D decision at D0, "
                     "other pairs are two 1D decisions")
        ->delimiter(',')
        ->expected(2);
    samples->add_option("--seed", rq->seed, "random seed")->capture_default_str();
    samples->add_flag("--spectrum", rq->spectrum, "add the power spectrum averaged over many pixels");
    samples->add_option("--device", rq->device, "OpenCL device index")->capture_default_str();
    describe_command(
        samples,
        {{kOutputGroup, {"--output"}},
         {"Points", {"--sampler", "--spp", "--pixel", "--width", "--dims", "--seed", "--spectrum"}},
         {kDeviceGroup, {"--device"}}},
        {{"pathcl samples -o sobol.png --sampler sobol --spp 256", "the 256 film positions of pixel 0,0 under Sobol'"},
         {"pathcl samples -o jittered.png --sampler jittered --spp 64 --spectrum",
          "64 jittered points and the power spectrum averaged over many pixels"},
         {"pathcl samples -o bounce.png --sampler halton --spp 128 --dims 8,9",
          "the first bounce's BSDF direction, a 2D decision"}});
    return {samples, [rq] { return run_samples(*rq); }};
}

} // namespace pathcl::cli
