#pragma once
// Shared by the Vulkan tests: a fixture that gives each test its own validated Context and
// fails the test if the validation layer reported an error at any point of that Context's life.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vk/context.h"

namespace fg::vk::test {

// Validation with synchronization checks: a missing barrier fails the test like a wrong value.
ContextOptions validated_options();

// The layer's messages, one per line, for failure output.
std::string joined(const std::vector<std::string>& messages);

class VulkanTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    Context& ctx() { return *ctx_; }
    // For tests that provoke validation errors on purpose.
    void expect_validation_errors() { validation_errors_expected_ = true; }
    // Destroys the Context now (objects still alive are reported as leaks) and returns what the
    // layer said over its whole life.
    std::shared_ptr<const ValidationLog> finish_context();

private:
    std::unique_ptr<Context> ctx_;
    std::shared_ptr<const ValidationLog> log_;
    bool validation_errors_expected_ = false;
};

// Sets (or, with nullopt, unsets) an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(std::string name, std::optional<std::string> value);
    ~ScopedEnv();
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string name_;
    std::optional<std::string> previous_;
};

}  // namespace fg::vk::test
