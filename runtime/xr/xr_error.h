#pragma once
// OpenXR results as exceptions that carry the call and the result's name.
#include <stdexcept>
#include <string>

#include <openxr/openxr.h>

namespace fg::xr {

class XrError : public std::runtime_error {
public:
    XrError(XrResult result, const std::string& what) : std::runtime_error(what), result_(result) {}
    XrResult result() const { return result_; }

private:
    XrResult result_;
};

// "XR_ERROR_RUNTIME_UNAVAILABLE", without an instance (xrResultToString needs one).
const char* result_name(XrResult result);

// Throws XrError for a failed call; returns the result otherwise (XR_SESSION_LOSS_PENDING, ...).
XrResult check(XrResult result, const char* call);

}  // namespace fg::xr
