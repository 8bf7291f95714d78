#include "film/image_io.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

using namespace caustica;
namespace fs = std::filesystem;

namespace {

// A fresh, empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("caustica_image_io_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string &name) const { return (dir_ / name).string(); }
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto &e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
        return names;
    }
    fs::path dir_;
};

Image test_image(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                img.at(x, y, c) = std::ldexp(float(x + 1) / (y + 2 + c), (x * 7 + y * 3 + c) % 40 - 20) *
                                  ((x + c) % 3 == 0 ? -1 : 1);
    img.at(0, 0, 0) = 0;
    img.at(1, 0, 1) = std::numeric_limits<float>::denorm_min();
    img.at(2, 0, 2) = 1e30f;
    return img;
}

// The sRGB encoding as specified (IEC 61966-2-1), written out again for the test.
int expected_srgb8(double v) {
    if (!(v > 0)) return 0;
    if (v >= 1) return 255;
    double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return int(std::lround(255 * e));
}

} // namespace

TEST_F(ImageIoTest, ExrRoundTripIsBitExact) {
    Image img = test_image(13, 7);
    write_exr(path("a.exr"), img, {{"caustica:integrator", "pt"}, {"note", "hello"}});
    Image back = read_exr(path("a.exr"));
    ASSERT_EQ(back.width, 13);
    ASSERT_EQ(back.height, 7);
    EXPECT_EQ(back.origin, (Vec2i{0, 0}));
    EXPECT_EQ(back.full_resolution, (Vec2i{13, 7}));
    EXPECT_EQ(std::memcmp(back.rgb.data(), img.rgb.data(), img.rgb.size() * sizeof(float)), 0);
    // Metadata are string attributes.
    Imf::InputFile file(path("a.exr").c_str());
    auto *attr = file.header().findTypedAttribute<Imf::StringAttribute>("caustica:integrator");
    ASSERT_NE(attr, nullptr);
    EXPECT_EQ(attr->value(), "pt");
    EXPECT_EQ(files(), std::vector<std::string>{"a.exr"});  // no temporary left behind
}

