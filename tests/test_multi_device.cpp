// One render on several devices (render/device_bands.h) is the one-device render bit for
// bit: every value of the EXR, variance and per-pixel sample counts included, for a
// plain render, for one of batches with adaptive sampling, with the rows first dealt
// unevenly, so that they are dealt again (and their films moved) in the middle of a batch,
// and for a render stopped inside a batch and resumed from its checkpoint.
// PoCL shows two devices when POCL_DEVICES names a CPU driver twice: its single-threaded
// "basic" driver here, as two instances of its "pthread" driver stall for tens of seconds
// at random, even at one thread each (they share one scheduler).
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/same_image.h"
#include "support/tool_run.h"

namespace pathcl::test_multi_device {
namespace {

using test::expect_same_image;
using test::ToolRun;

const std::string kTwoDevices = "POCL_DEVICES='basic basic'";
const std::string kGlass = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box-glass-mirror.gltf";
const std::string kCornell = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf";

class MultiDevice : public ToolRun {
protected:
    void SetUp() override
    {
        ToolRun::SetUp();
        ASSERT_EQ(run("devices", kTwoDevices), 0) << text("stderr.txt");
        if (text("stdout.txt").find("\n1: ") == std::string::npos)
            GTEST_SKIP() << "the OpenCL platform shows one device (not PoCL?)";
    }

    // Renders `options` on each device list and checks every image against the first.
    void expect_same_images(const std::string& scene, const std::string& options,
                            const std::vector<std::string>& device_flags)
    {
        for (std::size_t i = 0; i < device_flags.size(); ++i) {
            const std::string out = "r" + std::to_string(i) + ".exr";
            ASSERT_EQ(
                run("render '" + scene + "' -o " + out + " --quiet " + options + " " + device_flags[i], kTwoDevices), 0)
                << device_flags[i] << ": " << text("stderr.txt");
        }
        const Image first = read_image((dir_ / "r0.exr").string());
        for (std::size_t i = 1; i < device_flags.size(); ++i)
            expect_same_image(first, read_image((dir_ / ("r" + std::to_string(i) + ".exr")).string()), device_flags[i]);
    }
};

TEST_F(MultiDevice, TwoDevicesRenderTheOneDeviceImage)
{
    // 37 rows: the second band ends off the tile grid. Seen to fail: with the rows moved
    // between devices without their films, "radiance differs" for --device-shares 1,7.
    expect_same_images(kGlass, "--width 40 --height 37 --spp 24",
                       {"--device 0", "--device 0,1", "--device all", "--device 0,1 --device-shares 1,7",
                        "--device 1,0 --device-shares 5,0"});
}

TEST_F(MultiDevice, BatchesAndAdaptiveSamplingAreTheSameOnTwoDevices)
{
    expect_same_images(kCornell,
                       "--width 40 --height 37 --max-spp 64 --batch-spp 8 --adaptive --target-error 0.004 "
                       "--max-bounces 4",
                       {"--device 0", "--device 0,1 --device-shares 3,1"});
}

TEST_F(MultiDevice, StoppedAndResumedOnTwoDevicesIsTheOneDeviceImage)
{
    // A time budget stops the two-device render inside a batch; its checkpoint holds one
    // film composed from both devices' bands, which the resumed render deals out again.
    const std::string o = " --width 48 --height 45 --batch-spp 64 --quiet";
    ASSERT_EQ(run("render '" + kGlass + "' -o full.exr --spp 256 --device 0" + o, kTwoDevices), 0)
        << text("stderr.txt");
    ASSERT_EQ(run("render '" + kGlass + "' -o part.exr --max-spp 256 --time 0.3 --checkpoint cp.bin --device 0,1" + o,
                  kTwoDevices),
              0)
        << text("stderr.txt");
    ASSERT_EQ(run("render '" + kGlass + "' -o resumed.exr --spp 256 --resume cp.bin --device 0,1" + o, kTwoDevices), 0)
        << text("stderr.txt");
    expect_same_image(read_image((dir_ / "full.exr").string()), read_image((dir_ / "resumed.exr").string()),
                      "resumed on two devices");
}

} // namespace
} // namespace pathcl::test_multi_device
