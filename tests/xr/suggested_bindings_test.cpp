// The test runtime checks suggested bindings the way a real runtime does, so fgplay's bindings being
// accepted means something: a path the profile lacks, a path of the wrong kind for the action, an
// unknown profile and a malformed path are all refused. Loaded through the real OpenXR loader.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include <openxr/openxr.h>

namespace {

class SuggestedBindings : public ::testing::Test {
protected:
    void SetUp() override {
        setenv("XR_RUNTIME_JSON", FG_XR_TEST_RUNTIME_JSON, 1);
        unsetenv("XR_ENABLE_API_LAYERS");
        XrInstanceCreateInfo ci{XR_TYPE_INSTANCE_CREATE_INFO};
        std::strcpy(ci.applicationInfo.applicationName, "bindings test");
        ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
        ASSERT_EQ(xrCreateInstance(&ci, &instance_), XR_SUCCESS);
        XrActionSetCreateInfo si{XR_TYPE_ACTION_SET_CREATE_INFO};
        std::strcpy(si.actionSetName, "locomotion");
        std::strcpy(si.localizedActionSetName, "Locomotion");
        ASSERT_EQ(xrCreateActionSet(instance_, &si, &set_), XR_SUCCESS);
        fly_ = make("fly", XR_ACTION_TYPE_FLOAT_INPUT);
        turn_ = make("turn", XR_ACTION_TYPE_VECTOR2F_INPUT);
    }
    void TearDown() override {
        if (instance_) xrDestroyInstance(instance_);
    }

    XrAction make(const char* name, XrActionType type) {
        XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
        std::strcpy(ai.actionName, name);
        std::strcpy(ai.localizedActionName, name);
        ai.actionType = type;
        XrAction a = XR_NULL_HANDLE;
        EXPECT_EQ(xrCreateAction(set_, &ai, &a), XR_SUCCESS);
        return a;
    }
    XrPath path(const char* text) {
        XrPath p = XR_NULL_PATH;
        EXPECT_EQ(xrStringToPath(instance_, text, &p), XR_SUCCESS) << text;
        return p;
    }
    XrResult suggest(const char* profile, XrAction action, const char* binding) {
        XrActionSuggestedBinding b{action, path(binding)};
        XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        sb.interactionProfile = path(profile);
        sb.countSuggestedBindings = 1;
        sb.suggestedBindings = &b;
        return xrSuggestInteractionProfileBindings(instance_, &sb);
    }

    XrInstance instance_ = XR_NULL_HANDLE;
    XrActionSet set_ = XR_NULL_HANDLE;
    XrAction fly_ = XR_NULL_HANDLE, turn_ = XR_NULL_HANDLE;
};

TEST_F(SuggestedBindings, bindings_that_exist_on_the_profile_are_accepted) {
    EXPECT_EQ(suggest("/interaction_profiles/oculus/touch_controller", fly_, "/user/hand/right/input/trigger/value"), XR_SUCCESS);
    EXPECT_EQ(suggest("/interaction_profiles/valve/index_controller", turn_, "/user/hand/right/input/thumbstick"), XR_SUCCESS);
    // A click bound to a float action reads as 0 or 1, as the spec allows.
    EXPECT_EQ(suggest("/interaction_profiles/khr/simple_controller", fly_, "/user/hand/right/input/select/click"), XR_SUCCESS);
}

TEST_F(SuggestedBindings, a_path_the_profile_lacks_or_of_the_wrong_kind_is_refused) {
    EXPECT_EQ(suggest("/interaction_profiles/khr/simple_controller", turn_, "/user/hand/right/input/thumbstick"),
              XR_ERROR_PATH_UNSUPPORTED) << "the simple controller has no thumbstick";
    EXPECT_EQ(suggest("/interaction_profiles/oculus/touch_controller", fly_, "/user/hand/left/input/a/click"),
              XR_ERROR_PATH_UNSUPPORTED) << "A is on the right Touch controller";
    EXPECT_EQ(suggest("/interaction_profiles/oculus/touch_controller", turn_, "/user/hand/right/input/trigger/value"),
              XR_ERROR_PATH_UNSUPPORTED) << "a vector2f action needs a 2D input";
    EXPECT_EQ(suggest("/interaction_profiles/acme/no_such_controller", fly_, "/user/hand/right/input/trigger/value"),
              XR_ERROR_PATH_UNSUPPORTED);
}

TEST_F(SuggestedBindings, paths_are_interned_and_malformed_ones_refused) {
    XrPath a = path("/user/hand/left"), b = path("/user/hand/left");
    EXPECT_EQ(a, b);
    char buffer[XR_MAX_PATH_LENGTH];
    std::uint32_t length = 0;
    ASSERT_EQ(xrPathToString(instance_, a, sizeof buffer, &length, buffer), XR_SUCCESS);
    EXPECT_STREQ(buffer, "/user/hand/left");
    EXPECT_EQ(length, std::strlen("/user/hand/left") + 1);
    XrPath bad = XR_NULL_PATH;
    EXPECT_EQ(xrStringToPath(instance_, "user/hand", &bad), XR_ERROR_PATH_FORMAT_INVALID);
    EXPECT_EQ(xrStringToPath(instance_, "/user//hand", &bad), XR_ERROR_PATH_FORMAT_INVALID);
    EXPECT_EQ(xrStringToPath(instance_, "/User/Hand", &bad), XR_ERROR_PATH_FORMAT_INVALID);
}

TEST_F(SuggestedBindings, action_names_must_be_well_formed_and_unique) {
    XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
    std::strcpy(ai.actionName, "fly");
    std::strcpy(ai.localizedActionName, "Fly again");
    ai.actionType = XR_ACTION_TYPE_FLOAT_INPUT;
    XrAction a = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateAction(set_, &ai, &a), XR_ERROR_NAME_DUPLICATED);
    std::strcpy(ai.actionName, "Fly Fast");
    EXPECT_EQ(xrCreateAction(set_, &ai, &a), XR_ERROR_PATH_FORMAT_INVALID);
}

}  // namespace
