// Sample ranges end to end through the binary (render --sample-range, pathcl merge): the
// ranges of a render, rendered as separate processes at once and merged in any order and
// grouping, are the uninterrupted render's image bit for bit, metadata included; what
// cannot be merged exactly is a one-line error naming the file.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "image/image_io.h"
#include "support/same_image.h"
#include "support/tool_run.h"

namespace pathcl::test_cli_sample_ranges {
namespace {

using test::expect_same_image;
using test::ToolRun;

const std::string kScene = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box-glass-mirror.gltf";
// 56 spp in batches of 16: the last batch is partial, as a range may end in one.
const std::string kRender = " --width 40 --height 32 --spp 56 --batch-spp 16 --quiet";

std::string render_args(const std::string& out, const std::string& extra = "")
{
    return "render '" + kScene + "' -o " + out + kRender + extra;
}

TEST_F(ToolRun, SampleRangesRenderedApartMergeIntoTheWholeRender)
{
    ASSERT_EQ(run(render_args("whole.exr")), 0) << text("stderr.txt");
    ASSERT_EQ(
        run_parallel({render_args("a.exr", " --sample-range 0:16"), render_args("b.exr", " --sample-range 16:32"),
                      render_args("c.exr", " --sample-range 48:8"), render_args("ab.exr", " --sample-range 0:48")}),
        0)
        << text("stderr-0.txt") << text("stderr-1.txt") << text("stderr-2.txt") << text("stderr-3.txt");
    const Image whole = read_image((dir_ / "whole.exr").string());

    // All at once, in another order.
    ASSERT_EQ(run("merge c.exr a.exr b.exr -o abc.exr"), 0) << text("stderr.txt");
    EXPECT_NE(text("stdout.txt").find("the whole render"), std::string::npos) << text("stdout.txt");
    Image abc = read_image((dir_ / "abc.exr").string());
    expect_same_image(abc, whole);
    EXPECT_THROW(read_film_part((dir_ / "abc.exr").string(), abc), Error); // complete: no film part

    // In two steps: a merge short of samples is a partial render itself.
    ASSERT_EQ(run("merge c.exr a.exr -o ac.exr"), 0) << text("stderr.txt");
    EXPECT_NE(text("stdout.txt").find("still partial: samples 0:16,48:8"), std::string::npos) << text("stdout.txt");
    ASSERT_EQ(run("merge b.exr ac.exr -o ac_b.exr"), 0) << text("stderr.txt");
    expect_same_image(read_image((dir_ / "ac_b.exr").string()), whole);

    // The exact state itself, not only the float image it rounds to: two ranges merged
    // hold the sums the render of their union holds, to the last of the 192 bits.
    ASSERT_EQ(run("merge b.exr a.exr -o merged_ab.exr"), 0) << text("stderr.txt");
    Image merged_ab = read_image((dir_ / "merged_ab.exr").string()), ab = read_image((dir_ / "ab.exr").string());
    read_film_part((dir_ / "merged_ab.exr").string(), merged_ab);
    read_film_part((dir_ / "ab.exr").string(), ab);
    EXPECT_EQ(merged_ab.film_channels, ab.film_channels);
    EXPECT_TRUE(merged_ab.film == ab.film) << "the merged film state differs from the render of the union";
    EXPECT_EQ(merged_ab.metadata, ab.metadata);

    // A range's own image is the mean of its samples: a valid render, not a fragment.
    const Image b = read_image((dir_ / "b.exr").string());
    EXPECT_EQ(b.spp, 32u);
    EXPECT_EQ(b.metadata.at("sample_ranges"), "16:32");
    double mean_b = 0.0, mean_whole = 0.0;
    for (std::size_t i = 0; i < b.rgb.size(); ++i) {
        mean_b += b.rgb[i];
        mean_whole += whole.rgb[i];
    }
    EXPECT_NEAR(mean_b / mean_whole, 1.0, 0.05);
}

TEST_F(ToolRun, WhatCannotBeMergedExactlyIsAOneLineError)
{
    ASSERT_EQ(run(render_args("a.exr", " --sample-range 0:32")), 0) << text("stderr.txt");
    ASSERT_EQ(run(render_args("b.exr", " --sample-range 16:16")), 0) << text("stderr.txt");
    ASSERT_EQ(run(render_args("seed.exr", " --sample-range 32:24 --seed 6")), 0) << text("stderr.txt");
    ASSERT_EQ(run(render_args("whole.exr")), 0) << text("stderr.txt");
    struct Case {
        std::string args, says;
    };
    const std::vector<Case> cases = {
        {"merge a.exr b.exr -o m.exr", "b.exr: its samples 16:16 overlap a.exr's 0:32"},
        {"merge a.exr seed.exr -o m.exr", "seed.exr: is a range of another render than a.exr"},
        {"merge a.exr whole.exr -o m.exr", "whole.exr: is not a partial render"},
        {"merge a.exr a.exr -o m.exr", "a.exr: its samples 0:32 overlap a.exr's 0:32"},
        {"merge a.exr -o a.exr", "a.exr"},
        {"merge a.exr -o m.png", "m.png"},
        {render_args("x.exr", " --sample-range 8:16"), "--sample-range: is made of whole batches"},
        {render_args("x.exr", " --sample-range 48:16"), "--sample-range: ends at sample 64, past"},
        {render_args("x.exr", " --sample-range 0:0"), "--sample-range: \"0:0\" is not FIRST:COUNT"},
        {render_args("x.png", " --sample-range 0:16"), "x.png: a sample range's film state is kept in EXR only"},
        {"render '" + kScene + "' -o x.exr --width 8 --height 8 --batch-spp 16 --time 5 --sample-range 0:16",
         "--sample-range: is a fixed set"},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(run(c.args), 2) << c.args;
        const std::string err = text("stderr.txt");
        EXPECT_NE(err.find(c.says), std::string::npos) << c.args << "\n" << err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << c.args << "\n" << err;
        EXPECT_FALSE(std::filesystem::exists(dir_ / "m.exr") || std::filesystem::exists(dir_ / "x.exr"));
    }

    // A range stopped early holds fewer samples than it names: refused until finished.
    Image early = read_image((dir_ / "a.exr").string());
    read_film_part((dir_ / "a.exr").string(), early);
    early.metadata["stop"] = "interrupted";
    write_image((dir_ / "early.exr").string(), early);
    ASSERT_EQ(run(render_args("c.exr", " --sample-range 32:24")), 0) << text("stderr.txt");
    EXPECT_EQ(run("merge early.exr c.exr -o m.exr"), 2);
    EXPECT_NE(text("stderr.txt").find("early.exr: stopped early (interrupted)"), std::string::npos)
        << text("stderr.txt");
    // A count in the metadata past 64 bits is a malformed file, not an exception.
    Image huge = early;
    huge.metadata["stop"] = "spp";
    huge.metadata["film_batches"] = "99999999999999999999";
    write_image((dir_ / "huge.exr").string(), huge);
    EXPECT_EQ(run("merge huge.exr -o m.exr"), 2);
    EXPECT_NE(text("stderr.txt").find("huge.exr: its film part lacks a valid pathcl:film_batches"), std::string::npos)
        << text("stderr.txt");
    // The file written back is still a whole partial render: it merges once marked done.
    early.metadata["stop"] = "spp";
    write_image((dir_ / "early.exr").string(), early);
    ASSERT_EQ(run("merge early.exr c.exr -o m.exr"), 0) << text("stderr.txt");
    expect_same_image(read_image((dir_ / "m.exr").string()), read_image((dir_ / "whole.exr").string()));
}

} // namespace
} // namespace pathcl::test_cli_sample_ranges
