#include "railodd/ingest/types.hpp"

namespace railodd::ingest {

std::string tag_or(const Tags& tags, const std::string& key, const std::string& fallback) {
    const auto it = tags.find(key);
    return it == tags.end() ? fallback : it->second;
}

} // namespace railodd::ingest
