// AccessorReader: the bounds checks of an accessor against its view and buffer, and the
// decoding of each component type (normalized integers included) to double.
#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {

AccessorReader::AccessorReader(const tinygltf::Model& model, int index, const std::string& what,
                               const std::string& source)
    : what_(what), source_(source)
{
    if (index < 0 || index >= static_cast<int>(model.accessors.size()))
        fail("accessor index " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(index)];
    what_ += " (accessor " + std::to_string(index) + ")";
    if (acc.sparse.isSparse)
        fail("sparse accessors are not supported");
    if (acc.bufferView < 0 || acc.bufferView >= static_cast<int>(model.bufferViews.size()))
        fail("has no valid bufferView");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size()))
        fail("its bufferView has no valid buffer");
    const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    components_ = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
    component_size_ = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
    if (components_ <= 0 || component_size_ <= 0)
        fail("has an invalid type or component type");
    component_type_ = acc.componentType;
    normalized_ = acc.normalized;
    count_ = acc.count;
    std::size_t element = static_cast<std::size_t>(components_ * component_size_);
    stride_ = view.byteStride ? view.byteStride : element;
    // The view must lie inside its buffer and the accessor inside its view. Offsets
    // and counts come from the file, so every step is checked before it can wrap.
    const std::size_t buffer_size = buffer.data.size();
    if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset)
        fail("its bufferView lies outside its buffer (" + std::to_string(buffer_size) + " bytes)");
    if (acc.byteOffset > view.byteLength)
        fail("byteOffset lies past the end of its bufferView");
    const std::size_t room = view.byteLength - acc.byteOffset; // bytes from the first element
    bool fits = count_ == 0 || (element <= room && (count_ - 1) <= (room - element) / stride_);
    if (!fits)
        fail("reads past the end of its bufferView (" + std::to_string(count_) + " elements of stride " +
             std::to_string(stride_) + " from offset " + std::to_string(acc.byteOffset) + " in " +
             std::to_string(view.byteLength) + " bytes)");
    data_ = buffer.data.data() + view.byteOffset + acc.byteOffset;
}

double AccessorReader::get(std::size_t i, int c) const
{
    const unsigned char* p = data_ + i * stride_ + static_cast<std::size_t>(c * component_size_);
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
