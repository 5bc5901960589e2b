#include "reflection.h"

#include <algorithm>
#include <fmt/format.h>
#include <spirv_cross/spirv_cross_c.h>

namespace fg {

namespace {

struct ContextGuard {
    spvc_context ctx = nullptr;
    ~ContextGuard() {
        if (ctx) spvc_context_destroy(ctx);
    }
};

// From the qualifiers: readonly images and buffers are NonWritable, writeonly ones NonReadable
// (on the variable for images, on the block's members for buffers).
std::string binding_access(spvc_compiler compiler, spvc_variable_id id, spvc_resource_type type) {
    if (type == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER || type == SPVC_RESOURCE_TYPE_SAMPLED_IMAGE) return "read";
    bool no_write = spvc_compiler_has_decoration(compiler, id, SpvDecorationNonWritable);
    bool no_read = spvc_compiler_has_decoration(compiler, id, SpvDecorationNonReadable);
    if (type == SPVC_RESOURCE_TYPE_STORAGE_BUFFER) {
        const SpvDecoration* decorations = nullptr;
        size_t count = 0;
        spvc_compiler_get_buffer_block_decorations(compiler, id, &decorations, &count);
        for (size_t i = 0; i < count; ++i) {
            no_write = no_write || decorations[i] == SpvDecorationNonWritable;
            no_read = no_read || decorations[i] == SpvDecorationNonReadable;
        }
    }
    return no_write ? "read" : no_read ? "write" : "read_write";
}

// A storage image's declared format, named as the runtime's frame graph names its images.
std::string image_format(spvc_compiler compiler, spvc_type_id type_id) {
    switch (spvc_type_get_image_storage_format(spvc_compiler_get_type_handle(compiler, type_id))) {
        case SpvImageFormatR32f: return "r32f";
        case SpvImageFormatRg32f: return "rg32f";
        case SpvImageFormatRgba16f: return "rgba16f";
        case SpvImageFormatRgba32f: return "rgba32f";
        case SpvImageFormatRgba8: return "rgba8";
        case SpvImageFormatRgba32ui: return "rgba32ui";
        default: return "other";
    }
}

}  // namespace

std::optional<PassReflection> reflect_spirv(const std::string& pass, const std::vector<std::uint32_t>& words,
                                            Diagnostics& diag) {
    ContextGuard guard;
    if (spvc_context_create(&guard.ctx) != SPVC_SUCCESS) {
        diag.error("SPIRV-Cross: cannot create a context");
        return std::nullopt;
    }
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    spvc_resources resources = nullptr;
    if (spvc_context_parse_spirv(guard.ctx, words.data(), words.size(), &ir) != SPVC_SUCCESS ||
        spvc_context_create_compiler(guard.ctx, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) !=
            SPVC_SUCCESS ||
        spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS) {
        diag.error(fmt::format("SPIRV-Cross cannot reflect pass {}: {}", pass, spvc_context_get_last_error_string(guard.ctx)));
        return std::nullopt;
    }
    PassReflection r;
    for (unsigned i = 0; i < 3; ++i)
        r.local_size[i] = spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, i);

    struct Kind {
        spvc_resource_type type;
        const char* name;
    };
    const Kind kinds[] = {{SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "uniform_buffer"},
                          {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, "storage_buffer"},
                          {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, "storage_image"},
                          {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, "sampled_image"}};
    for (const auto& kind : kinds) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, kind.type, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            ManifestBinding b;
            b.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
            b.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
            b.kind = kind.name;
            b.name = list[i].name;
            b.access = binding_access(compiler, list[i].id, kind.type);
            if (kind.type == SPVC_RESOURCE_TYPE_STORAGE_IMAGE) b.format = image_format(compiler, list[i].type_id);
            if (kind.type == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER) {
                spvc_type type = spvc_compiler_get_type_handle(compiler, list[i].base_type_id);
                BlockLayout layout;
                size_t size = 0;
                spvc_compiler_get_declared_struct_size(compiler, type, &size);
                layout.size = static_cast<std::uint32_t>(size);
                for (unsigned m = 0; m < spvc_type_get_num_member_types(type); ++m) {
                    unsigned offset = 0;
                    spvc_compiler_type_struct_member_offset(compiler, type, m, &offset);
                    const char* member = spvc_compiler_get_member_name(compiler, list[i].base_type_id, m);
                    layout.offsets[member ? member : fmt::format("_{}", m)] = offset;
                }
                // The block's type name (FgParams) is what code generation declared.
                const char* type_name = spvc_compiler_get_name(compiler, list[i].base_type_id);
                r.uniform_blocks[type_name && *type_name ? type_name : b.name] = layout;
            }
            r.bindings.push_back(b);
        }
    }
    std::sort(r.bindings.begin(), r.bindings.end(),
              [](const auto& a, const auto& b) { return std::tie(a.set, a.binding) < std::tie(b.set, b.binding); });
    {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            size_t size = 0;
            spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, list[i].base_type_id),
                                                   &size);
            r.push_constant_size = std::max(r.push_constant_size, static_cast<std::uint32_t>(size));
        }
    }
    const spvc_specialization_constant* consts = nullptr;
    size_t count = 0;
    spvc_compiler_get_specialization_constants(compiler, &consts, &count);
    for (size_t i = 0; i < count; ++i) r.spec_constants.push_back(consts[i].constant_id);
    std::sort(r.spec_constants.begin(), r.spec_constants.end());
    return r;
}

}  // namespace fg