TEST_F(ImageIoTest, ExrKeepsLayersAndSingleChannels) {
    // Layers are written as NAME.R/G/B and single channels under their own names (a spectral
    // film's "S0.550,000nm", a G-buffer's "P.X"); both read back as written. In half floats the
    // channels round and clamp as the RGB do.
    Image img = test_image(4, 3);
    img.layers.push_back({"Albedo", std::vector<float>(img.rgb.size(), 0.25f)});
    std::vector<float> values(12);
    for (size_t i = 0; i < values.size(); ++i) values[i] = float(i) / 3 - 1;
    values[5] = 1e6f;
    img.channels.push_back({"S0.550,000nm", values});
    img.channels.push_back({"P.X", std::vector<float>(12, 2.f)});
    write_exr(path("c.exr"), img, {});
    Image back = read_exr(path("c.exr"));
    ASSERT_EQ(back.layers.size(), 1u);
    EXPECT_EQ(back.layers[0].name, "Albedo");
    EXPECT_EQ(back.layers[0].rgb, img.layers[0].rgb);
    ASSERT_NE(back.channel("S0.550,000nm"), nullptr);
    EXPECT_EQ(back.channel("S0.550,000nm")->values, values);
    EXPECT_EQ(back.channel("P.X")->values, std::vector<float>(12, 2.f));
    EXPECT_EQ(back.channel("R"), nullptr);

    write_exr(path("h.exr"), img, {}, ExrPixelType::Half);
    Image half = read_exr(path("h.exr"));
    const std::vector<float> &h = half.channel("S0.550,000nm")->values;
    for (size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(h[i], float(Imath::half(std::min(values[i], 65504.f)))) << i;

    Image wrong = test_image(4, 3);
    wrong.channels.push_back({"u", std::vector<float>(5)});
    EXPECT_THROW(write_exr(path("w.exr"), wrong, {}), std::runtime_error);
}

TEST_F(ImageIoTest, ExrKeepsTheCropWindow) {
    Image img = test_image(5, 4);
    img.origin = {10, 3};
    img.full_resolution = {32, 16};
    write_exr(path("crop.exr"), img, {});
    Image back = read_exr(path("crop.exr"));
    EXPECT_EQ(back.origin, (Vec2i{10, 3}));
    EXPECT_EQ(back.full_resolution, (Vec2i{32, 16}));
    EXPECT_EQ(back.rgb, img.rgb);
}

TEST_F(ImageIoTest, HalfExrRoundsToHalfAndClampsToItsRange) {
    Image img(3, 1);
    img.rgb = {0.1f, 1.f / 3, 70000.f, -2.5f, 1e-6f, 65504.f, 0.f, 123.456f, 1e9f};
    write_exr(path("h.exr"), img, {}, ExrPixelType::Half);
    Image back = read_exr(path("h.exr"));
    for (size_t i = 0; i < img.rgb.size(); ++i)
        EXPECT_EQ(back.rgb[i], float(Imath::half(std::min(img.rgb[i], 65504.f)))) << i;
    EXPECT_EQ(back.rgb[2], 65504.f);
}

TEST_F(ImageIoTest, PngIsClampedSrgb8) {
    const std::vector<float> values = {0,    0.001f, 0.0031308f, 0.01f, 0.18f, 0.5f, 0.75f,
                                       0.99f, 1,     2.5f,       -1,    std::nanf(""), 1e-5f, 0.2140f};
    Image img(int(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) img.at(int(i), 0, c) = values[i] * (c == 1 ? 0.5f : 1);
    write_png(path("a.png"), img);
    auto in = OIIO::ImageInput::open(path("a.png"));
    ASSERT_TRUE(in);
    const OIIO::ImageSpec &spec = in->spec();
    ASSERT_EQ(spec.width, img.width);
    ASSERT_EQ(spec.nchannels, 3);
    std::vector<uint8_t> px(size_t(spec.width) * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    for (size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(px[i * 3 + 0], expected_srgb8(values[i])) << values[i];
        EXPECT_EQ(px[i * 3 + 1], expected_srgb8(values[i] * 0.5)) << values[i];
    }
    // Anchors of the curve: mid grey 0.5 encodes to 0.7354 (188), 0.18 to 0.4614 (118).
    EXPECT_EQ(tone_map_clamp_srgb8(0.5f), 188);
    EXPECT_EQ(tone_map_clamp_srgb8(0.18f), 118);
    EXPECT_EQ(files(), std::vector<std::string>{"a.png"});
}

TEST_F(ImageIoTest, FailedWritesThrowAndLeaveNoFile) {
    // A directory that cannot exist: its parent is a regular file (fails even for root).
    { std::ofstream(path("blocker")) << "x"; }
    Image img = test_image(4, 4);
    EXPECT_THROW(write_exr(path("blocker/out.exr"), img, {}), std::runtime_error);
    EXPECT_THROW(write_png(path("blocker/out.png"), img), std::runtime_error);
    EXPECT_THROW(write_exr(path("missing/out.exr"), img, {}), std::runtime_error);
    EXPECT_EQ(files(), std::vector<std::string>{"blocker"});
    try {
        write_exr(path("blocker/out.exr"), img, {});
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("out.exr"), std::string::npos);  // names the file
    }
    // An inconsistent image is refused before anything is created.
    Image broken(4, 4);
    broken.rgb.pop_back();
    EXPECT_THROW(write_png(path("broken.png"), broken), std::runtime_error);
    EXPECT_EQ(files(), std::vector<std::string>{"blocker"});
}

TEST_F(ImageIoTest, WritingReplacesAnExistingFile) {
    Image a = test_image(3, 3), b(3, 3);
    write_exr(path("x.exr"), a, {});
    write_exr(path("x.exr"), b, {});
    EXPECT_EQ(read_exr(path("x.exr")).rgb, b.rgb);
    EXPECT_EQ(files(), std::vector<std::string>{"x.exr"});
}

TEST_F(ImageIoTest, ReadingAMissingOrInvalidFileThrows) {
    EXPECT_THROW(read_exr(path("nothing.exr")), std::runtime_error);
    { std::ofstream(path("bad.exr")) << "not an exr"; }
    EXPECT_THROW(read_exr(path("bad.exr")), std::runtime_error);
}
