#include <string>

#include <gtest/gtest.h>

#include "vk/vulkan_error.h"

namespace fg::vk {
namespace {

TEST(VulkanError, AFailingCallNamesTheCallAndTheResult) {
    try {
        check(VK_ERROR_INITIALIZATION_FAILED, "vkCreateDevice");
        FAIL() << "check() did not throw";
    } catch (const VulkanError& e) {
        EXPECT_STREQ(e.what(), "vkCreateDevice failed: VK_ERROR_INITIALIZATION_FAILED");
        EXPECT_EQ(e.result(), VK_ERROR_INITIALIZATION_FAILED);
    }
}

TEST(VulkanError, SuccessAndStatusCodesDoNotThrow) {
    EXPECT_NO_THROW(check(VK_SUCCESS, "vkCreateBuffer"));
    EXPECT_NO_THROW(check(VK_INCOMPLETE, "vkEnumeratePhysicalDevices"));
    EXPECT_NO_THROW(check(VK_TIMEOUT, "vkWaitForFences"));
}

TEST(VulkanError, ResultCodesHaveTheirSpecNames) {
    EXPECT_STREQ(result_name(VK_SUCCESS), "VK_SUCCESS");
    EXPECT_STREQ(result_name(VK_ERROR_DEVICE_LOST), "VK_ERROR_DEVICE_LOST");
    EXPECT_STREQ(result_name(VK_ERROR_OUT_OF_DEVICE_MEMORY), "VK_ERROR_OUT_OF_DEVICE_MEMORY");
    EXPECT_STREQ(result_name(VK_ERROR_VALIDATION_FAILED_EXT), "VK_ERROR_VALIDATION_FAILED_EXT");
}

TEST(VulkanError, AnUnknownResultCodeIsReportedByNumber) {
    const auto unknown = static_cast<VkResult>(-123456);
    EXPECT_STREQ(result_name(unknown), "VK_RESULT_UNKNOWN");
    try {
        check(unknown, "vkQueueSubmit2");
        FAIL() << "check() did not throw";
    } catch (const VulkanError& e) {
        EXPECT_EQ(std::string(e.what()), "vkQueueSubmit2 failed: VkResult -123456");
        EXPECT_EQ(e.result(), unknown);
    }
}

}  // namespace
}  // namespace fg::vk
