// AccessorReader: the bounds checks of an accessor against its view and buffer, sparse
// substitution, and the decoding of each component type (normalized integers included) to
// double.
#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {

namespace {

// An accessor without a bufferView is zeros (glTF 3.6.2.3), made in memory: at most this
// many bytes, as its count comes from the file.
constexpr std::size_t kMaxSynthesizedBytes = std::size_t(1) << 30;

// Checks that `bytes` bytes from byteOffset `offset` of view `index` lie inside the view
// and the view inside its buffer; returns the first byte. `view_name` names the view in
// errors ("its bufferView", "its sparse indices' bufferView").
const unsigned char* view_bytes(const tinygltf::Model& model, int index, std::size_t offset, std::size_t bytes,
                                const std::string& view_name, const AccessorReader& reader)
{
    if (index < 0 || index >= static_cast<int>(model.bufferViews.size()))
        reader.fail(view_name + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(index)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size()))
        reader.fail(view_name + " has no valid buffer");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        reader.fail(view_name + " lies outside its buffer (" + std::to_string(data.size()) + " bytes)");
    if (offset > view.byteLength || bytes > view.byteLength - offset)
        reader.fail("reads past the end of " + view_name + " (" + std::to_string(bytes) + " bytes from offset " +
                    std::to_string(offset) + " in " + std::to_string(view.byteLength) + ")");
    return data.data() + view.byteOffset + offset;
}

} // namespace

AccessorReader::AccessorReader(const tinygltf::Model& model, int index, const std::string& what,
                               const std::string& source)
    : what_(what), source_(source)
{
    if (index < 0 || index >= static_cast<int>(model.accessors.size()))
        fail("accessor index " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(index)];
    what_ += " (accessor " + std::to_string(index) + ")";
    components_ = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
    component_size_ = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
    if (components_ <= 0 || component_size_ <= 0)
        fail("has an invalid type or component type");
    component_type_ = acc.componentType;
    normalized_ = acc.normalized;
    count_ = acc.count;
    const std::size_t element = static_cast<std::size_t>(components_ * component_size_);
    stride_ = element;
    if (acc.bufferView < 0) {
        if (count_ > kMaxSynthesizedBytes / element)
            fail("has no bufferView and " + std::to_string(count_) + " elements: more than " +
                 std::to_string(kMaxSynthesizedBytes) + " bytes of zeros to make");
        owned_.assign(count_ * element, 0);
    } else {
        data_ = view_bytes(model, acc.bufferView, 0, 0, "its bufferView", *this);
        const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
        stride_ = view.byteStride ? view.byteStride : element;
        // The accessor inside its view: offsets and counts come from the file, so every
        // step is checked before it can wrap.
        if (acc.byteOffset > view.byteLength)
            fail("byteOffset lies past the end of its bufferView");
        const std::size_t room = view.byteLength - acc.byteOffset; // bytes from the first element
        bool fits = count_ == 0 || (element <= room && (count_ - 1) <= (room - element) / stride_);
        if (!fits)
            fail("reads past the end of its bufferView (" + std::to_string(count_) + " elements of stride " +
                 std::to_string(stride_) + " from offset " + std::to_string(acc.byteOffset) + " in " +
                 std::to_string(view.byteLength) + " bytes)");
        data_ += acc.byteOffset;
    }
    if (acc.sparse.isSparse)
        apply_sparse(model, acc, element);
}

void AccessorReader::apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& acc, std::size_t element)
{
    // The dense elements (or the zeros) are copied, then the listed ones replaced.
    if (owned_.empty() && count_ > 0) {
        owned_.resize(count_ * element);
        for (std::size_t i = 0; i < count_; ++i)
            std::memcpy(&owned_[i * element], data_ + i * stride_, element);
    }
    data_ = nullptr;
    stride_ = element;
    const int n = acc.sparse.count;
    if (n < 1 || static_cast<std::size_t>(n) > count_)
        fail("sparse count " + std::to_string(n) + " is not between 1 and the accessor's " + std::to_string(count_) +
             " elements");
    const int index_type = acc.sparse.indices.componentType;
    const std::size_t index_size = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                   : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                   : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                          : 0;
    if (index_size == 0)
        fail("sparse indices must be unsigned byte, short or int");
    if (acc.sparse.indices.byteOffset < 0 || acc.sparse.values.byteOffset < 0)
        fail("a sparse byteOffset is negative");
    const std::size_t count = static_cast<std::size_t>(n);
    const unsigned char* indices =
        view_bytes(model, acc.sparse.indices.bufferView, static_cast<std::size_t>(acc.sparse.indices.byteOffset),
                   count * index_size, "its sparse indices' bufferView", *this);
    const unsigned char* values =
        view_bytes(model, acc.sparse.values.bufferView, static_cast<std::size_t>(acc.sparse.values.byteOffset),
                   count * element, "its sparse values' bufferView", *this);
    std::uint64_t previous = 0;
    for (std::size_t k = 0; k < count; ++k) {
        std::uint32_t i32 = 0;
        if (index_size == 1)
            i32 = indices[k];
        else if (index_size == 2) {
            std::uint16_t v;
            std::memcpy(&v, indices + k * 2, 2);
            i32 = v;
        } else
            std::memcpy(&i32, indices + k * 4, 4);
        const std::uint64_t i = i32;
        if (i >= count_ || (k > 0 && i <= previous))
            fail("sparse index " + std::to_string(i) + " (entry " + std::to_string(k) +
                 ") is not below the accessor's " + std::to_string(count_) + " elements and above the one before");
        std::memcpy(&owned_[i * element], values + k * element, element);
        previous = i;
    }
}

double AccessorReader::get(std::size_t i, int c) const
{
    const unsigned char* base = data_ != nullptr ? data_ : owned_.data();
    const unsigned char* p = base + i * stride_ + static_cast<std::size_t>(c * component_size_);
    switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized_ ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        auto v = static_cast<signed char>(*p);
        return normalized_ ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized_ ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized_ ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default:
        fail("has an unsupported component type");
    }
}

void AccessorReader::require_float_or_normalized() const
{
    if (component_type_ != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_)
        fail("integer components must be normalized");
}

bool AccessorReader::is_float() const
{
    return component_type_ == TINYGLTF_COMPONENT_TYPE_FLOAT;
}

bool AccessorReader::is_index_type() const
{
    return components_ == 1 && !normalized_ &&
           (component_type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
            component_type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
            component_type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

void AccessorReader::fail(const std::string& msg) const
{
    throw Error(source_ + ": " + what_ + ": " + msg);
}

} // namespace pathcl
