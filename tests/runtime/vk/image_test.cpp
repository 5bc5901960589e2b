#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_shaders.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"
#include "vk/image.h"
#include "vk/sampler.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

// Odd sizes, so a row pitch that is not width * bytes-per-pixel shows up as skew.
constexpr VkExtent2D kExtent{37, 23};

template <class T>
std::vector<std::byte> as_byte_vector(const std::vector<T>& values) {
    const auto bytes = std::as_bytes(std::span(values));
    return {bytes.begin(), bytes.end()};
}

// Distinct, finite values per format: a copy that reorders, drops or converts anything shows.
std::vector<std::byte> test_pixels(VkFormat format, VkExtent2D extent) {
    const std::size_t pixels = std::size_t{extent.width} * extent.height;
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT: {
            std::vector<std::uint16_t> halves(pixels * 4);
            // 0x3C00..0x3FFF are the halfs in [1, 2): all normal, all distinct.
            for (std::size_t i = 0; i < halves.size(); ++i) halves[i] = static_cast<std::uint16_t>(0x3C00 + i % 1024);
            return as_byte_vector(halves);
        }
        case VK_FORMAT_R8G8B8A8_UNORM: {
            std::vector<std::uint8_t> bytes(pixels * 4);
            for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i * 7 + 3);
            return as_byte_vector(bytes);
        }
        default: {
            std::vector<float> floats(pixels * bytes_per_pixel(format) / 4);
            for (std::size_t i = 0; i < floats.size(); ++i) floats[i] = static_cast<float>(i) * 0.25f - 100.0f;
            return as_byte_vector(floats);
        }
    }
}

class ImageFormatTest : public test::VulkanTest, public ::testing::WithParamInterface<VkFormat> {};

TEST_P(ImageFormatTest, AStorageImageRoundTripsThroughUploadAndDownload) {
    StorageImage image(ctx(), GetParam(), kExtent);
    EXPECT_EQ(image.byte_size(), std::size_t{kExtent.width} * kExtent.height * bytes_per_pixel(GetParam()));

    const auto pixels = test_pixels(GetParam(), kExtent);
    image.upload(pixels);
    EXPECT_EQ(image.layout(), VK_IMAGE_LAYOUT_GENERAL);
    const auto downloaded = image.download();
    EXPECT_EQ(image.layout(), VK_IMAGE_LAYOUT_GENERAL);
    ASSERT_EQ(downloaded.size(), pixels.size());
    EXPECT_TRUE(downloaded == pixels) << format_name(GetParam()) << " pixels changed on the way";
}

INSTANTIATE_TEST_SUITE_P(EveryStorageFormat, ImageFormatTest,
                         ::testing::Values(VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT,
                                           VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
                                           VK_FORMAT_R8G8B8A8_UNORM),
                         [](const ::testing::TestParamInfo<VkFormat>& param_info) { return format_name(param_info.param); });

using ImageTest = test::VulkanTest;

TEST_F(ImageTest, PixelsAShaderStoresAppearInTheDownload) {
    StorageImage image(ctx(), VK_FORMAT_R32G32B32A32_SFLOAT, kExtent);
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
    DescriptorPool pool(ctx(), layout, 1);
    const VkDescriptorSet set = pool.allocate(layout);
    write_storage_image(ctx(), set, 0, image);
    ComputePipeline pipeline(ctx(), test::shaders::write_image_spv, {layout.handle()});

    EXPECT_EQ(image.layout(), VK_IMAGE_LAYOUT_UNDEFINED);
    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        image.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, access::none, access::compute_write);
        pipeline.dispatch(cmd, set, {groups_for(kExtent.width, 8), groups_for(kExtent.height, 8)});
    });
    EXPECT_EQ(image.layout(), VK_IMAGE_LAYOUT_GENERAL);

    const auto bytes = image.download();
    std::vector<float> texels(bytes.size() / sizeof(float));
    std::memcpy(texels.data(), bytes.data(), bytes.size());
    int wrong = 0;
    for (std::uint32_t y = 0; y < kExtent.height; ++y) {
        for (std::uint32_t x = 0; x < kExtent.width; ++x) {
            const float* t = &texels[(std::size_t{y} * kExtent.width + x) * 4];
            const bool right = t[0] == static_cast<float>(x) && t[1] == static_cast<float>(y) &&
                               t[2] == static_cast<float>(x * 1000 + y) && t[3] == 1.0f;
            if (!right && ++wrong <= 5)
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") is (" << t[0] << ", " << t[1] << ", " << t[2]
                              << ", " << t[3] << ")";
        }
    }
    EXPECT_EQ(wrong, 0);
}

TEST_F(ImageTest, AShaderReadsAnImageThroughACombinedImageSampler) {
    StorageImage image(ctx(), VK_FORMAT_R32G32B32A32_SFLOAT, kExtent);
    const auto pixels = test_pixels(VK_FORMAT_R32G32B32A32_SFLOAT, kExtent);
    image.upload(pixels);

    Buffer texels(ctx(), image.byte_size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Readback);
    Sampler sampler(ctx());
    DescriptorSetLayout layout(ctx(), {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    DescriptorPool pool(ctx(), layout, 1);
    const VkDescriptorSet set = pool.allocate(layout);
    write_combined_image_sampler(ctx(), set, 0, sampler, image);
    write_storage_buffer(ctx(), set, 1, texels);
    ComputePipeline pipeline(ctx(), test::shaders::sample_image_spv, {layout.handle()});

    OneShot::run(ctx(), [&](VkCommandBuffer cmd) {
        image.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, access::any_write, access::compute_read);
        pipeline.dispatch(cmd, set, {groups_for(kExtent.width, 8), groups_for(kExtent.height, 8)});
        compute_to_host_barrier(cmd);
    });
    EXPECT_EQ(image.layout(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

    std::vector<std::byte> read(image.byte_size());
    texels.download(read);
    EXPECT_TRUE(read == pixels) << "sampled texels differ from the uploaded ones";
}

TEST_F(ImageTest, PixelSizesFollowTheFormat) {
    EXPECT_EQ(bytes_per_pixel(VK_FORMAT_R32_SFLOAT), 4u);
    EXPECT_EQ(bytes_per_pixel(VK_FORMAT_R32G32_SFLOAT), 8u);
    EXPECT_EQ(bytes_per_pixel(VK_FORMAT_R16G16B16A16_SFLOAT), 8u);
    EXPECT_EQ(bytes_per_pixel(VK_FORMAT_R32G32B32A32_SFLOAT), 16u);
    EXPECT_EQ(bytes_per_pixel(VK_FORMAT_R8G8B8A8_UNORM), 4u);
    EXPECT_THROW(bytes_per_pixel(VK_FORMAT_R8G8B8_SRGB), std::invalid_argument);
}

TEST_F(ImageTest, FormatsOutsideTheStorageListAndEmptyImagesAreRefused) {
    EXPECT_THROW(StorageImage(ctx(), VK_FORMAT_R8G8B8_SRGB, kExtent), std::invalid_argument);
    EXPECT_THROW(StorageImage(ctx(), VK_FORMAT_R32_SFLOAT, VkExtent2D{0, 4}), std::invalid_argument);
}

TEST_F(ImageTest, AnUploadOfTheWrongSizeIsRefused) {
    StorageImage image(ctx(), VK_FORMAT_R32_SFLOAT, kExtent);
    const std::vector<std::byte> too_few(image.byte_size() - 4);
    EXPECT_THROW(image.upload(too_few), std::invalid_argument);
}

}  // namespace
}  // namespace fg::vk
