#include "vk_test_support.h"

#include <cstdlib>

namespace fg::vk::test {

ContextOptions validated_options() {
    ContextOptions options;
    options.validation = true;
    options.synchronization_validation = true;
    return options;
}

std::string joined(const std::vector<std::string>& messages) {
    std::string out;
    for (const std::string& m : messages) out += m + "\n";
    return out;
}

void VulkanTest::SetUp() {
    ctx_ = std::make_unique<Context>(validated_options());
    log_ = ctx_->validation_log();
    // Without the layer every "no validation errors" check below would pass vacuously.
    ASSERT_TRUE(ctx_->validation_enabled()) << "VK_LAYER_KHRONOS_validation is needed (vulkan-validationlayers)";
}

std::shared_ptr<const ValidationLog> VulkanTest::finish_context() {
    ctx_.reset();
    return log_;
}

void VulkanTest::TearDown() {
    finish_context();
    if (!log_ || validation_errors_expected_) return;
    EXPECT_EQ(log_->errors(), 0u) << joined(log_->messages());
}

ScopedEnv::ScopedEnv(std::string name, std::optional<std::string> value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) previous_ = old;
    if (value)
        ::setenv(name_.c_str(), value->c_str(), 1);
    else
        ::unsetenv(name_.c_str());
}

ScopedEnv::~ScopedEnv() {
    if (previous_)
        ::setenv(name_.c_str(), previous_->c_str(), 1);
    else
        ::unsetenv(name_.c_str());
}

}  // namespace fg::vk::test
