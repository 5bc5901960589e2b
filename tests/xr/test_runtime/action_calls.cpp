// The test runtime's input calls: paths, action sets and actions, suggested bindings checked
// against the interaction profiles, attaching, syncing scripted controller input, action states,
// action spaces and xrLocateSpace, and the current interaction profile.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "interaction_profiles.h"
#include "runtime_objects.h"

namespace fgxrt {

namespace {

// --- poses ---------------------------------------------------------------------------------

XrQuaternionf q_mul(const XrQuaternionf& a, const XrQuaternionf& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
XrQuaternionf q_conj(const XrQuaternionf& q) { return {-q.x, -q.y, -q.z, q.w}; }
XrVector3f q_rot(const XrQuaternionf& q, const XrVector3f& v) {
    XrQuaternionf r = q_mul(q_mul(q, {v.x, v.y, v.z, 0.0f}), q_conj(q));
    return {r.x, r.y, r.z};
}
// a then b: the pose b given in a's frame.
XrPosef compose(const XrPosef& a, const XrPosef& b) {
    XrVector3f p = q_rot(a.orientation, b.position);
    return {q_mul(a.orientation, b.orientation), {a.position.x + p.x, a.position.y + p.y, a.position.z + p.z}};
}
XrPosef inverse(const XrPosef& a) {
    XrQuaternionf c = q_conj(a.orientation);
    XrVector3f p = q_rot(c, a.position);
    return {c, {-p.x, -p.y, -p.z}};
}

// --- names and paths -----------------------------------------------------------------------

bool well_formed_name(const char* name, std::size_t size) {
    std::size_t n = strnlen(name, size);
    if (n == 0 || n == size) return false;
    for (std::size_t i = 0; i < n; ++i) {
        char c = name[i];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.')) return false;
    }
    return true;
}

bool well_formed_path(const char* text) {
    std::size_t n = strnlen(text, XR_MAX_PATH_LENGTH);
    if (n == 0 || n == XR_MAX_PATH_LENGTH || text[0] != '/' || text[n - 1] == '/') return false;
    for (std::size_t i = 0; i < n; ++i) {
        char c = text[i];
        if (c == '/' && i + 1 < n && text[i + 1] == '/') return false;
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.' || c == '/')) return false;
    }
    return true;
}

bool top_level_user_path(const std::string& p) {
    return p == "/user/hand/left" || p == "/user/hand/right" || p == "/user/head" || p == "/user/gamepad";
}

bool kinds_fit(XrActionType type, ComponentKind kind) {
    switch (type) {
        case XR_ACTION_TYPE_BOOLEAN_INPUT:
        case XR_ACTION_TYPE_FLOAT_INPUT: return kind == ComponentKind::Boolean || kind == ComponentKind::Float;
        case XR_ACTION_TYPE_VECTOR2F_INPUT: return kind == ComponentKind::Vector2;
        case XR_ACTION_TYPE_POSE_INPUT: return kind == ComponentKind::Pose;
        case XR_ACTION_TYPE_VIBRATION_OUTPUT: return kind == ComponentKind::Haptic;
        default: return false;
    }
}

// Whether `binding` lies under `subaction` (XR_NULL_PATH: any).
bool under(XrPath binding, XrPath subaction) {
    if (subaction == XR_NULL_PATH) return true;
    const std::string* b = path_string(binding);
    const std::string* s = path_string(subaction);
    return b && s && b->rfind(*s + "/", 0) == 0;
}

// --- calls ---------------------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL StringToPath(XrInstance handle, const char* text, XrPath* out) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (!text || !well_formed_path(text)) return XR_ERROR_PATH_FORMAT_INVALID;
    *out = intern_path(text);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL PathToString(XrInstance handle, XrPath path, std::uint32_t capacity, std::uint32_t* count,
                                            char* buffer) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    const std::string* s = path_string(path);
    if (!s) return XR_ERROR_PATH_INVALID;
    *count = static_cast<std::uint32_t>(s->size() + 1);
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < *count) return XR_ERROR_SIZE_INSUFFICIENT;
    std::memcpy(buffer, s->c_str(), *count);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateActionSet(XrInstance handle, const XrActionSetCreateInfo* info, XrActionSet* out) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (!well_formed_name(info->actionSetName, XR_MAX_ACTION_SET_NAME_SIZE)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (strnlen(info->localizedActionSetName, XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE) == 0)
        return XR_ERROR_LOCALIZED_NAME_INVALID;
    for (const auto& set : inst->action_sets) {
        if (set->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
        if (set->localized == info->localizedActionSetName) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto set = std::make_unique<ActionSet>();
    set->name = info->actionSetName;
    set->localized = info->localizedActionSetName;
    set->priority = info->priority;
    *out = reinterpret_cast<XrActionSet>(set.get());
    inst->action_sets.push_back(std::move(set));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyActionSet(XrActionSet handle) {
    ActionSet* set = action_set(handle);
    if (!set) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = live_instance();
    for (auto& [profile, bindings] : inst->suggested)
        std::erase_if(bindings, [set](const auto& b) { return b.first->set == set; });
    for (auto& sp : inst->spaces)
        if (sp->action && sp->action->set == set) sp->action = nullptr;   // the space lives on, unlocatable
    for (auto& s : inst->sessions) std::erase(s->attached_sets, set);
    std::erase_if(inst->action_sets, [set](const auto& p) { return p.get() == set; });
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateAction(XrActionSet handle, const XrActionCreateInfo* info, XrAction* out) {
    ActionSet* set = action_set(handle);
    if (!set) return XR_ERROR_HANDLE_INVALID;
    if (set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (!well_formed_name(info->actionName, XR_MAX_ACTION_NAME_SIZE)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (strnlen(info->localizedActionName, XR_MAX_LOCALIZED_ACTION_NAME_SIZE) == 0) return XR_ERROR_LOCALIZED_NAME_INVALID;
    switch (info->actionType) {
        case XR_ACTION_TYPE_BOOLEAN_INPUT:
        case XR_ACTION_TYPE_FLOAT_INPUT:
        case XR_ACTION_TYPE_VECTOR2F_INPUT:
        case XR_ACTION_TYPE_POSE_INPUT:
        case XR_ACTION_TYPE_VIBRATION_OUTPUT: break;
        default: return XR_ERROR_VALIDATION_FAILURE;
    }
    for (const auto& a : set->actions) {
        if (a->name == info->actionName) return XR_ERROR_NAME_DUPLICATED;
        if (a->localized == info->localizedActionName) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto a = std::make_unique<Action>();
    a->set = set;
    a->name = info->actionName;
    a->localized = info->localizedActionName;
    a->type = info->actionType;
    for (std::uint32_t i = 0; i < info->countSubactionPaths; ++i) {
        const std::string* p = path_string(info->subactionPaths[i]);
        if (!p) return XR_ERROR_PATH_INVALID;
        if (!top_level_user_path(*p)) return XR_ERROR_PATH_UNSUPPORTED;
        if (std::find(a->subactions.begin(), a->subactions.end(), info->subactionPaths[i]) != a->subactions.end())
            return XR_ERROR_PATH_UNSUPPORTED;
        a->subactions.push_back(info->subactionPaths[i]);
    }
    *out = reinterpret_cast<XrAction>(a.get());
    set->actions.push_back(std::move(a));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyAction(XrAction handle) {
    Action* a = action(handle);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = live_instance();
    for (auto& [profile, bindings] : inst->suggested) std::erase_if(bindings, [a](const auto& b) { return b.first == a; });
    for (auto& sp : inst->spaces)
        if (sp->action == a) sp->action = nullptr;
    std::erase_if(a->set->actions, [a](const auto& p) { return p.get() == a; });
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL SuggestInteractionProfileBindings(XrInstance handle,
                                                                 const XrInteractionProfileSuggestedBinding* info) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    const std::string* profile = path_string(info->interactionProfile);
    if (!profile) return XR_ERROR_PATH_INVALID;
    if (!known_profile(*profile)) return XR_ERROR_PATH_UNSUPPORTED;
    if (info->countSuggestedBindings == 0 || !info->suggestedBindings) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<std::pair<Action*, XrPath>> bindings;
    for (std::uint32_t i = 0; i < info->countSuggestedBindings; ++i) {
        const XrActionSuggestedBinding& b = info->suggestedBindings[i];
        Action* a = action(b.action);
        if (!a) return XR_ERROR_HANDLE_INVALID;
        if (a->set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
        const std::string* path = path_string(b.binding);
        if (!path) return XR_ERROR_PATH_INVALID;
        ComponentKind kind = component_kind(*profile, *path);
        if (kind == ComponentKind::None || !kinds_fit(a->type, kind)) {
            inst->report.fail(0, "xrSuggestInteractionProfileBindings: " + *profile + " has no " + *path + " for action \"" +
                                     a->name + "\"");
            return XR_ERROR_PATH_UNSUPPORTED;
        }
        // The binding must fit one of the action's subaction paths, when it has them.
        bool fits = a->subactions.empty();
        for (XrPath s : a->subactions) fits = fits || under(b.binding, s);
        if (!fits) return XR_ERROR_PATH_UNSUPPORTED;
        bindings.emplace_back(a, b.binding);
    }
    inst->suggested[info->interactionProfile] = std::move(bindings);   // replaces an earlier suggestion
    inst->report.suggested_profiles.push_back(*profile);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL AttachSessionActionSets(XrSession handle, const XrSessionActionSetsAttachInfo* info) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (s->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (info->countActionSets == 0) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<ActionSet*> sets;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i) {
        ActionSet* set = action_set(info->actionSets[i]);
        if (!set) return XR_ERROR_HANDLE_INVALID;
        sets.push_back(set);
    }
    for (ActionSet* set : sets) set->attached = true;
    s->attached = true;
    s->attached_sets = sets;
    // The "headset" has the scripted controllers; a profile fgplay suggested nothing for falls back
    // to khr/simple_controller, which every runtime can map, as real runtimes do.
    Instance* inst = live_instance();
    XrPath profile = intern_path(inst->input.profile());
    XrPath simple = intern_path("/interaction_profiles/khr/simple_controller");
    if (inst->suggested.count(profile)) s->profile = profile;
    else if (inst->suggested.count(simple)) s->profile = simple;
    inst->report.interaction_profile = s->profile ? *path_string(s->profile) : "none";
    if (s->profile) {
        XrEventDataBuffer buffer{XR_TYPE_EVENT_DATA_BUFFER};
        auto& e = reinterpret_cast<XrEventDataInteractionProfileChanged&>(buffer);
        e.type = XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED;
        e.next = nullptr;
        e.session = handle;
        inst->events.push_back(buffer);
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL SyncActions(XrSession handle, const XrActionsSyncInfo* info) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (s->lost) return XR_ERROR_SESSION_LOST;
    Instance* inst = live_instance();
    std::vector<ActionSet*> active;
    for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i) {
        ActionSet* set = action_set(info->activeActionSets[i].actionSet);
        if (!set) return XR_ERROR_HANDLE_INVALID;
        if (std::find(s->attached_sets.begin(), s->attached_sets.end(), set) == s->attached_sets.end())
            return XR_ERROR_ACTIONSET_NOT_ATTACHED;
        XrPath sub = info->activeActionSets[i].subactionPath;
        if (sub != XR_NULL_PATH && (!path_string(sub) || !top_level_user_path(*path_string(sub))))
            return XR_ERROR_PATH_UNSUPPORTED;
        active.push_back(set);
    }
    const bool focused = s->state == XR_SESSION_STATE_FOCUSED;
    // Input is sampled at the display time of the frame fgplay is rendering.
    const XrTime when = s->waited_display_time ? s->waited_display_time : inst->clock;
    const double t = session_seconds(*s, when);
    ++inst->report.actions_synced;
    for (ActionSet* set : s->attached_sets) {
        const bool on = focused && std::find(active.begin(), active.end(), set) != active.end();
        for (auto& a : set->actions) {
            float old_x = a->x, old_y = a->y;
            bool was_active = a->active;
            a->bound.clear();
            a->active = false;
            a->x = a->y = 0.0f;
            if (on && s->profile)
                for (const auto& [bound_action, binding] : inst->suggested[s->profile])
                    if (bound_action == a.get())
                        a->bound.emplace_back(binding, inst->input.value(*path_string(binding), t));
            a->active = !a->bound.empty();
            for (const auto& [binding, v] : a->bound) {
                // Several bindings: the largest magnitude wins, as the spec asks.
                if (std::hypot(v.x, v.y) > std::hypot(a->x, a->y)) {
                    a->x = v.x;
                    a->y = v.y;
                }
            }
            if (a->type == XR_ACTION_TYPE_BOOLEAN_INPUT) a->x = a->x >= 0.5f ? 1.0f : 0.0f;
            a->changed = was_active && a->active && (a->x != old_x || a->y != old_y);
            if (a->changed) a->last_change = when;
        }
    }
    s->synced_time = when;
    s->synced_focused = focused;
    return focused ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
}

// The action and its state for `info`, filtered by the subaction path; an error result otherwise.
XrResult state_of(XrSession handle, const XrActionStateGetInfo* info, XrActionType type, float& x, float& y, bool& active,
                  bool& changed, XrTime& last_change) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Action* a = action(info->action);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (std::find(s->attached_sets.begin(), s->attached_sets.end(), a->set) == s->attached_sets.end())
        return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (a->type != type) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(a->subactions.begin(), a->subactions.end(), info->subactionPath) == a->subactions.end())
        return XR_ERROR_PATH_UNSUPPORTED;
    x = y = 0.0f;
    active = false;
    for (const auto& [binding, v] : a->bound) {
        if (!under(binding, info->subactionPath)) continue;
        active = true;
        if (std::hypot(v.x, v.y) > std::hypot(x, y)) {
            x = v.x;
            y = v.y;
        }
    }
    if (a->type == XR_ACTION_TYPE_BOOLEAN_INPUT) x = x >= 0.5f ? 1.0f : 0.0f;
    changed = active && a->changed;
    last_change = active ? a->last_change : 0;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetActionStateBoolean(XrSession handle, const XrActionStateGetInfo* info,
                                                     XrActionStateBoolean* state) {
    float x, y;
    bool active, changed;
    XrTime last;
    XrResult r = state_of(handle, info, XR_ACTION_TYPE_BOOLEAN_INPUT, x, y, active, changed, last);
    if (XR_FAILED(r)) return r;
    state->currentState = x >= 0.5f ? XR_TRUE : XR_FALSE;
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->changedSinceLastSync = changed ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = last;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetActionStateFloat(XrSession handle, const XrActionStateGetInfo* info,
                                                   XrActionStateFloat* state) {
    float x, y;
    bool active, changed;
    XrTime last;
    XrResult r = state_of(handle, info, XR_ACTION_TYPE_FLOAT_INPUT, x, y, active, changed, last);
    if (XR_FAILED(r)) return r;
    state->currentState = x;
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->changedSinceLastSync = changed ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = last;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetActionStateVector2f(XrSession handle, const XrActionStateGetInfo* info,
                                                      XrActionStateVector2f* state) {
    float x, y;
    bool active, changed;
    XrTime last;
    XrResult r = state_of(handle, info, XR_ACTION_TYPE_VECTOR2F_INPUT, x, y, active, changed, last);
    if (XR_FAILED(r)) return r;
    state->currentState = {x, y};
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->changedSinceLastSync = changed ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = last;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetActionStatePose(XrSession handle, const XrActionStateGetInfo* info,
                                                  XrActionStatePose* state) {
    float x, y;
    bool active, changed;
    XrTime last;
    XrResult r = state_of(handle, info, XR_ACTION_TYPE_POSE_INPUT, x, y, active, changed, last);
    if (XR_FAILED(r)) return r;
    state->isActive = active ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateActionSpace(XrSession handle, const XrActionSpaceCreateInfo* info, XrSpace* out) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Action* a = action(info->action);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (a->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(a->subactions.begin(), a->subactions.end(), info->subactionPath) == a->subactions.end())
        return XR_ERROR_PATH_UNSUPPORTED;
    auto sp = std::make_unique<Space>();
    sp->session = s;
    sp->action = a;
    sp->subaction = info->subactionPath;
    sp->pose = info->poseInActionSpace;
    *out = reinterpret_cast<XrSpace>(sp.get());
    live_instance()->spaces.push_back(std::move(sp));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL LocateSpace(XrSpace space_handle, XrSpace base_handle, XrTime time, XrSpaceLocation* location) {
    Space* sp = space(space_handle);
    Space* base = space(base_handle);
    if (!sp || !base) return XR_ERROR_HANDLE_INVALID;
    if (sp->session != base->session) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    return locate(*sp->session, *sp, *base, time, location);
}

XRAPI_ATTR XrResult XRAPI_CALL GetCurrentInteractionProfile(XrSession handle, XrPath top_level,
                                                            XrInteractionProfileState* state) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    const std::string* p = path_string(top_level);
    if (!p) return XR_ERROR_PATH_INVALID;
    if (!top_level_user_path(*p)) return XR_ERROR_PATH_UNSUPPORTED;
    const bool hand = *p == "/user/hand/left" || *p == "/user/hand/right";
    state->interactionProfile = hand ? s->profile : XR_NULL_PATH;
    return XR_SUCCESS;
}

#define FG_FN(name) {"xr" #name, reinterpret_cast<PFN_xrVoidFunction>(&name)}

}  // namespace

const std::string* path_string(XrPath path) {
    Instance* inst = live_instance();
    if (!inst || path == XR_NULL_PATH || path > inst->paths.size()) return nullptr;
    return &inst->paths[path - 1];
}

XrPath intern_path(const std::string& text) {
    Instance* inst = live_instance();
    auto it = std::find(inst->paths.begin(), inst->paths.end(), text);
    if (it == inst->paths.end()) it = inst->paths.insert(inst->paths.end(), text);
    return static_cast<XrPath>(it - inst->paths.begin()) + 1;
}

ActionSet* action_set(XrActionSet handle) {
    Instance* inst = live_instance();
    if (!inst) return nullptr;
    for (auto& s : inst->action_sets)
        if (reinterpret_cast<XrActionSet>(s.get()) == handle) return s.get();
    return nullptr;
}

Action* action(XrAction handle) {
    Instance* inst = live_instance();
    if (!inst) return nullptr;
    for (auto& s : inst->action_sets)
        for (auto& a : s->actions)
            if (reinterpret_cast<XrAction>(a.get()) == handle) return a.get();
    return nullptr;
}

XrResult locate(Session& s, Space& space, Space& base, XrTime time, XrSpaceLocation* location) {
    Instance* inst = live_instance();
    const double t = session_seconds(s, time);
    const XrPosef head = inst->poses.head(t);
    // Each space's pose in LOCAL; false when it cannot be located now.
    auto in_local = [&](const Space& sp, XrPosef& out) {
        if (sp.action) {
            const Action& a = *sp.action;
            int hand = -1;
            for (const auto& [binding, v] : a.bound) {
                if (!under(binding, sp.subaction)) continue;
                const std::string& b = *path_string(binding);
                hand = b.rfind("/user/hand/left/", 0) == 0 ? 0 : 1;
                break;
            }
            if (hand < 0 || !a.active) return false;   // not bound, or not active at the last sync
            out = compose(inst->input.aim(hand, t, head), sp.pose);
            return true;
        }
        if (sp.type == XR_REFERENCE_SPACE_TYPE_VIEW) out = compose(head, sp.pose);
        else out = sp.pose;   // LOCAL and STAGE coincide here
        return true;
    };
    XrPosef a, b;
    location->locationFlags = 0;
    if (!in_local(space, a) || !in_local(base, b)) {
        location->pose = {{0, 0, 0, 1}, {0, 0, 0}};
        return XR_SUCCESS;
    }
    location->pose = compose(inverse(b), a);
    location->locationFlags = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                              XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
    return XR_SUCCESS;
}

const std::vector<NamedFunction> kActionFunctions = {
    FG_FN(StringToPath),
    FG_FN(PathToString),
    FG_FN(CreateActionSet),
    FG_FN(DestroyActionSet),
    FG_FN(CreateAction),
    FG_FN(DestroyAction),
    FG_FN(SuggestInteractionProfileBindings),
    FG_FN(AttachSessionActionSets),
    FG_FN(SyncActions),
    FG_FN(GetActionStateBoolean),
    FG_FN(GetActionStateFloat),
    FG_FN(GetActionStateVector2f),
    FG_FN(GetActionStatePose),
    FG_FN(CreateActionSpace),
    FG_FN(LocateSpace),
    FG_FN(GetCurrentInteractionProfile),
};

}  // namespace fgxrt
