#include "xr/xr_error.h"

#include <fmt/format.h>
#include <openxr/openxr_reflection.h>

namespace fg::xr {

const char* result_name(XrResult result) {
    switch (result) {
#define FG_XR_RESULT_CASE(name, value) \
    case name: return #name;
        XR_LIST_ENUM_XrResult(FG_XR_RESULT_CASE)
#undef FG_XR_RESULT_CASE
        default: return "an unknown XrResult";
    }
}

XrResult check(XrResult result, const char* call) {
    if (XR_FAILED(result)) throw XrError(result, fmt::format("{} failed: {}", call, result_name(result)));
    return result;
}

}  // namespace fg::xr
