// SPDX-License-Identifier: MIT
// The bytes of a glTF accessor, every element checked to lie inside its
// bufferView and buffer before it is read (gltf_read.cpp). Internal to
// lib/mesh/io.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>

namespace tinygltf {
class Model;
}

namespace seamless {

// Elements of one accessor: element i starts at base + i * stride and has
// `elem` bytes, every one of them inside the accessor's bufferView and buffer.
struct AccessorView {
    const unsigned char* base = nullptr;
    size_t stride = 0, count = 0;
    const unsigned char* operator[](size_t i) const { return base + i * stride; }
};

// Accessor `index` of `model` with elements of `elem` bytes; throws InputError
// naming `file` and `field` when any byte of it lies outside its buffer, or it
// is sparse or has no valid bufferView or buffer.
AccessorView view_of(const tinygltf::Model& model, int index, size_t elem, const std::string& file,
                     const std::string& field);

inline float read_float(const unsigned char* p) {
    float f;
    std::memcpy(&f, p, 4);
    return f;
}

} // namespace seamless
