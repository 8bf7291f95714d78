// The "nanovdb" medium (media/nanovdb_medium.h): a grid written with NanoVDB's own builder is
// read back through the scene parameters, placed by its voxel size and origin, interpolated
// trilinearly between voxel centres, bounded by its majorants; and bad files are errors at the
// "filename" parameter.
#include "param_helpers.h"

#include "core/error.h"
#include "core/rng.h"
#include "media/medium_factory.h"
#include "spectral/color_space.h"

#include <gtest/gtest.h>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace caustica {
namespace {

using namespace caustica::testing;

class NanoVDBMediumTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("caustica-nanovdb-" + std::to_string(getpid()));
        std::filesystem::create_directories(dir_);
        // Voxel (i, j, k) of a 4 x 4 x 4 block holds 1 + i + 2 j + 4 k; voxels are 0.5 units wide
        // and the index origin sits at (1, 0, 0), so voxel centre (i, j, k) is at
        // (1 + 0.5 i, 0.5 j, 0.5 k) (NanoVDB's index space puts voxel centres at integers).
        nanovdb::GridBuilder<float> builder(0.f);
        auto accessor = builder.getAccessor();
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) accessor.setValue(nanovdb::Coord(i, j, k), value(i, j, k));
        builder.setGridClass(nanovdb::GridClass::FogVolume);
        nanovdb::io::writeGrid((dir_ / "block.nvdb").string(), builder.getHandle<>(0.5, nanovdb::Vec3d(1, 0, 0), "density"));
        std::ofstream((dir_ / "garbage.nvdb").string()) << "not a NanoVDB file";
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    static float value(int i, int j, int k) { return float(1 + i + 2 * j + 4 * k); }

    MediumPtr create(std::vector<ParsedParameter> params) {
        ParameterDictionary dict(std::move(params), SourceLocation{"test.pbrt", 1, 1}, &RGBColorSpace::srgb(),
                                 dir_.string());
        return create_medium("nanovdb", dict, SourceLocation{"test.pbrt", 1, 1});
    }
    int error_line(std::vector<ParsedParameter> params) {
        return input_error_line([&] { create(std::move(params)); });
    }

    std::filesystem::path dir_;
};

TEST_F(NanoVDBMediumTest, ReadsTheDensityGridAndInterpolatesIt) {
    MediumPtr medium = create({strings("string", "filename", {"block.nvdb"}, 2), numbers("rgb", "sigma_s", {2, 2, 2}, 3),
                               numbers("float", "scale", {0.5f}, 4)});
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    // At voxel centres: the voxel's value times scale times sigma.
    for (auto [i, j, k] : {std::array{1, 1, 1}, std::array{2, 1, 2}, std::array{1, 2, 1}}) {
        const Vec3f p{1 + 0.5f * i, 0.5f * j, 0.5f * k};
        EXPECT_NEAR(medium->properties(p, lambda).sigma_s[0], 2 * 0.5f * value(i, j, k), 1e-4f);
        EXPECT_NEAR(medium->properties(p, lambda).sigma_a[0], 0.5f * value(i, j, k), 1e-4f) << "default sigma_a 1";
    }
    // Half way between two centres along x: the mean of the two.
    EXPECT_NEAR(medium->properties({1.75f, 0.5f, 0.5f}, lambda).sigma_a[0], 0.5f * (value(1, 1, 1) + value(2, 1, 1)) / 2,
                1e-4f);
    EXPECT_EQ(medium->properties({0, 0.5f, 0.5f}, lambda).sigma_a[0], 0) << "outside the grid's bounds";
    EXPECT_NEAR(medium->max_sigma_t(lambda)[0], 3 * 0.5f * value(3, 3, 3), 1e-4f) << "the majorant is the largest voxel";
}

TEST_F(NanoVDBMediumTest, BadFilesAreErrorsAtTheFilename) {
    EXPECT_EQ(error_line({strings("string", "filename", {"missing.nvdb"}, 5)}), 5);
    EXPECT_EQ(error_line({strings("string", "filename", {"garbage.nvdb"}, 6)}), 6);
    EXPECT_EQ(error_line({strings("string", "filename", {"block.nvdb"}, 7), strings("string", "gridname", {"smoke"}, 8)}), 7)
        << "no grid of that name";
    EXPECT_EQ(error_line({}), 1) << "no filename";
}

} // namespace
} // namespace caustica
