// Checkpoints on the host (render/checkpoint.h): written and read back whole, read only as
// far as the render they belong to allows, and refused when any counter or value is one
// the render cannot have reached, for a checkpoint is a file anyone may have written (its
// checksum guards against damage, not against intent).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "common/error.h"
#include "render/checkpoint.h"
#include "support/expect_error.h"

namespace pathcl::test_checkpoint {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::error_of;

constexpr std::size_t kPixels = 4;

fs::path scratch(const std::string& name)
{
    return fs::temp_directory_path() / ("pathcl-checkpoint-" + std::to_string(::getpid()) + "-" + name);
}

// A render of 4 pixels, 40 spp in batches of 16: batches 0 and 1 whole, batch 2 of 8 passes.
BatchPlan plan()
{
    RenderOptions o;
    o.sampler = SamplerType::Independent;
    o.spp = 40;
    o.batch_spp = 16;
    return plan_batches(o);
}

// One device's film after `passes` passes of one sample per pixel, each of radiance 0.5.
std::vector<FilmPixel> device_film(std::uint32_t passes)
{
    std::vector<FilmPixel> film(kPixels);
    for (FilmPixel& f : film) {
        const float n = static_cast<float>(passes);
        f.sum = {0.5f * n, 0.5f * n, 0.5f * n, n};
        f.sum_sq = {0.25f * n, 0.25f * n, 0.25f * n, n};
    }
    return film;
}

// The state a render stopped at pass 3 of batch 1 writes: batch 0 whole in the film.
RenderCheckpoint valid_checkpoint()
{
    FilmAccumulator acc(kPixels, 16);
    FilmSum batch(kPixels);
    batch.add(device_film(16), std::vector<pcl_uint>(kPixels, 0u));
    acc.add_batch(batch);
    RenderCheckpoint cp;
    cp.key = "scene 0; size 2x2";
    cp.batch = 1;
    cp.pass = 3;
    cp.spp_done = 19;
    cp.samples = 19.0 * kPixels;
    cp.film = acc.state();
    cp.device_films = {device_film(3)};
    cp.device_bad = {std::vector<pcl_uint>(kPixels, 0u)};
    return cp;
}

// Guards the reader's copy of an empty array (the mask of a render that is not adaptive):
// memcpy from a null pointer, undefined even for 0 bytes, which the sanitizer build
// reported on every resume. Seen to fail there before the fix.
TEST(Checkpoint, WrittenAndReadBackWholeWithoutAnAdaptiveMask)
{
    const RenderCheckpoint cp = valid_checkpoint();
    const fs::path file = scratch("round-trip.bin");
    write_checkpoint(file.string(), cp);
    const RenderCheckpoint back = read_checkpoint(file.string(), kPixels);
    fs::remove(file);
    EXPECT_EQ(back.key, cp.key);
    EXPECT_EQ(back.batch, cp.batch);
    EXPECT_EQ(back.pass, cp.pass);
    EXPECT_EQ(back.spp_done, cp.spp_done);
    EXPECT_TRUE(back.active.empty());
    ASSERT_EQ(back.film.sum.size(), cp.film.sum.size());
    EXPECT_TRUE(back.film.sum[0] == cp.film.sum[0]);
    EXPECT_NO_THROW(check_checkpoint(back, plan(), kPixels, false));
}

// A file larger than any checkpoint of the render is refused from its size, before a
// byte is read: a 3 GB sparse file took 3.2 GB and 10 s to refuse for an 8x8 render
// whose checkpoint is 24 KB.
TEST(Checkpoint, AFileLargerThanTheRendersCheckpointIsRefusedUnread)
{
    const fs::path file = scratch("huge.bin");
    {
        std::FILE* f = std::fopen(file.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fclose(f);
    }
    fs::resize_file(file, std::uintmax_t(3) << 30); // sparse: no disk taken
    const std::string e = error_of([&] { read_checkpoint(file.string(), 64); });
    fs::remove(file);
    EXPECT_TRUE(contains(e, file.string() + ": is 3221225472 bytes, more than the limit of " +
                                std::to_string(max_checkpoint_bytes(64))))
        << e;
    EXPECT_LT(max_checkpoint_bytes(64), std::uint64_t(1) << 17);
}

// Every counter is checked against the render's layout and every value for what the
// render can hold. Broken variant seen to fail: without check_checkpoint a batch past the
// end resumed into a 19-spp image labelled complete, and the other cases into wrapped
// counters or NaN pixels.
TEST(Checkpoint, CountersAndValuesTheRenderCannotHaveAreRefused)
{
    EXPECT_NO_THROW(check_checkpoint(valid_checkpoint(), plan(), kPixels, false));
    struct Case {
        const char* what;
        void (*spoil)(RenderCheckpoint&);
        const char* says;
    };
    const Case cases[] = {
        {"batch past the end", [](RenderCheckpoint& c) { c.batch = 3; }, "which this render does not have"},
        {"pass past its batch", [](RenderCheckpoint& c) { c.pass = 16; }, "which this render does not have"},
        {"pass past the short last batch",
         [](RenderCheckpoint& c) {
             c.batch = 2;
             c.pass = 8;
         },
         "which this render does not have"},
        {"spp counter wrapped", [](RenderCheckpoint& c) { c.spp_done = 0xfffffff0u; }, "samples per pixel done"},
        {"samples NaN", [](RenderCheckpoint& c) { c.samples = NAN; }, "number of samples"},
        {"film batches", [](RenderCheckpoint& c) { c.film.batches = 2; }, "whole batches"},
        {"film sample count NaN", [](RenderCheckpoint& c) { c.film.samples[1] = NAN; }, "pixel 1 of its film"},
        {"film sample count past the samples taken", [](RenderCheckpoint& c) { c.film.samples[2] = 17.0; },
         "pixel 2 of its film"},
        {"film sum poisoned", [](RenderCheckpoint& c) { c.film.sum[3].add(INFINITY); }, "not a number"},
        {"film sum out of range", [](RenderCheckpoint& c) { c.film.sum_sq[0].limb[2] = 0x7fffffffffffffffull; },
         "out of range"},
        {"bad-sample count", [](RenderCheckpoint& c) { c.film.bad = 1000; }, "bad samples"},
        {"device film NaN", [](RenderCheckpoint& c) { c.device_films[0][2].sum_sq.y = NAN; }, "not finite"},
        {"device film count", [](RenderCheckpoint& c) { c.device_films[0][0].sum.w = 4.0f; }, "more samples"},
        {"device bad count", [](RenderCheckpoint& c) { c.device_bad[0][0] = 4; }, "more samples"},
        {"device film size", [](RenderCheckpoint& c) { c.device_films[0].pop_back(); }, "one film"},
        {"two device films", [](RenderCheckpoint& c) { c.device_films.push_back(c.device_films[0]); }, "one film"},
        {"mask without adaptive sampling", [](RenderCheckpoint& c) { c.active.assign(kPixels, 1u); }, "not adaptive"},
    };
    for (const Case& c : cases) {
        RenderCheckpoint cp = valid_checkpoint();
        c.spoil(cp);
        const std::string e = error_of([&] { check_checkpoint(cp, plan(), kPixels, false); });
        EXPECT_TRUE(contains(e, "resume: the checkpoint ")) << c.what << ": " << e;
        EXPECT_TRUE(contains(e, c.says)) << c.what << ": " << e;
    }
    RenderCheckpoint cp = valid_checkpoint();
    cp.active = {1u, 0u, 2u, 1u};
    EXPECT_TRUE(contains(error_of([&] { check_checkpoint(cp, plan(), kPixels, true); }), "other than 0 and 1"));
    cp.active.clear();
    EXPECT_TRUE(contains(error_of([&] { check_checkpoint(cp, plan(), kPixels, true); }), "no mask"));
}

} // namespace
} // namespace pathcl::test_checkpoint
