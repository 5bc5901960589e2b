#pragma once
// The runtime side of the OpenXR loader's negotiation (the loader's "runtime interface", version
// 1). Debian's libopenxr-dev 1.0.20 ships no openxr_loader_negotiation.h, so the structures are
// declared here as the loader documents them (OpenXR loader design document, "Runtime
// Interface Negotiation").
#include <cstddef>
#include <cstdint>

#include <openxr/openxr.h>

extern "C" {

typedef enum XrLoaderInterfaceStructs {
    XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
    XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST,
    XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO,
    XR_LOADER_INTERFACE_STRUCTS_MAX_ENUM = 0x7FFFFFFF
} XrLoaderInterfaceStructs;

#define XR_CURRENT_LOADER_RUNTIME_VERSION 1
#define XR_LOADER_INFO_STRUCT_VERSION 1
#define XR_RUNTIME_INFO_STRUCT_VERSION 1

typedef struct XrNegotiateLoaderInfo {
    XrLoaderInterfaceStructs structType;   // XR_LOADER_INTERFACE_STRUCT_LOADER_INFO
    uint32_t structVersion;                // XR_LOADER_INFO_STRUCT_VERSION
    size_t structSize;                     // sizeof(XrNegotiateLoaderInfo)
    uint32_t minInterfaceVersion;
    uint32_t maxInterfaceVersion;
    XrVersion minApiVersion;
    XrVersion maxApiVersion;
} XrNegotiateLoaderInfo;

typedef struct XrNegotiateRuntimeRequest {
    XrLoaderInterfaceStructs structType;   // XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST
    uint32_t structVersion;                // XR_RUNTIME_INFO_STRUCT_VERSION
    size_t structSize;                     // sizeof(XrNegotiateRuntimeRequest)
    uint32_t runtimeInterfaceVersion;      // XR_CURRENT_LOADER_RUNTIME_VERSION
    XrVersion runtimeApiVersion;
    PFN_xrGetInstanceProcAddr getInstanceProcAddr;
} XrNegotiateRuntimeRequest;

// The one symbol a runtime library exports.
XRAPI_ATTR XrResult XRAPI_CALL xrNegotiateLoaderRuntimeInterface(const XrNegotiateLoaderInfo* loaderInfo,
                                                                 XrNegotiateRuntimeRequest* runtimeRequest);
}
