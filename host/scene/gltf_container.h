// Checks of a glTF file as bytes, made before the glTF library parses it, for the two
// ways a hostile file defeats that library: a GLB whose chunk lengths run past the file
// (it reads beyond its buffer) and JSON nested so deep that its recursive conversion of
// the document overflows the stack.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pathcl {

// Deeper JSON is refused; real glTF files nest fewer than 20 levels.
constexpr std::size_t kMaxJsonDepth = 256;

// Whether bytes start with the GLB magic "glTF".
bool is_glb(const unsigned char* bytes, std::size_t size);

// Throws pathcl::Error "WHAT: ..." unless bytes are a well-formed GLB container: magic,
// version 2, a total length equal to the size, a first chunk of type JSON and every
// chunk's header and data inside the file. Also checks the JSON chunk's nesting. Returns
// the JSON chunk.
std::string_view check_glb(const unsigned char* bytes, std::size_t size, const std::string& what);

// Throws pathcl::Error "WHAT: ..." when the JSON text nests arrays and objects deeper than
// kMaxJsonDepth (counted outside strings; the text need not be valid JSON).
void check_json_nesting(const unsigned char* text, std::size_t size, const std::string& what);

} // namespace pathcl
