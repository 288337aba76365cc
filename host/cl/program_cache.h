// On-disk cache of compiled program binaries, keyed by a hash of everything that changes
// the binary: device, driver, build options and full source text. PoCL has its own cache,
// other drivers may not; this one works for all. Directory: $PATHCL_CACHE_DIR, else
// $XDG_CACHE_HOME/pathcl, else ~/.cache/pathcl. Any failure to read or write it only costs
// a recompile.
//
// Each entry, <key>.bin, is a header then the driver's binary: magic "PATHCLKC", format
// version (u32), key length (u32) and bytes, binary length (u64), then a 64-bit FNV-1a of
// all of that and the binary (u64); integers little-endian. Drivers crash on malformed
// binaries and a valid one under the wrong key renders the wrong program, so an entry that
// fails any check (truncated, corrupted, renamed, older format) is a miss: it is rebuilt
// and rewritten, never handed to the driver.
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
