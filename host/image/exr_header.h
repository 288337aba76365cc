// A walk over an OpenEXR file's headers before OpenImageIO opens it. The OpenEXR 3.1 and
// OpenImageIO 2.4 of Debian 12 trust what a header declares: an attribute's byte count (a
// 4 KB file whose string attribute claims 2 GB makes OpenEXR allocate and fill 2 GB), a
// string vector's element sizes, a preview image's size, a multi-part file's chunk
// counts, and a channel's pixel type (OpenImageIO aborts the process on a type other than
// uint, half and float in a part after the first). OpenEXR also reads a value of a
// fixed-size type, or a channel list, by the value's own size and the next attribute from
// there, whatever byte count the file declares; so the walk requires the two to agree, and
// then reads the file where OpenEXR will. Each is checked against the bytes the file has.
#pragma once

#include <string>

namespace pathcl {

// Throws pathcl::Error naming `path` and what is wrong unless every header of the EXR at
// `path` is well formed in the ways above. Reads the headers only, never the pixels.
void check_exr_headers(const std::string& path);

} // namespace pathcl
