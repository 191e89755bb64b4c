// The NIfTI reader on a 4D .nii.gz written with libnifti2: voxel sizes, TR as time, scaling.
#include <cstring>

#include <gtest/gtest.h>
#include <nifti2_io.h>

#include "tstyles/data/series_opener.h"

namespace {

TEST(NiftiReader, FourDimensionalGzipImageIsASeriesAlongTime) {
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_readers_test" / "nifti";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::int64_t dims[8] = {4, 3, 2, 2, 2, 1, 1, 1};
    nifti_image* image = nifti_make_new_nim(dims, DT_INT16, 1);
    ASSERT_NE(image, nullptr);
    image->dx = image->pixdim[1] = 2.0;
    image->dy = image->pixdim[2] = 3.0;
    image->dz = image->pixdim[3] = 4.0;
    image->dt = image->pixdim[4] = 2.5;
    auto* values = static_cast<std::int16_t*>(image->data);
    for (int index = 0; index < 24; ++index) values[index] = std::int16_t(index);
    const std::string prefix = (folder / "bold.nii.gz").string();
    ASSERT_EQ(nifti_set_filenames(image, prefix.c_str(), 0, 1), 0);
    nifti_image_write(image);
    nifti_image_free(image);

    const tstyles::Series series = tstyles::openSeries(folder / "bold.nii.gz", {});
    ASSERT_EQ(series.size(), 2u);
    EXPECT_DOUBLE_EQ(series.steps[1].time, 2.5);
    EXPECT_EQ(series.steps[0].rectilinear().dims, glm::ivec3(3, 2, 2));
    EXPECT_EQ(series.steps[0].rectilinear().spacing, glm::dvec3(2, 3, 4));
    EXPECT_NEAR(series.steps[1].density[0], 12.0 / 23.0, 1e-6);
}

}  // namespace
