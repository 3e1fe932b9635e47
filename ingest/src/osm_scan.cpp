#include "osm_scan.hpp"

#include "railodd/util/xml_text.hpp"

#include <cstring>
#include <system_error>

namespace railodd::ingest {

Tags tags_of(const osmium::TagList& list, bool& repaired) {
    Tags tags;
    for (const auto& tag : list) {
        std::string key = tag.key(), value = tag.value();
        repaired = make_xml_text(key) || repaired;
        repaired = make_xml_text(value) || repaired;
        tags.emplace(std::move(key), std::move(value));
    }
    return tags;
}

void check_tag_list(const std::filesystem::path& file, const osmium::OSMObject& object) {
    const osmium::TagList& tags = object.tags();
    const char* p = reinterpret_cast<const char*>(tags.data()) + sizeof(osmium::TagList);
    const char* end = reinterpret_cast<const char*>(tags.data()) + tags.byte_size();
    std::size_t strings = 0;
    while (p < end) {
        const void* zero = std::memchr(p, '\0', static_cast<std::size_t>(end - p));
        if (zero == nullptr) {
            break;
        }
        p = static_cast<const char*>(zero) + 1;
        ++strings;
    }
    if (p != end || strings % 2 != 0) {
        throw InputError(file.string(), std::string{"OSM "} + osmium::item_type_to_name(object.type()) + " " +
                                            std::to_string(object.id()) +
                                            ": malformed tag list (a key or value holds a NUL byte)");
    }
}

void rethrow_as_input_error(const std::filesystem::path& file, const std::string& pass) {
    try {
        throw;
    } catch (const osmium::pbf_error& e) {
        throw InputError(file.string(), "corrupt or truncated PBF data (" + pass + "): " + e.what());
    } catch (const osmium::xml_error& e) {
        throw InputError(file.string(), "malformed OSM XML (" + pass + "): " + e.what());
    } catch (const osmium::opl_error& e) {
        throw InputError(file.string(), "malformed OPL (" + pass + "): " + e.what());
    } catch (const osmium::gzip_error& e) {
        throw InputError(file.string(), "corrupt or truncated gzip data (" + pass + "): " + e.what());
    } catch (const osmium::bzip2_error& e) {
        throw InputError(file.string(), "corrupt or truncated bzip2 data (" + pass + "): " + e.what());
    } catch (const std::system_error& e) {
        throw InputError(file.string(), "cannot read (" + pass + "): " + e.what());
    } catch (const std::exception& e) {
        throw InputError(file.string(), "cannot read as OSM data (" + pass + "): " + e.what());
    }
}

} // namespace railodd::ingest
