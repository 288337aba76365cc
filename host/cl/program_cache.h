// On-disk cache of compiled program binaries, keyed by a hash of everything that changes
// the binary: device, driver, build options and full source text. PoCL has its own cache,
// other drivers may not; this one works for all. Directory: $PATHCL_CACHE_DIR, else
// $XDG_CACHE_HOME/pathcl, else ~/.cache/pathcl. Any failure to read or write it only costs
// a recompile.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pathcl {

std::string program_cache_key(const std::string& device_identity, const std::string& options,
                              const std::string& source);

std::optional<std::vector<unsigned char>> program_cache_load(const std::string& key);

void program_cache_store(const std::string& key, const std::vector<unsigned char>& binary);

} // namespace pathcl
