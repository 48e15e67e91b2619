// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/mesh/io/gltf_accessor.h>

#include <tiny_gltf.h>

namespace seamless {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& field,
                       const std::string& message) {
    throw InputError(file, field, message);
}

// a + b, or fail when it overflows size_t.
size_t add(size_t a, size_t b, const std::string& file, const std::string& field) {
    size_t r;
    if (__builtin_add_overflow(a, b, &r)) fail(file, field, "byte offsets overflow");
    return r;
}
size_t mul(size_t a, size_t b, const std::string& file, const std::string& field) {
    size_t r;
    if (__builtin_mul_overflow(a, b, &r)) fail(file, field, "byte offsets overflow");
    return r;
}

} // namespace

AccessorView view_of(const tinygltf::Model& model, int index, size_t elem, const std::string& file,
                     const std::string& field) {
    if (index < 0 || index >= static_cast<int>(model.accessors.size()))
        fail(file, field, "accessor index " + std::to_string(index) + " out of range");
    const auto& a = model.accessors[index];
    if (a.sparse.isSparse) fail(file, field, "sparse accessors are not supported");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size()))
        fail(file, field, "accessor has no valid bufferView");
    const auto& v = model.bufferViews[a.bufferView];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(model.buffers.size()))
        fail(file, field, "bufferView has no valid buffer");
    const auto& b = model.buffers[v.buffer];
    // Every sum and product below is checked: offsets near 2^64 must not wrap.
    const size_t view_end = add(v.byteOffset, v.byteLength, file, field);
    if (view_end > b.data.size()) fail(file, field, "bufferView exceeds its buffer");
    AccessorView r;
    r.stride = v.byteStride ? v.byteStride : elem;
    if (r.stride < elem) fail(file, field, "byteStride smaller than an element");
    r.count = a.count;
    const size_t start = add(v.byteOffset, a.byteOffset, file, field);
    // Also for an empty accessor: base must point into the buffer.
    if (start > view_end) fail(file, field, "accessor byteOffset exceeds its bufferView");
    if (a.count > 0) {
        const size_t last = add(mul(a.count - 1, r.stride, file, field), elem, file, field);
        if (add(start, last, file, field) > view_end)
            fail(file, field,
                 "accessor of " + std::to_string(a.count) + " elements exceeds its bufferView");
    }
    r.base = b.data.data() + start;
    return r;
}

} // namespace seamless
