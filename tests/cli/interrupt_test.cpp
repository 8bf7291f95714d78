// SIGINT and SIGTERM during a render: the command stops, writes the image accumulated so far
// (normalised by the samples actually taken, marked partial) and exits with 128 + the signal.
#include "process_test_support.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <csignal>
#include <thread>

using namespace caustica::testing;

namespace {

// Starts `caustica render` on the Cornell box with a sample count far beyond what can finish,
// waits until its statistics show it is rendering (the progress output), sends the signal and
// returns the exit status.
int interrupt_render(int signal_number, const std::string &out, const std::string &log) {
    std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";
    const pid_t pid = start_caustica({"render", scene, "--spp", "1000000", "-o", out}, log);
    // Wait for the first progress line: the scene is built and samples are being taken.
    for (int i = 0; i < 600 && read_text(log).find("progress:") == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    kill(pid, signal_number);
    const int status = wait_for(pid);
    return status < 1000 ? status : -1;
}

void expect_partial_image(const std::string &out) {
    auto in = OIIO::ImageInput::open(out);
    ASSERT_TRUE(in) << out;
    EXPECT_EQ(in->spec().get_string_attribute("caustica:partial"), "true");
    in->close();
    RgbImage img = read_rgb(out);
    RgbImage ref = read_rgb(data_path("renderer/cornell-box.pt-4096spp.exr"));
    // Normalised by the samples actually taken: the image mean matches the converged reference.
    // At the one or more samples per pixel reached in a second, the mean over 16k pixels has a
    // relative standard error near 1%; 10% is generous, while a wrong normalisation (dividing by
    // the requested million samples, or counting unsampled pixels) is off by orders of magnitude.
    for (int c = 0; c < 3; ++c) {
        double sum = 0, ref_sum = 0;
        for (size_t i = c; i < img.rgb.size(); i += 3) {
            ASSERT_TRUE(std::isfinite(img.rgb[i]));
            sum += img.rgb[i];
            ref_sum += ref.rgb[i];
        }
        EXPECT_NEAR(sum / ref_sum, 1.0, 0.1) << "channel " << c;
    }
}

TEST(Interrupt, SigintWritesThePartialImageAndExits130) {
    std::string dir = scratch_dir("sigint");
    EXPECT_EQ(interrupt_render(SIGINT, dir + "/partial.exr", dir + "/log.txt"), 130) << read_text(dir + "/log.txt");
    expect_partial_image(dir + "/partial.exr");
}

TEST(Interrupt, SigtermWritesThePartialImageAndExits143) {
    std::string dir = scratch_dir("sigterm");
    EXPECT_EQ(interrupt_render(SIGTERM, dir + "/partial.exr", dir + "/log.txt"), 143) << read_text(dir + "/log.txt");
    expect_partial_image(dir + "/partial.exr");
}

} // namespace
