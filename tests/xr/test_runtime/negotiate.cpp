// The test runtime's entry point: negotiation with the OpenXR loader, and the function lookup
// the loader and the API layers call.
#include <cstring>

#include "loader_negotiation.h"
#include "runtime_objects.h"

namespace fgxrt {
namespace {

XRAPI_ATTR XrResult XRAPI_CALL GetInstanceProcAddr(XrInstance handle, const char* name, PFN_xrVoidFunction* function) {
    if (!name || !function) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    if (std::strcmp(name, "xrGetInstanceProcAddr") == 0) {
        *function = reinterpret_cast<PFN_xrVoidFunction>(&GetInstanceProcAddr);
        return XR_SUCCESS;
    }
    // Without an instance only the calls that create one may be looked up.
    if (handle == XR_NULL_HANDLE && std::strcmp(name, "xrCreateInstance") != 0 &&
        std::strcmp(name, "xrEnumerateInstanceExtensionProperties") != 0 &&
        std::strcmp(name, "xrEnumerateApiLayerProperties") != 0)
        return XR_ERROR_HANDLE_INVALID;
    for (const auto* table : {&kInstanceFunctions, &kSessionFunctions, &kActionFunctions})
        for (const auto& f : *table)
            if (std::strcmp(f.name, name) == 0) {
                *function = f.function;
                return XR_SUCCESS;
            }
    return XR_ERROR_FUNCTION_UNSUPPORTED;
}

}  // namespace
}  // namespace fgxrt

extern "C" __attribute__((visibility("default"))) XRAPI_ATTR XrResult XRAPI_CALL
xrNegotiateLoaderRuntimeInterface(const XrNegotiateLoaderInfo* info, XrNegotiateRuntimeRequest* request) {
    if (!info || !request || info->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
        info->structVersion != XR_LOADER_INFO_STRUCT_VERSION || info->structSize != sizeof(XrNegotiateLoaderInfo) ||
        request->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
        request->structVersion != XR_RUNTIME_INFO_STRUCT_VERSION || request->structSize != sizeof(XrNegotiateRuntimeRequest))
        return XR_ERROR_INITIALIZATION_FAILED;
    if (info->minInterfaceVersion > XR_CURRENT_LOADER_RUNTIME_VERSION ||
        info->maxInterfaceVersion < XR_CURRENT_LOADER_RUNTIME_VERSION)
        return XR_ERROR_INITIALIZATION_FAILED;
    if (XR_VERSION_MAJOR(info->minApiVersion) > 1 || XR_VERSION_MAJOR(info->maxApiVersion) < 1)
        return XR_ERROR_INITIALIZATION_FAILED;
    request->runtimeInterfaceVersion = XR_CURRENT_LOADER_RUNTIME_VERSION;
    request->runtimeApiVersion = XR_CURRENT_API_VERSION;
    request->getInstanceProcAddr = &fgxrt::GetInstanceProcAddr;
    return XR_SUCCESS;
}
