#include "interaction_profiles.h"

#include <map>
#include <vector>

namespace fgxrt {

namespace {

using Components = std::map<std::string, ComponentKind>;
using K = ComponentKind;

// Per hand: the path after /user/hand/<hand>/.
struct Profile {
    Components both, left_only, right_only;
};

const std::map<std::string, Profile>& profiles() {
    static const std::map<std::string, Profile> table = {
        {"/interaction_profiles/khr/simple_controller",
         {{{"input/select/click", K::Boolean}, {"input/menu/click", K::Boolean}, {"input/grip/pose", K::Pose},
           {"input/aim/pose", K::Pose}, {"output/haptic", K::Haptic}},
          {},
          {}}},
        {"/interaction_profiles/oculus/touch_controller",
         {{{"input/squeeze/value", K::Float}, {"input/trigger/value", K::Float}, {"input/trigger/touch", K::Boolean},
           {"input/thumbstick", K::Vector2}, {"input/thumbstick/x", K::Float}, {"input/thumbstick/y", K::Float},
           {"input/thumbstick/click", K::Boolean}, {"input/thumbstick/touch", K::Boolean},
           {"input/thumbrest/touch", K::Boolean}, {"input/grip/pose", K::Pose}, {"input/aim/pose", K::Pose},
           {"output/haptic", K::Haptic}},
          {{"input/x/click", K::Boolean}, {"input/x/touch", K::Boolean}, {"input/y/click", K::Boolean},
           {"input/y/touch", K::Boolean}, {"input/menu/click", K::Boolean}},
          {{"input/a/click", K::Boolean}, {"input/a/touch", K::Boolean}, {"input/b/click", K::Boolean},
           {"input/b/touch", K::Boolean}, {"input/system/click", K::Boolean}}}},
        {"/interaction_profiles/valve/index_controller",
         {{{"input/system/click", K::Boolean}, {"input/system/touch", K::Boolean}, {"input/a/click", K::Boolean},
           {"input/a/touch", K::Boolean}, {"input/b/click", K::Boolean}, {"input/b/touch", K::Boolean},
           {"input/squeeze/value", K::Float}, {"input/squeeze/force", K::Float}, {"input/trigger/click", K::Boolean},
           {"input/trigger/value", K::Float}, {"input/trigger/touch", K::Boolean}, {"input/thumbstick", K::Vector2},
           {"input/thumbstick/x", K::Float}, {"input/thumbstick/y", K::Float}, {"input/thumbstick/click", K::Boolean},
           {"input/thumbstick/touch", K::Boolean}, {"input/trackpad", K::Vector2}, {"input/trackpad/x", K::Float},
           {"input/trackpad/y", K::Float}, {"input/trackpad/force", K::Float}, {"input/trackpad/touch", K::Boolean},
           {"input/grip/pose", K::Pose}, {"input/aim/pose", K::Pose}, {"output/haptic", K::Haptic}},
          {},
          {}}},
    };
    return table;
}

}  // namespace

bool known_profile(const std::string& profile) { return profiles().count(profile) > 0; }

ComponentKind component_kind(const std::string& profile, const std::string& path) {
    auto it = profiles().find(profile);
    if (it == profiles().end()) return K::None;
    const std::string left = "/user/hand/left/", right = "/user/hand/right/";
    bool is_left = path.rfind(left, 0) == 0, is_right = path.rfind(right, 0) == 0;
    if (!is_left && !is_right) return K::None;
    std::string rest = path.substr(is_left ? left.size() : right.size());
    const Profile& p = it->second;
    for (const Components* c : {&p.both, is_left ? &p.left_only : &p.right_only})
        if (auto f = c->find(rest); f != c->end()) return f->second;
    return K::None;
}

}  // namespace fgxrt
