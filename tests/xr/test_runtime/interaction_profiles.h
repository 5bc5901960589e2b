#pragma once
// The interaction profiles the test runtime knows, with every binding path each one has and the
// kind of value it gives, so that xrSuggestInteractionProfileBindings can reject a path a real
// runtime would reject.
#include <string>

namespace fgxrt {

enum class ComponentKind { None, Boolean, Float, Vector2, Pose, Haptic };

bool known_profile(const std::string& profile);
// The kind of `path` in `profile`, or None when the profile has no such path.
ComponentKind component_kind(const std::string& profile, const std::string& path);

}  // namespace fgxrt
