#include "osm_scan.hpp"

#include <system_error>

namespace railodd::ingest {

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
