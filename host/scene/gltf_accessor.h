// Reading glTF accessors: the one place where buffer bytes become numbers. Offsets,
// strides and counts all come from the file, so every accessor is checked against its
// bufferView and buffer here, before any of its elements is read.
#pragma once

#include <cstddef>
#include <string>

namespace tinygltf {
class Model;
}

namespace pathcl {

// Reads accessor elements as doubles, honouring stride, component type and normalization,
// after checking that every element lies inside its buffer.
class AccessorReader {
public:
    // `what` names the accessor's use in errors ("node 3 mesh 0 primitive 1 POSITION");
    // `source` names the file.
    AccessorReader(const tinygltf::Model& model, int index, const std::string& what, const std::string& source);

    std::size_t count() const { return count_; }
    int components() const { return components_; }

    // Component `c` of element `i`, normalized integers mapped to [0, 1] or [-1, 1].
    double get(std::size_t i, int c) const;

    // Attributes that are fractions (texture coordinates, colours) stored as integers
    // must be normalized.
    void require_float_or_normalized() const;

    // Stored as 32-bit floats.
    bool is_float() const;

    // Unsigned, not normalized scalars: what glTF allows for indices.
    bool is_index_type() const;

    // Throws pathcl::Error("SOURCE: WHAT (accessor N): msg").
    [[noreturn]] void fail(const std::string& msg) const;

private:
    std::string what_, source_;
    const unsigned char* data_ = nullptr;
    std::size_t count_ = 0, stride_ = 0;
    int components_ = 0, component_size_ = 0, component_type_ = 0;
    bool normalized_ = false;
};

} // namespace pathcl
