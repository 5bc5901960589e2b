// Preloaded into every process of the sanitizer test run (scripts/fractograph.sh test).
// LeakSanitizer looks for leaks at exit, but the Vulkan and OpenXR loaders unload their layers and
// drivers before that. Memory that lavapipe keeps for the process's lifetime is then reachable from
// no loaded library and reads as leaked, and the validation layers' own leftovers come from a
// library that is gone, so tests/sanitizers/lsan.supp cannot suppress them by name. Opening each
// of them once more here, never to be unloaded, keeps them mapped and named. RTLD_LOCAL: their
// symbols (vkGetInstanceProcAddr) must not shadow the loaders'. A library that is absent is skipped.
#include <dlfcn.h>

__attribute__((constructor)) static void keep_layers_loaded(void) {
    static const char* const libraries[] = {
        "libvulkan_lvp.so",
        "libVkLayer_khronos_validation.so",
        "/usr/lib/x86_64-linux-gnu/openxr/1/api_layers/libXrApiLayer_core_validation.so",
    };
    for (unsigned i = 0; i < sizeof libraries / sizeof libraries[0]; ++i)
        dlopen(libraries[i], RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
}
