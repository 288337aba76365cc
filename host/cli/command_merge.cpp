// `pathcl merge`: adds the sample ranges of one render, rendered apart, into one image
// (render/partial_renders.h).
#include <cstdio>

#include "cli/commands.h"
#include "cli/help_format.h"
#include "common/error.h"
#include "common/file_identity.h"
#include "common/staged_files.h"
#include "image/image_io.h"
#include "render/partial_renders.h"

namespace pathcl::cli {
namespace {

struct MergeRequest {
    std::vector<std::string> inputs;
    std::string output;
};

int run_merge(const MergeRequest& rq)
{
    check_output_path(rq.output);
    if (lowercase_extension(rq.output) != ".exr")
        throw Error(rq.output + ": a merge is written as EXR (it may be a partial render itself)");
    std::vector<NamedFile> inputs;
    for (const std::string& input : rq.inputs)
        inputs.push_back({input, "partial render"});
    check_distinct_files(inputs, {{rq.output, "-o"}});
    Image merged = merge_partial_renders(rq.inputs);
    write_image(rq.output, merged);
    auto ranges = merged.metadata.find("sample_ranges");
    std::printf("%s: %zu renders merged, %u spp%s\n", rq.output.c_str(), rq.inputs.size(), merged.spp,
                ranges == merged.metadata.end() ? ", the whole render"
                                                : (", still partial: samples " + ranges->second).c_str());
    return 0;
}

} // namespace

Command add_merge_command(CLI::App& app)
{
    auto rq = std::make_shared<MergeRequest>();
    CLI::App* merge = app.add_subcommand(
        "merge", "Add the sample ranges of one render (render --sample-range) into its image, exactly");
    merge->add_option("inputs", rq->inputs, "partial renders (EXR) of one render, no sample in two")->required();
    merge->add_option("-o,--output", rq->output, "the merged EXR: the whole render's image once every range is in")
        ->required();
    describe_command(
        merge, {{kOutputGroup, {"--output"}}},
        {{"pathcl merge half1.exr half2.exr -o box.exr",
          "the two halves of a render made with --sample-range 0:512 and 512:512: its image bit for bit"}});
    return {merge, [rq] { return run_merge(*rq); }};
}

} // namespace pathcl::cli
