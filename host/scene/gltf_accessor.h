// Reading glTF accessors: the one place where buffer bytes become numbers. Offsets,
// strides and counts all come from the file, so every accessor is checked against its
// bufferView and buffer here, before any of its elements is read; sparse accessors and
// accessors without a bufferView (zeros) are read too.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
} // namespace tinygltf

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
    void apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& acc, std::size_t element);

    std::string what_, source_;
    // The elements: in the buffer (data_), or made here (owned_, data_ null) when the
    // accessor has no bufferView (zeros) or is sparse (the dense ones with the listed
    // ones replaced).
    const unsigned char* data_ = nullptr;
    std::vector<unsigned char> owned_;
    std::size_t count_ = 0, stride_ = 0;
    int components_ = 0, component_size_ = 0, component_type_ = 0;
    bool normalized_ = false;
};

} // namespace pathcl
