#pragma once
// One streaming pass over an OSM file for the given entity types. libosmium
// decodes PBF blocks on its thread pool and still delivers objects in file
// order, so every pass is deterministic whatever the thread count.
#include "railodd/ingest/types.hpp"
#include "railodd/util/errors.hpp"

#include <osmium/io/any_input.hpp>
#include <osmium/osm.hpp>

#include <filesystem>
#include <string>

namespace railodd::ingest {

// Turns libosmium's exceptions (pbf_error, xml_error, gzip_error, ...) into an
// InputError naming the file.
[[noreturn]] void rethrow_as_input_error(const std::filesystem::path& file, const std::string& pass);

// Refuses an object whose tag list is not whole zero-terminated key/value
// pairs within its bounds: libosmium walks tags with strlen, which runs past
// the list when a string held a NUL (check_pbf_strings names such a string
// up front; this guards every pass of every format).
void check_tag_list(const std::filesystem::path& file, const osmium::OSMObject& object);

// The tags as strings that XML and JSON outputs can carry: bytes that are not
// UTF-8 XML text become U+FFFD, and `repaired` says so (for the report).
Tags tags_of(const osmium::TagList& list, bool& repaired);

template <typename Visitor>
void scan_osm(const std::filesystem::path& file, osmium::osm_entity_bits::type types, const std::string& pass,
              Visitor&& visit) {
    try {
        osmium::io::Reader reader{osmium::io::File{file.string()}, types, osmium::io::read_meta::no};
        while (osmium::memory::Buffer buffer = reader.read()) {
            for (auto& object : buffer.select<osmium::OSMObject>()) {
                check_tag_list(file, object);
                visit(object);
            }
        }
        reader.close();
    } catch (const railodd::Error&) {
        throw;
    } catch (...) {
        rethrow_as_input_error(file, pass);
    }
}

} // namespace railodd::ingest
