// The glTF schema checks the glTF library does not make, on the JSON text before it is
// parsed into typed structs. That library reads an index into an int (4294967296 becomes
// mesh 0), skips a member of the wrong JSON type as if it were absent (a texCoord of 1e300
// becomes set 0, a two-component baseColorFactor becomes white) and keeps arrays of any
// length, so a damaged file renders as a different scene instead of failing. Checked here:
// every index pathcl or the library follows (a JSON integer naming an existing element),
// the types of the members pathcl reads, the lengths of the fixed-size number arrays and
// their finiteness, and a rotation that is not the zero quaternion.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace pathcl {

// The JSON text parsed once, for every check made before the glTF library reads the file
// (the schema, the required extensions, the Draco indices); a discarded value when the
// text is not valid JSON, which the glTF library's parser then reports, naming the file.
// The nesting must already be bounded (check_json_nesting).
nlohmann::json parse_gltf_json(std::string_view json);

// Throws pathcl::Error "WHAT: PATH: ..." (PATH like nodes[3].mesh) at the first violation.
// A discarded document (not JSON) passes.
void check_gltf_schema(const nlohmann::json& doc, const std::string& what);

} // namespace pathcl
