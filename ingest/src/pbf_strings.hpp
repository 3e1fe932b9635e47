#pragma once
// A check of an OSM PBF file's string tables before libosmium decodes it.
// libosmium copies each string of a block's table into its tag lists as a
// zero-terminated string; a NUL byte inside one splits it, the key/value pairs
// after it shift, and walking such a tag list reads past its end. OSM text
// never holds a NUL, so a string that does is refused here, naming the object
// that uses it.
#include <filesystem>

namespace railodd::ingest {

// Throws InputError(file, "OSM way 42: tag key ... holds a NUL byte ...") when
// an object's tag key, tag value or member role in a PBF data block holds a
// NUL byte. Blobs it cannot read (unknown compression, damaged framing) are
// left to libosmium, which reports them.
void check_pbf_strings(const std::filesystem::path& file);

} // namespace railodd::ingest
