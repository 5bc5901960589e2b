// Device ranking without the hardware: the candidates below stand in for a multi-GPU machine.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vk/device_selection.h"
#include "vk/vulkan_error.h"

namespace fg::vk {
namespace {

DeviceCandidate candidate(std::uint32_t index, std::string name, VkPhysicalDeviceType type) {
    DeviceCandidate c;
    c.index = index;
    c.name = std::move(name);
    c.type = type;
    c.api_version = VK_MAKE_API_VERSION(0, 1, 3, 250);
    c.compute_family = 0;
    c.timestamps = true;
    c.synchronization2 = true;
    return c;
}

std::vector<DeviceCandidate> mixed_machine() {
    return {candidate(0, "llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
            candidate(1, "Intel(R) UHD Graphics 770", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
            candidate(2, "NVIDIA GeForce RTX 4070", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
            candidate(3, "Virtio-GPU Venus", VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU)};
}

std::string selection_error(const std::vector<DeviceCandidate>& devices, std::string_view choice,
                            bool require_timestamps = true) {
    try {
        choose_device(devices, choice, require_timestamps);
    } catch (const VulkanError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(DeviceSelection, ADiscreteGpuIsPreferredOverIntegratedVirtualAndCpuDevices) {
    const auto devices = mixed_machine();
    EXPECT_EQ(devices[choose_device(devices, "", true)].name, "NVIDIA GeForce RTX 4070");

    auto without_discrete = devices;
    without_discrete.erase(without_discrete.begin() + 2);
    EXPECT_EQ(without_discrete[choose_device(without_discrete, "", true)].type, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU);

    const std::vector<DeviceCandidate> virtual_and_cpu{devices[0], devices[3]};
    EXPECT_EQ(virtual_and_cpu[choose_device(virtual_and_cpu, "", true)].type, VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU);
}

TEST(DeviceSelection, AnUnusableDeviceIsPassedOverEvenWhenItRanksHigher) {
    auto devices = mixed_machine();
    devices[2].api_version = VK_MAKE_API_VERSION(0, 1, 2, 0);  // discrete, but too old
    devices[1].synchronization2 = false;                       // integrated, but no sync2
    devices[3].compute_family.reset();                         // virtual, but no compute queue
    EXPECT_EQ(devices[choose_device(devices, "", true)].index, 0u);
}

TEST(DeviceSelection, TimestampSupportIsRequiredOnlyWhenAskedFor) {
    auto devices = mixed_machine();
    devices[2].timestamps = false;
    EXPECT_EQ(devices[choose_device(devices, "", true)].index, 1u);
    EXPECT_EQ(devices[choose_device(devices, "", false)].index, 2u);
}

TEST(DeviceSelection, ADeviceCanBeChosenByIndexOrByPartOfItsNameInAnyCase) {
    const auto devices = mixed_machine();
    EXPECT_EQ(devices[choose_device(devices, "0", true)].index, 0u);
    EXPECT_EQ(devices[choose_device(devices, "3", true)].index, 3u);
    EXPECT_EQ(devices[choose_device(devices, "LLVMpipe", true)].index, 0u);
    EXPECT_EQ(devices[choose_device(devices, "uhd graphics", true)].index, 1u);
}

TEST(DeviceSelection, ChoosingADeviceThatDoesNotExistListsTheAvailableDevices) {
    const std::string message = selection_error(mixed_machine(), "radeon");
    EXPECT_NE(message.find("no Vulkan device matches 'radeon'"), std::string::npos) << message;
    for (const char* name : {"llvmpipe", "Intel(R) UHD Graphics 770", "NVIDIA GeForce RTX 4070", "Virtio-GPU Venus"})
        EXPECT_NE(message.find(name), std::string::npos) << name << " missing from: " << message;

    const std::string by_index = selection_error(mixed_machine(), "7");
    EXPECT_NE(by_index.find("no Vulkan device matches '7'"), std::string::npos) << by_index;
    EXPECT_NE(by_index.find("2: NVIDIA GeForce RTX 4070 [discrete"), std::string::npos) << by_index;
}

TEST(DeviceSelection, ChoosingAnUnusableDeviceSaysWhy) {
    auto devices = mixed_machine();
    devices[2].api_version = VK_MAKE_API_VERSION(0, 1, 2, 0);
    const std::string message = selection_error(devices, "nvidia");
    EXPECT_NE(message.find("'nvidia' cannot be used"), std::string::npos) << message;
    EXPECT_NE(message.find("supports Vulkan 1.2, needs 1.3"), std::string::npos) << message;
}

TEST(DeviceSelection, NoDeviceAtAllGetsAnInstallHint) {
    const std::string message = selection_error({}, "");
    EXPECT_NE(message.find("no Vulkan device found: install mesa-vulkan-drivers for lavapipe"), std::string::npos)
        << message;
}

TEST(DeviceSelection, AComputeQueueThatWritesTimestampsIsPreferred) {
    std::vector<VkQueueFamilyProperties> families(3);
    families[0].queueFlags = VK_QUEUE_GRAPHICS_BIT;  // no compute
    families[0].queueCount = 1;
    families[0].timestampValidBits = 64;
    families[1].queueFlags = VK_QUEUE_COMPUTE_BIT;
    families[1].queueCount = 1;
    families[1].timestampValidBits = 0;
    families[2].queueFlags = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
    families[2].queueCount = 2;
    families[2].timestampValidBits = 36;
    EXPECT_EQ(choose_compute_family(families), 2u);

    families[2].timestampValidBits = 0;
    EXPECT_EQ(choose_compute_family(families), 1u);

    families[1].queueFlags = VK_QUEUE_TRANSFER_BIT;
    families[2].queueFlags = VK_QUEUE_TRANSFER_BIT;
    EXPECT_EQ(choose_compute_family(families), std::nullopt);
}

}  // namespace
}  // namespace fg::vk
